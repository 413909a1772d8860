#pragma once
// Meshing a Gmsh geometry script (.geo) through the Gmsh SDK, contained: Gmsh runs
// in a child process, so that a crash, an abort or an exit inside the library, or a
// parser left in a bad state, cannot take the run down or affect a later read. The
// child writes a .msh file, which is then read by Tunica's own .msh reader like any
// other. A script can run commands (Gmsh's `System`): callers run one only when the
// user has allowed it (--allow-scripts).
#include <string>

namespace tunica {

struct GeoMeshFormat {
  double version = 4.1;  ///< 4.1 or 2.2
  bool binary = false;
};

/// Opens the script `path` in a child process, meshes its surfaces in 2-D if it
/// holds no 2-D mesh yet, and returns the bytes of the .msh file Gmsh writes (its
/// physical groups only). Throws InputError naming `path` (and the line of a syntax
/// error) when Gmsh reports an error, and when the child dies (its signal named).
std::string mesh_geo_script(const std::string& path, const GeoMeshFormat& format = {});

}  // namespace tunica
