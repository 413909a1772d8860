#include "io/unitless_values.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace tunica {

bool warn_if_unitless(const DeckNode& v, Dimension dim, Model& m, bool load_target) {
  if (dim != Dimension::pressure && dim != Dimension::angle && dim != Dimension::penalty) return false;
  double written = 0;
  std::string unit;
  if (!v.is_scalar() || !split_quantity(v.as_string(), written, unit) || !unit.empty() || written == 0) return false;
  const std::string& w = v.as_string();
  if (dim == Dimension::penalty) {
    // A pressure per length: its unit follows both the force and the length unit of the deck.
    const std::string deck_unit = m.units.display_unit(Dimension::penalty);
    m.warnings.push_back(format_location(
        v.where(), fmt::format("{} has no unit and is taken in the deck's unit of a penalty (contact pressure per unit "
                               "penetration), {}; write the unit to be sure, e.g. `{} {}` (this value)",
                               w, deck_unit, w, deck_unit)));
    return true;
  }
  if (dim == Dimension::angle) {
    m.warnings.push_back(format_location(
        v.where(), fmt::format("{} has no unit and is read in radians ({} rad = {:.4g} deg); write the unit to be sure, "
                               "e.g. `{} rad`, or `{} deg` if degrees are meant",
                               w, w, written * 180 / std::numbers::pi, w, w)));
    return true;
  }
  // The value as read, spelt with a unit, keeps the model; the number with the unit a user most
  // likely meant (mmHg for a load, kPa for a modulus) is offered only where it changes the value.
  const double p = m.units.to_internal(written, "", Dimension::pressure);
  const std::string deck_unit = m.units.display_unit(Dimension::pressure);
  const double kpa = m.units.from_internal(p, "kPa", Dimension::pressure);
  const std::string meant = load_target ? "mmHg" : "kPa";
  const double as_meant = m.units.to_internal(written, meant, Dimension::pressure);
  std::string other =
      std::abs(as_meant - p) > 1e-9 * std::abs(p) ? fmt::format(", or `{} {}` if {} is meant", w, meant, meant) : "";
  // A value in the hundreds or more from SI habits: pascals (FEBio and Abaqus decks in m, N, Pa).
  if (std::abs(written) >= 100 &&
      std::abs(m.units.to_internal(written, "Pa", Dimension::pressure) - p) > 1e-9 * std::abs(p))
    other += fmt::format(", or `{} Pa` if pascals are meant", w);
  m.warnings.push_back(format_location(
      v.where(), load_target ? fmt::format("{} has no unit and is taken in the deck's pressure unit, {} (= {:.4g} kPa = "
                                           "{:.4g} mmHg); write the unit to be sure, e.g. `{:.10g} kPa` (this value){}",
                                           w, deck_unit, kpa, m.units.from_internal(p, "mmHg", Dimension::pressure), kpa,
                                           other)
                             : fmt::format("{} has no unit and is taken in the deck's pressure unit, {} (= {:.4g} kPa); "
                                           "write the unit to be sure, e.g. `{:.10g} kPa` (this value){}",
                                           w, deck_unit, kpa, kpa, other)));
  return true;
}

bool warn_if_gradians(const DeckNode& v, Model& m) {
  double written = 0;
  std::string unit;
  if (!v.is_scalar() || !split_quantity(v.as_string(), written, unit) || unit.empty() || written == 0) return false;
  double rad = 0;
  try {
    rad = m.units.to_internal(written, unit, Dimension::angle);
  } catch (const std::invalid_argument&) {
    return false;  // read_quantity says what is wrong with the unit
  }
  const double gradian = std::numbers::pi / 200;
  if (std::abs(rad - written * gradian) > 1e-9 * std::abs(written * gradian)) return false;
  m.warnings.push_back(format_location(
      v.where(), fmt::format("{} is {:.4g} deg: `{}` is the gradian (400 to a turn), not the degree; write `{:g} deg` if "
                             "degrees are meant",
                             v.as_string(), rad * 180 / std::numbers::pi, unit, written)));
  return true;
}

void warn_unitless_values(const DeckNode& node, const ComponentSpec& spec, Model& m) {
  for (const ParamSpec& p : spec.params) {
    if ((p.dim != Dimension::pressure && p.dim != Dimension::angle && p.dim != Dimension::penalty) ||
        !node.has(p.name))
      continue;
    const DeckNode given = node[p.name];
    const auto warn = [&](const DeckNode& v) {
      return warn_if_unitless(v, p.dim, m) || (p.dim == Dimension::angle && warn_if_gradians(v, m));
    };
    if (given.is_sequence()) {
      for (const DeckNode& v : given.items())
        if (warn(v)) break;
    } else {
      warn(given);
    }
  }
}

}  // namespace tunica
