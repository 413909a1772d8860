#include "output/history.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "quantities/history_quantity.hpp"

namespace tunica {

namespace {

double reduce(const std::vector<double>& v, Reduce how) {
  if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
  switch (how) {
    case Reduce::min: return *std::min_element(v.begin(), v.end());
    case Reduce::max: return *std::max_element(v.begin(), v.end());
    case Reduce::sum: {
      double s = 0;
      for (double x : v) s += x;
      return s;
    }
    case Reduce::mean: break;
  }
  double s = 0;
  for (double x : v) s += x;
  return s / static_cast<double>(v.size());
}

}  // namespace

std::vector<double> history_values(const Analysis& a, const IncrementInfo& info) {
  const Model& m = a.model();
  const QuantityState state{a.system(), a.displacement(), a.reactions(), a.loads(), info.time};
  std::vector<double> out;
  std::vector<std::vector<MembranePoint>> points(m.parts.size());
  std::vector<std::vector<SolidPoint>> solid_points(m.parts.size());
  for (const auto& r : m.output.history) {
    const HistoryQuantity* q = find_history_quantity(r.quantity);
    if (!q) throw std::logic_error("unknown history quantity " + r.quantity);
    std::vector<double> vals;
    double v = 0;
    switch (q->target) {
      case QuantityTarget::none: v = q->global(state); break;
      case QuantityTarget::load: v = q->at(state, r.load); break;
      case QuantityTarget::node_set:
        for (int n : m.node_sets[r.node_set].nodes) vals.push_back(q->at(state, n));
        v = reduce(vals, r.reduce);
        break;
      case QuantityTarget::contact:
        for (const auto& c : a.system().contact_states(a.displacement(), r.contact, a.loads().step))
          vals.push_back(q->contact(c));
        v = reduce(vals, r.reduce);
        break;
      case QuantityTarget::part:
        if (m.parts[r.part].is_solid()) {
          if (solid_points[r.part].empty()) solid_points[r.part] = a.system().solid_points(a.displacement(), r.part);
          for (const auto& p : solid_points[r.part]) vals.push_back(q->solid(p));
        } else {
          if (points[r.part].empty()) points[r.part] = a.system().points(a.displacement(), r.part, a.loads().step);
          if (q->membrane_whole) {
            v = q->membrane_whole(points[r.part]);
            break;
          }
          for (const auto& p : points[r.part]) vals.push_back(q->membrane(p));
        }
        v = reduce(vals, r.reduce);
        break;
    }
    out.push_back(m.units.from_internal(v, r.unit, r.dim));
  }
  return out;
}

}  // namespace tunica
