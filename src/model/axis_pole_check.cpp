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
      // A flat part from the axis (every node at one z): a disk, or a tube's points written [z, r].
      double zlo = m.X[part.nodes.front()](1), zhi = zlo, rhi = 0;
      for (int k : part.nodes) zlo = std::min(zlo, m.X[k](1)), zhi = std::max(zhi, m.X[k](1)), rhi = std::max(rhi, m.X[k](0));
      std::string flat;
      if (zhi - zlo <= 1e-9 * size) {
        const std::string len = m.units.display_unit(Dimension::length);
        const auto in_len = [&](double x) { return m.units.from_internal(x, len, Dimension::length); };
        flat = fmt::format(
            ". The part is a flat disk in the plane z = {:.4g} {} (points are [r, z], the radius first): if a tube "
            "along the axis was meant, write each point the other way round ([{:.4g} {}, 0 {}] to [{:.4g} {}, {:.4g} {}])",
            in_len(zlo), len, in_len(zlo), len, len, in_len(zlo), len, in_len(rhi), len);
      }
      out.push_back({p, n,
                     fmt::format("{} lies on the axis (R = 0), a pole of part '{}', and no boundary condition holds "
                                 "its r: a membrane pole is free to leave the axis, which its neighbours barely "
                                 "resist, and it drifts off by round-off. Hold r there{}",
                                 node_label(m, n), part.name,
                                 set.empty() ? std::string(" (a node set of that node, `dofs: [r]`)")
                                             : fmt::format(": `{{node_set: {}, dofs: [r]}}` in `boundary`", set)) +
                         flat});
    }
  }
  return out;
}

}  // namespace tunica
