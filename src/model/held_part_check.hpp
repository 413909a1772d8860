#pragma once
// A part whose every node the boundaries hold in every translational DOF: it cannot deform, so a
// load on it does nothing and its results are the reference state's (a boundary meant for the ends
// given `<part>.all`, or a node set that lists every node).
#include <string>
#include <vector>

#include "model/model.hpp"

namespace tunica {

struct HeldPart {
  int part = -1;
  int boundary = -1;     ///< the boundary holding the most of its nodes, where the warning points
  std::string message;   ///< names the part, the boundaries and what to hold instead
};

/// One per part (with at least two nodes) all of whose nodes are held in every translational DOF.
std::vector<HeldPart> held_part_warnings(const Model& m);

}  // namespace tunica
