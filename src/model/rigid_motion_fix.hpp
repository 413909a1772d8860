#pragma once
// What to hold to stop a body's free rigid motions (model/rigid_motion_check.hpp), in the deck's
// terms: node sets of the body that lie in a coordinate plane, each held in the DOF normal to its
// plane, and where no set does, one node by its index in its part. A set is preferred when the
// holds then leave an inflation free (every node held in DOF j has one coordinate x_j: u = ε(x − q)
// meets u_j = 0 there with q_j that coordinate), and among those, a plane through the body's
// middle: the symmetry planes x0/y0 of a tube, the equator of a sphere. So the proposal depends
// on the part's mesh and on what the deck already holds, never on a generator's name.
#include <string>
#include <vector>

#include "model/model.hpp"

namespace tunica {

/// "x of `wall.x0` and y of `wall.y0` (the nodes on the planes x = 0 and y = 0, ...)": holds
/// that together with `held` leave the 3-D body `nodes` no free rigid motion (checked with
/// free_rigid_motions); "" if none is found.
std::string rigid_motion_fix(const Model& m, const std::vector<int>& nodes, const std::vector<unsigned>& held);

/// "of `tube.start`": a node set of the axisymmetric body `nodes` whose nodes share one z (the
/// first in deck order), else one node by its index in its part.
std::string axial_hold(const Model& m, const std::vector<int>& nodes);

}  // namespace tunica
