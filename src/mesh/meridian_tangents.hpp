#pragma once
// Unit tangents of a meridian polyline at its nodes, in the direction of node
// order: the reference slopes X′ = ∂X/∂S of the axisymmetric shell
// (elements/axisym_shell.hpp). At a node with two neighbours, the tangent of
// the circle through the three points,
//     t ∝ |v|² u + |u|² v,   u = P_i − P_{i−1},  v = P_{i+1} − P_i;
// at an end node, that circle's tangent there (the tangent of the neighbouring
// interior node reflected about the end chord ê:  t = 2 (t_i·ê) ê − t_i).
// Exact for lines and circular arcs (the generators in mesh/meridian.hpp). A
// two-node meridian is a straight segment.
#include <vector>

#include "mesh/meridian.hpp"

namespace tunica {

/// Unit tangents at the nodes of `m` (at least 2 nodes, consecutive nodes distinct;
/// std::invalid_argument otherwise).
std::vector<Eigen::Vector2d> meridian_tangents(const Meridian& m);

}  // namespace tunica
