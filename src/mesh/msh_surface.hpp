#pragma once
// From the contents of a .msh file to a SurfaceMesh: physical surfaces become
// surfaces (their physical names, or "surface_<tag>"), physical curves and
// points node sets ("curve_<tag>", "point_<tag>" when unnamed), an element-data
// view with 3 components the per-element direction-1 vectors. Only what the
// physical surfaces use is kept; nodes are numbered compactly in tag order.
#include <string>

#include "mesh/msh_file.hpp"
#include "mesh/surface_mesh.hpp"

namespace tunica {

/// Throws InputError naming `path`, and the line and the tags as written in the file, on:
/// a node tag defined twice, an element tag used twice (2.2 files may repeat an element
/// once per physical group, with the same nodes), an element naming a node the file does
/// not define, an element of a physical surface that is not a 3-node triangle or a 4-node
/// quadrangle (never dropped), a physical surface without elements, no physical surface,
/// two nodes of the physical surfaces at one position (a crack), an element sharing no
/// edge with any other (when the surfaces have more than one element), and a missing or
/// malformed direction view (`direction_view` non-empty).
SurfaceMesh surface_mesh_from_msh(const MshFile& file, const std::string& path, const std::string& direction_view = "");

}  // namespace tunica
