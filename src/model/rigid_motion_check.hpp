#pragma once
// Rigid motions that no boundary condition holds. A body free to translate or rotate has a
// singular tangent: the run fails, or (round-off giving the solver a pivot) converges with the
// body carried off by an arbitrary rigid motion that every displacement output then shows.
#include <Eigen/Dense>
#include <string>
#include <vector>

#include "model/model.hpp"

namespace tunica {

/// A rigid motion of a 3-D body: a translation along axis k, or a rotation about a line parallel
/// to axis k, through `through` if `located` (the line the held nodes lie on), else about every
/// such line (no node holds a DOF across it).
struct RigidMotion {
  bool rotation = false;
  int k = 0;
  bool located = false;
  Eigen::Vector3d through = Eigen::Vector3d::Zero();
};

/// The rigid motions of the 3-D body made of `nodes` that the held DOFs leave free for a finite
/// amount (bit d of held[n]: position DOF d of node n is held): a translation along x, y or z that
/// no held DOF stops, a rotation about an axis parallel to x, y or z that no held DOF stops (every
/// node holding a DOF across that axis lies on it). Motions held only to first order (a quarter
/// tube's symmetry planes) are held by the stress they meet and are not named.
std::vector<RigidMotion> free_rigid_motions(const Model& m, const std::vector<int>& nodes,
                                            const std::vector<unsigned>& held);

/// A body (parts joined by shared nodes) free to move rigidly: its parts and the message.
struct UnheldBody {
  std::vector<int> parts;
  std::string message;
};

/// One message per body that the boundary conditions leave free to move rigidly: 3-D, the
/// free_rigid_motions; axisymmetric, the translation along z. Each names what to hold
/// (model/rigid_motion_fix.hpp). Bodies in a contact pair are left out (the contact may hold
/// them) unless `contact_holds` is false (what would hold them if they lost contact). Empty when
/// every body is held.
std::vector<UnheldBody> unheld_rigid_motions(const Model& m, bool contact_holds = true);

}  // namespace tunica
