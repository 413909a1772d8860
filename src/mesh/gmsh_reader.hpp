#pragma once
// Gmsh files as surface meshes. A .msh file (4.1 or 2.2, ASCII or binary) is data:
// it is read by Tunica's own reader (msh_parser.hpp, msh_surface.hpp), within size
// limits, and nothing in it runs. A file that does not begin with $MeshFormat is
// not read as a mesh, whatever its name. A Gmsh script (.geo) is a program: it is
// meshed (in a child process, geo_mesher.hpp) only when `allow_scripts` is set,
// which the command line's --allow-scripts does.
//
// Physical surfaces become SurfaceMesh surfaces, physical curves and points node
// sets; only 3-node and 6-node triangles and 4-node quadrilaterals are accepted on
// physical surfaces. An element-data view with 3 components named `direction_view` gives
// per-element direction-1 vectors.
#include <string>

#include "mesh/surface_mesh.hpp"

namespace tunica {

/// True if `path` names a Gmsh script rather than a mesh (its extension is .geo).
bool is_gmsh_script(const std::string& path);

/// Reads `path`. Throws InputError (file = path; the line and the tags as written in the
/// file where they are known; key = the physical group or view concerned) on anything
/// the readers refuse, and on a script when `allow_scripts` is false.
SurfaceMesh read_gmsh(const std::string& path, const std::string& direction_view = "", bool allow_scripts = false);

/// The surface mesh of `msh`, the bytes of the .msh file Gmsh made of the script `script`.
/// Errors name the script and no lines (they would be those of a file the user never saw).
SurfaceMesh read_script_mesh(const std::string& script, const std::string& msh, const std::string& direction_view = "");

}  // namespace tunica
