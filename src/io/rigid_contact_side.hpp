#pragma once
// A rigid contact surface given the wrong way round (`side: outside` where `inside` was meant, a
// polyline listed in the wrong direction) reads as valid: the slave then starts behind the surface,
// counts as penetrated from the first iteration, and the penalty pushes it through the surface in the
// first increment (theory manual §9, (9.1): g_N < 0 on the wrong side). The deck reader refuses such a
// pair at the reference state, as it refuses a slave behind a deformable master (deck_contact.cpp).
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

}  // namespace tunica
