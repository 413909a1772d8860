#pragma once
// The open edges of a 3-D surface part (corner edges that one element alone uses: where the
// surface ends) and their connected chains: a tube's end rings, the edges on a symmetry plane, a
// hole. The enclosed-volume checks work on them (assembly/pressure_load_checks.hpp,
// model/volume_axis_check.hpp).
#include <map>
#include <utility>
#include <vector>

#include "model/model.hpp"

namespace tunica {

/// The open edges of part `part`, each as its element runs it (a → b), in the order of their
/// sorted node pairs; `longest` (if given) receives the part's longest corner edge. Empty for a
/// part that is not a 3-D surface.
std::vector<std::pair<int, int>> open_edges(const Model& m, int part, double* longest = nullptr);

/// Union-find over node numbers, for the connected chains of open edges.
struct NodeChains {
  std::map<int, int> parent;
  int find(int a);
  void join(int a, int b) { parent[find(a)] = find(b); }
};

}  // namespace tunica
