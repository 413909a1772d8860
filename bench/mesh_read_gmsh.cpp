// Times reading a .msh file through the Gmsh SDK (gmsh::open, then the nodes and the
// 2-D elements), the SDK's own reading path: the reference against which bench/mesh-read.sh
// times Tunica's reader. Built and run by that script only.
#include <gmsh.h>

#include <chrono>
#include <cstdio>

int main(int argc, char** argv) {
  if (argc < 2) return 2;
  const auto t0 = std::chrono::steady_clock::now();
  gmsh::initialize(0, nullptr, false);
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::open(argv[1]);
  std::vector<std::size_t> tags;
  std::vector<double> coord, param;
  gmsh::model::mesh::getNodes(tags, coord, param, -1, -1, false, false);
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> etags, enodes;
  gmsh::model::mesh::getElements(types, etags, enodes, 2, -1);
  gmsh::finalize();
  std::size_t elements = 0;
  for (const auto& e : etags) elements += e.size();
  std::printf("%zu nodes, %zu elements, %.3f s\n", tags.size(), elements,
              std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  return 0;
}
