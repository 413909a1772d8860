#include "mesh/gmsh_reader.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "core/bounded_file.hpp"
#include "core/errors.hpp"
#include "mesh/geo_mesher.hpp"
#include "mesh/msh_parser.hpp"
#include "mesh/msh_surface.hpp"

namespace tunica {

bool is_gmsh_script(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext == ".geo";
}

SurfaceMesh read_gmsh(const std::string& path, const std::string& direction_view, bool allow_scripts) {
  if (is_gmsh_script(path)) {
    if (!allow_scripts)
      throw InputError(SourceLocation{path, 0, 0, ""},
                       "this is a Gmsh script (.geo), which can run commands: Tunica meshes one only with "
                       "--allow-scripts (tunica run/check DECK --allow-scripts), or mesh it once with "
                       "tunica mesh FILE.geo -o FILE.msh and name the .msh");
    return read_script_mesh(path, mesh_geo_script(path), direction_view);
  }
  const std::string bytes = read_file_bounded(path, kMaxMshBytes, "mesh file");
  return surface_mesh_from_msh(parse_msh(bytes, path), path, direction_view);
}

SurfaceMesh read_script_mesh(const std::string& script, const std::string& msh, const std::string& direction_view) {
  try {
    return surface_mesh_from_msh(parse_msh(msh, script, false), script, direction_view);
  } catch (const InputError& e) {
    throw InputError(e.where(), e.reason() + " (in the mesh Gmsh made of the script)");
  }
}

}  // namespace tunica
