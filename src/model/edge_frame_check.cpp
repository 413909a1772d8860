#include "model/edge_frame_check.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>
#include <vector>

namespace tunica {

namespace {

/// The corner nodes of an element of a 3-D surface block (the first three or four).
int corners(ElementKind k) { return k == ElementKind::quad4 ? 4 : 3; }

}  // namespace

double edge_frame_turned_fraction(const Model& m, int p) {
  const Part& part = m.parts[static_cast<std::size_t>(p)];
  if (m.dofs_per_node() != 3 || part.frame.type != FrameRule::Type::edge) return 0;
  std::vector<Eigen::Vector3d> d, n;
  std::map<std::pair<int, int>, std::vector<int>> by_edge;
  for (const ElementBlock& block : part.blocks) {
    if (block.kind != ElementKind::tri3 && block.kind != ElementKind::quad4 && block.kind != ElementKind::tri6) continue;
    const int c = corners(block.kind);
    for (int e = 0; e < block.size(); ++e) {
      const int* en = block.element(e);
      const Eigen::Vector3d& x0 = m.X[en[0]];
      const Eigen::Vector3d normal = c == 4 ? Eigen::Vector3d((m.X[en[2]] - x0).cross(m.X[en[3]] - m.X[en[1]]))
                                            : Eigen::Vector3d((m.X[en[1]] - x0).cross(m.X[en[2]] - x0));
      const int id = static_cast<int>(d.size());
      d.push_back((m.X[en[1]] - x0).normalized());
      n.push_back(normal.normalized());
      for (int a = 0; a < c; ++a) {
        const int i = en[a], j = en[(a + 1) % c];
        by_edge[{std::min(i, j), std::max(i, j)}].push_back(id);
      }
    }
  }
  const double cos_turn = std::cos(kEdgeFrameTurnDeg * std::numbers::pi / 180);
  long pairs = 0, turned = 0;
  for (const auto& [edge, elements] : by_edge) {
    if (elements.size() != 2) continue;
    const int a = elements[0], b = elements[1];
    // b's direction taken into a's tangent plane.
    const Eigen::Vector3d t = d[b] - d[b].dot(n[a]) * n[a];
    if (!(t.norm() > 0) || !d[a].allFinite()) continue;
    ++pairs;
    if (std::abs(t.normalized().dot(d[a])) < cos_turn) ++turned;
  }
  return pairs > 0 ? static_cast<double>(turned) / static_cast<double>(pairs) : 0.0;
}

}  // namespace tunica
