#pragma once
// Surface files that are not Gmsh meshes (STL, VTK, OBJ, PLY): what a user who names one
// as a mesh should do to get a named surface Tunica reads.
#include <string>

namespace tunica {

/// For a path whose extension is that of a surface format (.stl, .vtk, .vtp, .vtu, .obj, .ply,
/// .off), what it is and how to turn it into a .msh with a physical surface named `surface`;
/// "" for any other path.
std::string surface_format_advice(const std::string& path, const std::string& surface);

}  // namespace tunica
