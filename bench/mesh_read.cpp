// Times Tunica's own .msh reader (read_gmsh: bounded read, parse, physical groups,
// node sets and the mesh checks of the file) on one file: bench/mesh-read.sh.
#include <chrono>
#include <cstdio>

#include "core/bounded_file.hpp"
#include "core/errors.hpp"
#include "mesh/gmsh_reader.hpp"
#include "mesh/msh_parser.hpp"
#include "mesh/msh_surface.hpp"

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: tunica-bench-mesh FILE.msh\n");
    return 2;
  }
  try {
    using clock = std::chrono::steady_clock;
    const auto seconds = [](clock::time_point a, clock::time_point b) { return std::chrono::duration<double>(b - a).count(); };
    const auto t0 = clock::now();
    const std::string bytes = tunica::read_file_bounded(argv[1], tunica::kMaxMshBytes, "mesh file");
    const auto t1 = clock::now();
    const tunica::MshFile f = tunica::parse_msh(bytes, argv[1]);
    const auto t2 = clock::now();
    const tunica::SurfaceMesh m = tunica::surface_mesh_from_msh(f, argv[1]);
    const auto t3 = clock::now();
    std::printf("read %.3f s, parse %.3f s, groups and checks %.3f s; ", seconds(t0, t1), seconds(t1, t2), seconds(t2, t3));
    std::size_t elements = 0;
    for (const auto& s : m.surfaces) elements += s.triangles.size() + s.quads.size();
    std::printf("%zu nodes, %zu elements, %.3f s\n", m.nodes.size(), elements,
                std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  } catch (const tunica::InputError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  }
  return 0;
}
