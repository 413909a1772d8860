#pragma once
// Gmsh files through the Gmsh SDK: a mesh (.msh, any version Gmsh reads) or a
// geometry (.geo, meshed in 2-D on reading with the options it sets).
// Physical surfaces become SurfaceMesh surfaces (their physical names, or
// "surface_<tag>" if unnamed); physical curves and points become node sets
// (their names, or "curve_<tag>" / "point_<tag>"). Only linear 3-node
// triangles and 4-node quadrilaterals are accepted on physical surfaces.
// Element data views with 3 components (from $ElementData in a .msh file)
// named `direction_view` give per-element direction-1 vectors.
#include <string>

#include "mesh/surface_mesh.hpp"

namespace tunica {

/// Reads `path`. Throws InputError (file = path; key = the physical group or
/// view concerned, when there is one) on an unreadable file, a file without
/// physical surfaces, unsupported elements on a physical surface, or a
/// requested direction view that is missing or not 3-component element data.
/// Nodes not used by any physical surface are dropped and the rest renumbered.
SurfaceMesh read_gmsh(const std::string& path, const std::string& direction_view = "");

}  // namespace tunica
