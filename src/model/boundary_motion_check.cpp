#include "model/boundary_motion_check.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "model/node_label.hpp"

namespace tunica {

namespace {

const char* dof_name(const Model& m, int d) {
  static const char* axisym[] = {"r", "z"};
  static const char* solid[] = {"x", "y", "z"};
  return m.dofs_per_node() == 3 ? solid[d] : axisym[d];
}

}  // namespace

std::vector<MotionMisfit> boundary_motion_warnings(const Model& m) {
  std::vector<MotionMisfit> out;
  if (m.X.empty()) return out;
  const int dim = m.dofs_per_node();
  const bool axisymmetric = dim != 3;
  Eigen::Vector3d lo = m.X.front(), hi = lo;
  for (const Eigen::Vector3d& x : m.X) lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
  const double size = (hi - lo).norm();
  if (!(size > 0)) return out;
  const double tol = 1e-9 * size;
  const std::string len = m.units.display_unit(Dimension::length);
  const auto in_len = [&](double x) { return m.units.from_internal(x, len, Dimension::length); };
  // Per DOF, the nodes some boundary holds in it, and by which boundary (the first).
  std::vector<std::vector<int>> held_by(dim, std::vector<int>(m.num_nodes(), -1));
  for (int b = 0; b < static_cast<int>(m.boundaries.size()); ++b)
    for (int d : m.boundaries[b].dofs)
      if (d < dim)
        for (int n : m.node_sets[m.boundaries[b].node_set].nodes)
          if (held_by[d][n] < 0) held_by[d][n] = b;
  for (int s = 0; s < static_cast<int>(m.steps.size()); ++s) {
    const Step& step = m.steps[s];
    if (step.inverse) continue;  // an inverse step's values place the reference, not the loaded state
    for (int b = 0; b < static_cast<int>(m.boundaries.size()); ++b) {
      const Boundary& bc = m.boundaries[b];
      const auto target = step.targets.find(bc.name);
      if (target == step.targets.end() || !std::isfinite(target->second) || target->second == 0) continue;
      const double u = target->second;
      const NodeSet& set = m.node_sets[bc.node_set];
      if (set.nodes.empty()) continue;
      std::vector<char> in_set(m.num_nodes(), 0);
      for (int n : set.nodes) in_set[n] = 1;
      for (int d : bc.dofs) {
        if (d >= dim) continue;
        double slo = std::numeric_limits<double>::infinity(), shi = -slo;
        int nlo = set.nodes.front();
        for (int n : set.nodes) {
          if (m.X[n](d) < slo) slo = m.X[n](d), nlo = n;
          shi = std::max(shi, m.X[n](d));
        }
        const std::string value = fmt::format("{:.4g} {}", in_len(u), len);
        if (axisymmetric && d == 0) {
          if (slo + u < -tol)
            out.push_back({s, b,
                           fmt::format("boundary '{}' moves r of node set '{}' by {} in step '{}', which puts {} (at "
                                       "r = {:.4g} {}) at r = {:.4g} {}, across the axis: a boundary value is the "
                                       "displacement from the reference (user guide §3.1), not the position. Check "
                                       "the value, its sign and its unit",
                                       bc.name, set.name, value, step.name, node_label(m, nlo), in_len(slo), len,
                                       in_len(slo + u), len)});
          continue;
        }
        // Toward the other side, past all of the model's extent in d.
        const double mid = 0.5 * (lo(d) + hi(d));
        const bool from_high = u < 0 && 0.5 * (slo + shi) > mid && shi + u < lo(d) - tol;
        const bool from_low = u > 0 && 0.5 * (slo + shi) < mid && slo + u > hi(d) + tol;
        if (!from_high && !from_low) continue;
        int other = -1;  // a boundary that holds d on a node outside the set
        for (int n = 0; n < m.num_nodes() && other < 0; ++n)
          if (!in_set[n] && held_by[d][n] >= 0) other = held_by[d][n];
        if (other < 0) continue;  // nothing holds the rest: the model translates
        const char* dn = dof_name(m, d);
        // "z = 10 mm" for a set on one plane, "z = 9.5 to 10 mm" for a set that spans a range.
        const auto span = [&](double a, double b) {
          return std::abs(b - a) <= tol ? fmt::format("{} = {:.4g} {}", dn, in_len(a), len)
                                        : fmt::format("{} = {:.4g} to {:.4g} {}", dn, in_len(a), in_len(b), len);
        };
        out.push_back(
            {s, b,
             fmt::format("boundary '{}' moves {} of node set '{}' (at {}) by {} in step '{}', to {}: past the whole "
                         "model, whose nodes span {}, while boundary '{}' holds {} on the other side, so the wall "
                         "between them would have to pass through itself (Newton then converges to crushed states or "
                         "stops at an everted surface). A boundary value is the displacement from the reference (user "
                         "guide §3.1), not the position: check the value, its sign and its unit",
                         bc.name, dn, set.name, span(slo, shi), value, step.name, span(slo + u, shi + u),
                         span(lo(d), hi(d)), m.boundaries[other].name, dn)});
      }
    }
  }
  return out;
}

std::string boundary_motion_hint(const Model& m, int step) {
  std::string out;
  for (const MotionMisfit& w : boundary_motion_warnings(m))
    if (w.step == step) out += (out.empty() ? "" : " ") + w.message + ".";
  return out;
}

}  // namespace tunica
