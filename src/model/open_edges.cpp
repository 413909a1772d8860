#include "model/open_edges.hpp"

#include <algorithm>

namespace tunica {

std::vector<std::pair<int, int>> open_edges(const Model& m, int part, double* longest) {
  struct Use {
    int count = 0;
    std::pair<int, int> directed;  // a → b as its element runs it
  };
  std::map<std::pair<int, int>, Use> edges;  // by sorted node pair
  double l = 0;
  for (const ElementBlock& b : m.parts[part].blocks) {
    if (!is_surface_kind(b.kind)) return {};
    const int c = corner_nodes(b.kind);
    for (int e = 0; e < b.size(); ++e) {
      const int* en = b.element(e);
      for (int k = 0; k < c; ++k) {
        const int a = en[k], z = en[(k + 1) % c];
        auto& rec = edges[{std::min(a, z), std::max(a, z)}];
        if (rec.count++ == 0) rec.directed = {a, z};
        l = std::max(l, (m.X[a] - m.X[z]).norm());
      }
    }
  }
  if (longest) *longest = l;
  std::vector<std::pair<int, int>> open;
  for (const auto& [key, rec] : edges)
    if (rec.count == 1) open.push_back(rec.directed);
  return open;
}

int NodeChains::find(int a) {
  auto it = parent.find(a);
  if (it == parent.end()) return parent[a] = a;
  if (it->second == a) return a;
  return it->second = find(it->second);
}

}  // namespace tunica
