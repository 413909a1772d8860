#pragma once
// Nodes of two parts at the same position that are not one node: the parts touch there but are not
// joined, so each edge is free (a capsule balloon of three axisymmetric parts, an end cap meshed
// apart from its tube). Parts are joined by sharing nodes (one meridian, or one mesh file whose
// surfaces share their boundary nodes); a separate part is a separate membrane.
#include <string>
#include <vector>

#include "model/model.hpp"

namespace tunica {

struct CoincidentNodes {
  int part_a = -1, part_b = -1;  ///< the two parts (part_a < part_b)
  std::string message;           ///< names both parts, a pair of nodes, their position and the count
};

/// One per pair of parts with nodes within 10⁻⁹ of the model's size of each other that are distinct
/// nodes (a node shared by both parts is a joint, not a finding).
std::vector<CoincidentNodes> coincident_node_warnings(const Model& m);

}  // namespace tunica
