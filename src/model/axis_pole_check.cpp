#include "model/axis_pole_check.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "model/node_label.hpp"

namespace tunica {

std::vector<PoleMisfit> free_pole_warnings(const Model& m) {
  std::vector<PoleMisfit> out;
  if (m.dofs_per_node() == 3 || m.X.empty()) return out;
  double size = 0;
  for (const auto& x : m.X) size = std::max(size, x.head<2>().norm());
  std::vector<char> held(m.num_nodes(), 0);
  for (const Boundary& b : m.boundaries)
    if (std::find(b.dofs.begin(), b.dofs.end(), 0) != b.dofs.end())
      for (int n : m.node_sets[b.node_set].nodes) held[n] = 1;
  for (int p = 0; p < static_cast<int>(m.parts.size()); ++p) {
    const Part& part = m.parts[p];
    if (part.blocks.empty() || part.blocks.front().kind != ElementKind::axisym2) continue;
    for (int n : part.nodes) {
      if (held[n] || !(std::abs(m.X[n](0)) <= 1e-9 * size)) continue;
      // A node set that holds this node alone names where to hold it.
      std::string set;
      for (const NodeSet& s : m.node_sets)
        if (s.nodes.size() == 1 && s.nodes.front() == n) {
          set = s.name;
          break;
        }
      out.push_back({p, n,
                     fmt::format("{} lies on the axis (R = 0), a pole of part '{}', and no boundary condition holds "
                                 "its r: a membrane pole is free to leave the axis, which its neighbours barely "
                                 "resist, and it drifts off by round-off. Hold r there{}",
                                 node_label(m, n), part.name,
                                 set.empty() ? std::string(" (a node set of that node, `dofs: [r]`)")
                                             : fmt::format(": `{{node_set: {}, dofs: [r]}}` in `boundary`", set))});
    }
  }
  return out;
}

}  // namespace tunica
