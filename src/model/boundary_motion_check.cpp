#include "model/boundary_motion_check.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include "model/node_label.hpp"

namespace tunica {

namespace {

const char* dof_name(const Model& m, int d) {
  static const char* axisym[] = {"r", "z"};
  static const char* solid[] = {"x", "y", "z"};
  return m.dofs_per_node() == 3 ? solid[d] : axisym[d];
}

/// One step value of a boundary's translational DOF, with where its node set lies and goes.
struct Motion {
  int step = -1, boundary = -1, dof = -1;
  double u = 0;             ///< the value (internal length)
  double slo = 0, shi = 0;  ///< the node set's extent in the DOF at the reference
  int nlo = -1;             ///< the set's node of least coordinate
  double lo = 0, hi = 0;    ///< the model's extent in the DOF
  int other = -1;           ///< a boundary holding the DOF on a node outside the set, or −1
  /// The set lies on one side of the middle of the model's extent and moves toward the other.
  bool toward = false;
};

/// Calls `f(step, boundary, value)` for each finite nonzero value a forward step gives a boundary
/// (an inverse step's values place the reference, not the loaded state).
void for_each_value(const Model& m, const std::function<void(int, int, double)>& f) {
  for (int s = 0; s < static_cast<int>(m.steps.size()); ++s) {
    const Step& step = m.steps[s];
    if (step.inverse) continue;
    for (int b = 0; b < static_cast<int>(m.boundaries.size()); ++b) {
      const auto target = step.targets.find(m.boundaries[b].name);
      if (target != step.targets.end() && std::isfinite(target->second) && target->second != 0) f(s, b, target->second);
    }
  }
}

/// Calls `f` for each nonzero value of a translational DOF of a boundary in a forward step.
void for_each_motion(const Model& m, const std::function<void(const Motion&)>& f) {
  if (m.X.empty()) return;
  const int dim = m.dofs_per_node();
  Eigen::Vector3d lo = m.X.front(), hi = lo;
  for (const Eigen::Vector3d& x : m.X) lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
  if (!((hi - lo).norm() > 0)) return;
  // Per DOF, the nodes some boundary holds in it, and by which boundary (the first).
  std::vector<std::vector<int>> held_by(dim, std::vector<int>(m.num_nodes(), -1));
  for (int b = 0; b < static_cast<int>(m.boundaries.size()); ++b)
    for (int d : m.boundaries[b].dofs)
      if (d < dim)
        for (int n : m.node_sets[m.boundaries[b].node_set].nodes)
          if (held_by[d][n] < 0) held_by[d][n] = b;
  for_each_value(m, [&](int s, int b, double u) {
    const Boundary& bc = m.boundaries[b];
    const NodeSet& set = m.node_sets[bc.node_set];
    if (set.nodes.empty()) return;
    std::vector<char> in_set(m.num_nodes(), 0);
    for (int n : set.nodes) in_set[n] = 1;
    for (int d : bc.dofs) {
      if (d >= dim) continue;
      Motion mo{s, b, d, u};
      mo.slo = std::numeric_limits<double>::infinity(), mo.shi = -mo.slo;
      for (int n : set.nodes) {
        if (m.X[n](d) < mo.slo) mo.slo = m.X[n](d), mo.nlo = n;
        mo.shi = std::max(mo.shi, m.X[n](d));
      }
      mo.lo = lo(d), mo.hi = hi(d);
      for (int n = 0; n < m.num_nodes() && mo.other < 0; ++n)
        if (!in_set[n] && held_by[d][n] >= 0) mo.other = held_by[d][n];
      const double mid = 0.5 * (mo.lo + mo.hi), centre = 0.5 * (mo.slo + mo.shi);
      mo.toward = (mo.u < 0 && centre > mid) || (mo.u > 0 && centre < mid);
      f(mo);
    }
  });
}

}  // namespace

std::vector<MotionMisfit> boundary_motion_warnings(const Model& m) {
  std::vector<MotionMisfit> out;
  if (m.X.empty()) return out;
  Eigen::Vector3d lo = m.X.front(), hi = lo;
  for (const Eigen::Vector3d& x : m.X) lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
  const double tol = 1e-9 * (hi - lo).norm();
  const bool axisymmetric = m.dofs_per_node() != 3;
  const std::string len = m.units.display_unit(Dimension::length);
  const auto in_len = [&](double x) { return m.units.from_internal(x, len, Dimension::length); };
  for_each_motion(m, [&](const Motion& mo) {
    const Boundary& bc = m.boundaries[mo.boundary];
    const std::string& set = m.node_sets[bc.node_set].name;
    const std::string& step = m.steps[mo.step].name;
    const std::string value = fmt::format("{:.4g} {}", in_len(mo.u), len);
    if (axisymmetric && mo.dof == 0) {
      if (mo.slo + mo.u < -tol)
        out.push_back({mo.step, mo.boundary,
                       fmt::format("boundary '{}' moves r of node set '{}' by {} in step '{}', which puts {} (at r = "
                                   "{:.4g} {}) at r = {:.4g} {}, across the axis: a boundary value is the displacement "
                                   "from the reference (user guide §3.1), not the position. Check the value, its sign "
                                   "and its unit",
                                   bc.name, set, value, step, node_label(m, mo.nlo), in_len(mo.slo), len,
                                   in_len(mo.slo + mo.u), len)});
      return;
    }
    // Away from another boundary that holds the DOF, by more than the model's whole extent in it:
    // the wall between at least doubles its length, far beyond an artery's axial stretch (1.1 to 1.6).
    if (!mo.toward && mo.other >= 0 && mo.hi > mo.lo && std::abs(mo.u) > mo.hi - mo.lo &&
        !(axisymmetric && mo.dof == 0)) {
      const char* dn = dof_name(m, mo.dof);
      // A set on one plane away from the origin: the displacement that would put it where the value says.
      const bool plane = mo.shi - mo.slo <= tol && std::abs(mo.slo) > tol;
      out.push_back(
          {mo.step, mo.boundary,
           fmt::format("boundary '{}' moves {} of node set '{}' by {} in step '{}', away from boundary '{}', which "
                       "holds {} on the other side: more than the model's whole extent in {} ({:.4g} {}), so the wall "
                       "between is stretched at least {:.3g}-fold along {}, where arteries reach 1.1 to 1.6 axially. A "
                       "boundary value is the displacement from the reference (user guide §3.1), not the position{}",
                       bc.name, dn, set, value, step, m.boundaries[mo.other].name, dn, dn, in_len(mo.hi - mo.lo), len,
                       1 + std::abs(mo.u) / (mo.hi - mo.lo), dn,
                       plane ? fmt::format(": if the set (at {} = {:.4g} {}) is to end at {} = {}, the value is {:.4g} {}",
                                           dn, in_len(mo.slo), len, dn, value, in_len(mo.u - mo.slo), len)
                             : std::string(": check the value and its unit"))});
      return;
    }
    // Toward the other side, past all of the model's extent in the DOF, against another boundary.
    const bool past = mo.u < 0 ? mo.shi + mo.u < mo.lo - tol : mo.slo + mo.u > mo.hi + tol;
    if (!mo.toward || !past || mo.other < 0) return;
    const char* dn = dof_name(m, mo.dof);
    // "z = 10 mm" for a set on one plane, "z = 9.5 to 10 mm" for a set that spans a range.
    const auto span = [&](double a, double b) {
      return std::abs(b - a) <= tol ? fmt::format("{} = {:.4g} {}", dn, in_len(a), len)
                                    : fmt::format("{} = {:.4g} to {:.4g} {}", dn, in_len(a), in_len(b), len);
    };
    out.push_back(
        {mo.step, mo.boundary,
         fmt::format("boundary '{}' moves {} of node set '{}' (at {}) by {} in step '{}', to {}: past the whole model, "
                     "whose nodes span {}, while boundary '{}' holds {} on the other side, so the wall between them "
                     "would have to pass through itself (Newton then converges to crushed states or stops at an "
                     "everted surface). A boundary value is the displacement from the reference (user guide §3.1), "
                     "not the position: check the value, its sign and its unit",
                     bc.name, dn, set, span(mo.slo, mo.shi), value, step, span(mo.slo + mo.u, mo.shi + mo.u),
                     span(mo.lo, mo.hi), m.boundaries[mo.other].name, dn)});
  });
  // One value for several translational DOFs moves the set by it along each (diagonally).
  for_each_value(m, [&](int s, int b, double u) {
    const Boundary& bc = m.boundaries[b];
    std::vector<std::string> moved;
    for (int d : bc.dofs)
      if (d < m.dofs_per_node()) moved.push_back(dof_name(m, d));
    if (moved.size() < 2) return;
    std::string list;
    for (std::size_t k = 0; k < moved.size(); ++k)
      list += (k == 0 ? "" : k + 1 == moved.size() ? " and " : ", ") + moved[k];
    out.push_back({s, b,
                   fmt::format("boundary '{}' names {} and step '{}' sets it to {:.4g} {}: a boundary value moves "
                               "every DOF the boundary names by it, so node set '{}' moves by {:.4g} {} along each "
                               "of {}. To move it along one only, hold the others in a boundary of their own (e.g. "
                               "`{}_hold: {{node_set: {}, dofs: [{}]}}`) and name only the moving DOF in '{}'",
                               bc.name, list, m.steps[s].name, in_len(u), len, m.node_sets[bc.node_set].name,
                               in_len(u), len, list, bc.name, m.node_sets[bc.node_set].name, moved.front(), bc.name)});
  });
  return out;
}

std::string boundary_motion_hint(const Model& m, int step) {
  std::string out;
  for (const MotionMisfit& w : boundary_motion_warnings(m))
    if (w.step == step) out += (out.empty() ? "" : " ") + w.message + ".";
  return out;
}

std::string shortening_motions(const Model& m, int step) {
  std::string out;
  const bool axisymmetric = m.dofs_per_node() != 3;
  const std::string len = m.units.display_unit(Dimension::length);
  for_each_motion(m, [&](const Motion& mo) {
    if (mo.step != step || !mo.toward || mo.other < 0 || (axisymmetric && mo.dof == 0) || !(mo.hi > mo.lo)) return;
    out += fmt::format("{}boundary '{}' moves {} by {:.4g} {} toward boundary '{}', {:.3g} % of the model's extent in {}",
                       out.empty() ? "" : "; ", m.boundaries[mo.boundary].name, dof_name(m, mo.dof),
                       m.units.from_internal(mo.u, len, Dimension::length), len, m.boundaries[mo.other].name,
                       100 * std::abs(mo.u) / (mo.hi - mo.lo), dof_name(m, mo.dof));
  });
  return out;
}

}  // namespace tunica
