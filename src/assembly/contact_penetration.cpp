#include "assembly/contact_penetration.hpp"

#include <fmt/format.h>

namespace tunica {

namespace {

/// The reference length of the elements at position i of a chain: the mean of its segments.
double element_length(const Model& m, const std::vector<int>& chain, int i) {
  double sum = 0;
  int count = 0;
  if (i > 0) sum += (m.X[chain[i]] - m.X[chain[i - 1]]).norm(), ++count;
  if (i + 1 < static_cast<int>(chain.size())) sum += (m.X[chain[i + 1]] - m.X[chain[i]]).norm(), ++count;
  return count > 0 ? sum / count : 0.0;
}

/// "node i of part 'P'": a global node by its index along the first part that holds it.
std::string node_label(const Model& m, int node) {
  for (const Part& part : m.parts)
    for (std::size_t i = 0; i < part.nodes.size(); ++i)
      if (part.nodes[i] == node) return fmt::format("node {} of part '{}'", i, part.name);
  return fmt::format("node {}", node);
}

}  // namespace

std::string far_penetration_warning(const System& system, const Eigen::VectorXd& u, int step, int c,
                                    const std::string& when) {
  const Model& m = system.model();
  const ContactPair& pair = m.contacts[c];
  if (pair.is_reverse_pass()) return "";
  const std::vector<ContactNodeState> states = system.contact_states(u, c, step);
  int worst = -1;
  double worst_ratio = kFarPenetration, worst_length = 0;
  for (std::size_t k = 0; k < states.size(); ++k) {
    if (!states[k].point.active) continue;
    const double h = element_length(m, pair.area_chain, pair.area_index[k]);
    if (!(h > 0)) continue;
    const double ratio = -states[k].point.gap / h;
    if (ratio > worst_ratio) worst_ratio = ratio, worst = static_cast<int>(k), worst_length = h;
  }
  if (worst < 0) return "";
  const ContactPoint& p = states[worst].point;
  const double depth = -p.gap;
  // The penalty is halved per pass in a two-pass pair: the pair's own is twice its first pass's.
  const double penalty = pair.reverse >= 0 ? 2 * pair.law.penalty : pair.law.penalty;
  const double wanted = penalty * depth / (1e-3 * worst_length);  // leaves 10⁻³ h at this pressure
  const std::string len = m.units.display_unit(Dimension::length), eps = m.units.display_unit(Dimension::penalty);
  const std::string surface = pair.deformable() ? fmt::format("the master '{}'", pair.master_name)
                                                : fmt::format("the rigid surface '{}'", m.rigid_surfaces[pair.rigid].name);
  const std::string side =
      pair.deformable() ? "`master_orientation`"
      : m.rigid_surfaces[pair.rigid].type == RigidSurface::Type::cylinder ? "the cylinder's `side`"
                                                                           : "the polyline's point order";
  const std::string sunk = fmt::format(
      "contact pair '{}': {}, the slave's {} has sunk {:.4g} {} into {}, {:.2g} of its element length {:.4g} {} "
      "(contact pressure {:.4g} kPa against the penalty {:.4g} {})",
      pair.name, when, node_label(m, pair.nodes[worst]), depth, len, surface, worst_ratio, worst_length, len,
      m.units.from_internal(p.pressure, "kPa", Dimension::pressure), penalty, eps);
  // A slave whose enclosed volume the step prescribes, against a rigid surface: a target beyond what
  // fits inside it, not the penalty, sets how far it sinks in (a stiffer penalty raises the pressure).
  const Step* st = step >= 0 && step < static_cast<int>(m.steps.size()) ? &m.steps[step] : nullptr;
  if (st && !pair.deformable() && st->volume_control.load >= 0 &&
      m.loads[st->volume_control.load].part == pair.part) {
    const std::string vu = m.units.display_unit(Dimension::volume);
    return format_location(
        pair.where,
        fmt::format("{}, and step '{}' prescribes the volume of load '{}' on the slave (`volume_control`, target "
                    "{:.4g} {}). If the target is more than fits inside {}, the volume and not the penalty sets how "
                    "deep the slave sinks (a larger `penalty` raises the pressure, not the depth): lower the step's "
                    "`volume` target, or control the pressure instead. Otherwise raise `penalty` (to about {:.2g} {} "
                    "for a penetration of 10⁻³ of the element length). The contact results there are not to be "
                    "trusted.",
                    sunk, st->name, m.loads[st->volume_control.load].name,
                    m.units.from_internal(st->volume_control.target, vu, Dimension::volume), vu, surface, wanted,
                    eps));
  }
  return format_location(
      pair.where,
      fmt::format("{}, far more than a penalty should leave (the penetration p_c/ε should be small against the "
                  "element length: user guide §3.2, choosing ε): the contact results there are not to be trusted. "
                  "Raise `penalty` (to about {:.2g} {} for a penetration of 10⁻³ of the element length); if the "
                  "slave should not press this hard on {} at all, check {}.",
                  sunk, wanted, eps, surface, side));
}

}  // namespace tunica
