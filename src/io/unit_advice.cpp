#include "io/unit_advice.hpp"

#include <fmt/format.h>

#include <sstream>
#include <stdexcept>
#include <vector>

#include "core/article.hpp"
#include "core/suggest.hpp"

namespace tunica {

std::vector<std::string> common_units(Dimension dim) {
  switch (dim) {
    case Dimension::length: return {"m", "cm", "mm", "um", "nm", "in"};
    case Dimension::force: return {"N", "mN", "kN", "uN", "dyne", "lbf"};
    case Dimension::pressure: return {"Pa", "kPa", "MPa", "GPa", "mmHg", "bar", "psi", "atm", "N/mm^2", "N/m^2"};
    case Dimension::angle: return {"deg", "rad", "degree"};
    case Dimension::volume: return {"mm^3", "cm^3", "m^3", "ml", "ul"};
    case Dimension::penalty: return {"N/mm^3", "N/m^3"};
    case Dimension::moment: return {"N*mm", "N*m"};
    default: return {};
  }
}

namespace {

/// The number of `written` without its unit, trimmed ("3" of "3 MPa abs").
std::string number_of(const std::string& written, const std::string& unit) {
  const std::size_t at = unit.empty() ? std::string::npos : written.rfind(unit);
  std::string n = at == std::string::npos ? written : written.substr(0, at);
  while (!n.empty() && (n.back() == ' ' || n.back() == '\t')) n.pop_back();
  while (!n.empty() && (n.front() == ' ' || n.front() == '\t')) n.erase(0, 1);
  return n;
}

/// ", e.g. `0.122 mm`" (the number as written with a unit of `dim`; for a mistyped unit the
/// nearest common one, else the deck's), or "" for a dimensionless value.
std::string unit_fix(const std::string& number, const std::string& unit, Dimension dim, const UnitSystem& units) {
  if (dim == Dimension::dimensionless) return "";
  std::string fix = nearest_name(unit, common_units(dim));
  if (fix.empty()) fix = dim == Dimension::angle ? "deg" : dim == Dimension::pressure ? "kPa" : units.display_unit(dim);
  return fmt::format(", e.g. `{} {}`", number, fix);
}

bool converts(const std::string& unit, Dimension dim, const UnitSystem& units) {
  try {
    units.check_unit(unit, dim);
    return true;
  } catch (const std::invalid_argument&) {
    return false;
  }
}

}  // namespace

std::string unit_advice(const std::string& written, const std::string& unit, Dimension dim, const UnitSystem& units,
                        const std::string& reason) {
  const std::string number = number_of(written, unit);
  const std::string expected = with_article(dimension_name(dim));
  if (dim == Dimension::angle && (unit == "grad" || unit == "grads" || unit == "gon" || unit == "gradian" ||
                                  unit == "gradians")) {
    return fmt::format("{} (in '{}'; expected {}): '{}' means degrees in some languages and gradians in others; for "
                       "degrees write `{} deg`, for gradians (400 to a turn) `{} grade`",
                       reason, written, expected, unit, number, number);
  }
  // Words UDUNITS-2 multiplies: name the first that is no unit, and the unit the others make.
  std::vector<std::string> words, known;
  std::string unknown;
  std::istringstream in(unit);
  for (std::string w; in >> w;) {
    words.push_back(w);
    if (is_unit(w)) known.push_back(w);
    else if (unknown.empty()) unknown = w;
  }
  if (words.size() > 1 && !unknown.empty()) {
    std::string rest;
    for (const auto& w : known) rest += (rest.empty() ? "" : " ") + w;
    const std::string what = fmt::format("unit '{}' is not understood (in '{}'): '{}' is not a unit, and UDUNITS-2 "
                                         "reads the words of a unit as units multiplied",
                                         unit, written, unknown);
    if (!rest.empty() && converts(rest, dim, units))
      return fmt::format("{}; '{}' alone is {}: write `{} {}` (a note can follow as a YAML comment, `# {}`)", what, rest,
                         expected, number, rest, unknown);
    return fmt::format("{} (expected {}{})", what, expected, unit_fix(number, unknown, dim, units));
  }
  return fmt::format("{} (in '{}'; expected {}{})", reason, written, expected, unit_fix(number, unit, dim, units));
}

}  // namespace tunica
