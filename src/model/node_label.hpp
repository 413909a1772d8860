#pragma once
// How messages name a node so that it can be found where it was defined: by its tag in the mesh
// file it was read from, or by its index in its part (as `node_sets` lists count them).
#include <string>

#include "model/model.hpp"

namespace tunica {

/// "node 13 of wall.msh" (a node read from a Gmsh file, by its tag there) or "node 3 of part
/// 'tube'" (a generated node, by its 0-based index in the part's nodes: along the meridian from
/// its start, row by row in a solid grid, in increasing order in a 3-D part).
std::string node_label(const Model& m, int node);

}  // namespace tunica
