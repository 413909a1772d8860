#pragma once
// A boundary value that moves its nodes past the far side of the model (an end pulled through the
// other end: the wall would turn inside out) or, in an axisymmetric model, across the axis. A
// boundary value is a displacement from the reference (user guide §3.1); such a value is most
// often a position written as a displacement, or a sign or unit mistyped. Newton then converges
// to crushed states (stretches near zero, stresses of hundreds of MPa) or stops at an everted
// surface, neither of which says why.
#include <string>
#include <vector>

#include "model/model.hpp"

namespace tunica {

struct MotionMisfit {
  int step = -1;      ///< 0-based
  int boundary = -1;
  std::string message;  ///< names the boundary, its node set, the value, where the nodes end and what they pass
};

/// One per step target of a forward step that moves the translational DOF d of a boundary's node
/// set so that
///  - (axisymmetric, d = r) a node of the set ends at r < 0: across the axis;
///  - or every node of the set ends beyond the model's opposite extreme in d (the set lies on the
///    far side of the middle of the model's extent in d and moves toward the other side, past
///    all of it), while another boundary holds d on nodes outside the set: the part between
///    them would have to pass through itself.
///  - or (not r of an axisymmetric model) the set moves away from the other side by more than the
///    model's whole extent in d while another boundary holds d on nodes outside the set: the wall
///    between is stretched at least 1 + |u|/extent-fold (a position written as a displacement).
/// And one per step value of a boundary that names two or more translational DOFs: the value
/// moves the set by it along each (`dofs: [r, z]` with `1 mm` moves 1 mm out and 1 mm up), which
/// is easily read as a motion along one.
std::vector<MotionMisfit> boundary_motion_warnings(const Model& m);

/// The misfits of step `step` (0-based) alone, as one sentence each, for a failure's hint.
std::string boundary_motion_hint(const Model& m, int step);

/// The values of step `step` (0-based) that move a node set toward the other side of the model
/// where another boundary holds the same DOF (axial DOFs; not r): they shorten the wall between.
/// "" if none, else each as "boundary 'e2' moves z by -2 mm toward boundary 'e1', 10 % of the
/// model's extent in z", joined by "; ".
std::string shortening_motions(const Model& m, int step);

}  // namespace tunica
