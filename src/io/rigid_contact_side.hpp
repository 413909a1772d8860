#pragma once
// A rigid contact surface given the wrong way round (`side: outside` where `inside` was meant, a
// polyline listed in the wrong direction) reads as valid: the slave then starts behind the surface,
// counts as penetrated from the first iteration, and the penalty pushes it through the surface in the
// first increment (theory manual §9, (9.1): g_N < 0 on the wrong side). The deck reader refuses such a
// pair at the reference state, as it refuses a slave behind a deformable master (deck_contact.cpp).
#include <functional>
#include <vector>

#include "io/read_params.hpp"
#include "model/model.hpp"

namespace tunica {

/// A slave node behind its rigid surface by more than this fraction of its element length at the
/// reference state is deep: no model starts there on purpose.
constexpr double kDeepBehind = 0.1;
/// A slave node behind by more than this fraction of its element length (round-off of a slave meshed
/// onto the surface stays far below) counts as behind; most slave nodes behind is the wrong side.
constexpr double kBehind = 1e-6;

/// Refuses the rigid pair `c` (its slave read) at its `rigid` key when at the reference state some
/// slave node lies behind the surface deeper than kDeepBehind of its element length, or more than
/// half of the slave nodes that face it lie behind it (signed distance < −kBehind × element length):
/// the message names the pair, how many nodes and how deep (in the deck's length unit), and the fix
/// (`side`, or the polyline's point order).
void check_rigid_side(const Params& p, const ContactPair& c, const Model& m);

/// Refuses the pair `c` at its `offset` key when the offset c is larger than the starting gap s of
/// a slave node on the surface's contact side by more than kDeepBehind of its element length: the
/// node would count as penetrated by c − s from the first iteration (g_N = s − c, (9.1)) and the
/// penalty would push the membrane away by that in the first increment. `distance(x, s)` gives the
/// signed distance of a reference point (false where the surface has no side there); slave node k
/// is node `index[k]` of the meridian `chain` (for its element length).
void check_contact_offset(const Params& p, const ContactPair& c, const Model& m,
                          const std::function<bool(const Eigen::Vector2d&, double&)>& distance,
                          const std::vector<int>& chain, const std::vector<int>& index);
/// The signed distance of reference point x to rigid surface r, positive on the slave's side (false
/// where a polyline has no side, beyond its ends).
bool rigid_signed_distance(const RigidSurface& r, const Eigen::Vector2d& x, double& s);

}  // namespace tunica
