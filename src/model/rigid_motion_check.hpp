#pragma once
// Rigid motions that no boundary condition holds. A body free to translate or rotate has a
// singular tangent: the run fails, or (round-off giving the solver a pivot) converges with the
// body carried off by an arbitrary rigid motion that every displacement output then shows.
#include <string>
#include <vector>

#include "model/model.hpp"

namespace tunica {

/// One message per body (parts joined by shared nodes) that the boundary conditions leave free to
/// move rigidly by a finite amount: 3-D, a translation along x, y or z that no held DOF stops, a
/// rotation about an axis parallel to x, y or z that no held DOF stops (every node holding a DOF
/// across that axis lies on it); axisymmetric, the translation along z. Motions held only to first
/// order (a quarter tube's symmetry planes) are held by the stress they meet and are not named.
/// Bodies in a contact pair are left out (the contact may hold them). Empty when every body is held.
std::vector<std::string> unheld_rigid_motions(const Model& m);

}  // namespace tunica
