#include "model/coincident_nodes_check.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <unordered_map>

#include "model/node_label.hpp"

namespace tunica {

std::vector<CoincidentNodes> coincident_node_warnings(const Model& m) {
  std::vector<CoincidentNodes> out;
  // The part of each node (the first that uses it; a node of two parts is shared, a joint).
  std::vector<int> part_of(m.num_nodes(), -1);
  for (int p = 0; p < static_cast<int>(m.parts.size()); ++p)
    for (int n : m.parts[p].nodes)
      if (part_of[n] < 0) part_of[n] = p;
  std::vector<int> nodes;
  for (int n = 0; n < m.num_nodes(); ++n)
    if (part_of[n] >= 0) nodes.push_back(n);
  if (nodes.size() < 2) return out;
  double size = 0;
  for (int n : nodes) size = std::max(size, m.X[n].cwiseAbs().maxCoeff());
  const double tol = 1e-9 * std::max(size, 1e-300);
  // Nodes in cells of size tol: a pair within tol lies in one cell or two neighbouring ones, so
  // each node is compared with the nodes of the 27 cells around it (O(n), whatever the layout).
  using Cell = std::array<long long, 3>;
  struct CellHash {
    std::size_t operator()(const Cell& c) const {
      return std::hash<long long>()(c[0] * 73856093LL ^ c[1] * 19349663LL ^ c[2] * 83492791LL);
    }
  };
  const auto cell_of = [&](int n) {
    Cell c;
    for (int k = 0; k < 3; ++k) c[k] = static_cast<long long>(std::floor(m.X[n](k) / tol));
    return c;
  };
  std::unordered_map<Cell, std::vector<int>, CellHash> cells;
  if (m.parts.size() > 1)
    for (int n : nodes) cells[cell_of(n)].push_back(n);
  // Per pair of parts: the first pair of nodes found and how many.
  std::map<std::pair<int, int>, std::pair<std::pair<int, int>, int>> found;
  for (int a : m.parts.size() > 1 ? nodes : std::vector<int>{}) {
    const Cell c = cell_of(a);
    for (long long i = -1; i <= 1; ++i)
      for (long long j = -1; j <= 1; ++j)
        for (long long k = -1; k <= 1; ++k) {
          const auto it = cells.find(Cell{c[0] + i, c[1] + j, c[2] + k});
          if (it == cells.end()) continue;
          for (int b : it->second) {
            if (b <= a || part_of[a] == part_of[b] || (m.X[a] - m.X[b]).norm() > tol) continue;
            const auto key = std::minmax(part_of[a], part_of[b]);
            auto [at, fresh] = found.try_emplace({key.first, key.second}, std::make_pair(std::make_pair(a, b), 0));
            ++at->second.second;
            at->second.first = std::min(at->second.first, std::make_pair(a, b));  // the lowest pair, however found
          }
        }
  }
  const bool axisymmetric = m.dofs_per_node() != 3;
  for (const auto& [parts, first] : found) {
    const auto [a, b] = first.first;
    const Eigen::Vector3d& x = m.X[a];
    const std::string where = axisymmetric ? fmt::format("r = {:.6g}, z = {:.6g}", x(0), x(1))
                                           : fmt::format("({:.6g}, {:.6g}, {:.6g})", x(0), x(1), x(2));
    out.push_back({parts.first, parts.second,
                   fmt::format("parts '{}' and '{}' have {} pair(s) of nodes at the same position that are not joined "
                               "(the first: {} and {}, at {}): each part's edge there is free, as if the parts were "
                               "cut apart. Parts are joined only by sharing nodes: one part whose mesh runs through "
                               "({}), or, if they are meant to be apart (contact), starting them apart",
                               m.parts[parts.first].name, m.parts[parts.second].name, first.second,
                               node_label(m, a), node_label(m, b), where,
                               axisymmetric ? "an axisymmetric part whose `mesh` is a list of `line` and `arc` pieces "
                                              "joined end to start"
                                            : "a 3-D surface from one Gmsh file whose surfaces share their boundary "
                                              "curve")});
  }
  return out;
}

}  // namespace tunica
