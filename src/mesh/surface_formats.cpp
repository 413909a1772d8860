#include "mesh/surface_formats.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "core/printable.hpp"

namespace tunica {

std::string surface_format_advice(const std::string& path, const std::string& surface) {
  const std::filesystem::path p(path);
  std::string ext = p.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  const std::string file = printable(p.filename().string()), name = printable(surface);
  const auto gmsh = [&](const std::string& what) {
    return fmt::format("open {} in Gmsh, add a physical surface named '{}' (Geometry > Physical groups > Add > Surface, "
                       "or a .geo with Merge \"{}\"; Physical Surface(\"{}\") = {{1}}; meshed by tunica mesh FILE.geo "
                       "-o FILE.msh) and save it as a .msh of version 4.1 (File > Export, Gmsh MSH), then name the .msh "
                       "in `file`",
                       what, name, ext == ".stl" || ext == ".vtk" ? file : "FILE.stl", name);
  };
  if (ext == ".stl" || ext == ".vtk")
    return fmt::format("{} is {} surface, not a Gmsh mesh: Tunica reads .msh files (and .geo scripts). To turn it into a "
                       "named surface, {}",
                       file, ext == ".stl" ? "an STL" : "a VTK", gmsh(file));
  if (ext == ".vtp" || ext == ".vtu" || ext == ".obj" || ext == ".ply" || ext == ".off")
    return fmt::format("{} is {} surface, not a Gmsh mesh: Tunica reads .msh files (and .geo scripts). To turn it "
                       "into a named surface, save it as STL first (ParaView: File > Save Data, STL), then {}",
                       file, ext == ".vtp" || ext == ".vtu" ? "a VTK XML" : ext == ".obj" ? "a Wavefront OBJ"
                                                                     : ext == ".ply" ? "a PLY" : "an OFF",
                       gmsh("the STL"));
  return "";
}

}  // namespace tunica
