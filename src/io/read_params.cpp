#include "io/read_params.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "core/article.hpp"
#include "core/suggest.hpp"
#include "io/unit_advice.hpp"

namespace tunica {

namespace {

/// "value '<as written>' (= x <unit>) is out of range (must be … <unit>)", and for a plain
/// number given to an angle that would fit in degrees, the fix.
std::string out_of_range_message(const DeckNode& v, const ParamSpec& p, double x, const UnitSystem& units) {
  const std::string unit = units.display_unit(p.dim);
  const std::string written = v.is_scalar() ? v.as_string() : fmt::format("{:g}", x);
  double number = 0;
  std::string typed;
  const bool plain = split_quantity(written, number, typed) && typed.empty();
  std::string s = plain || unit.empty() || typed == unit ? fmt::format("value {} is out of range (must be {}{})", written, range_text(p),
                                                      unit.empty() ? "" : " " + unit)
                                        : fmt::format("value {} (= {:g} {}) is out of range (must be {} {})", written, x,
                                                      unit, range_text(p), unit);
  if (p.dim == Dimension::angle && plain) {
    const double rad = x * std::numbers::pi / 180;
    const bool fits = !(p.min && (p.min_exclusive ? rad <= *p.min : rad < *p.min)) && !(p.max && rad > *p.max);
    if (fits) s += fmt::format(": a plain number is radians; for degrees write `{} deg`", written);
  }
  if (!p.range_fix.empty()) s += ": " + p.range_fix;
  return s;
}

/// What a missing key's value looks like: "<a length, e.g. 1 mm>", "<one of: a, b>", ...
std::string value_placeholder(const ParamSpec& p, const UnitSystem& units) {
  switch (p.type) {
    case ParamType::number:
      return p.dim == Dimension::dimensionless ? "<a number>"
                                               : fmt::format("<{} in {}>", with_article(dimension_name(p.dim)),
                                                             p.dim == Dimension::angle ? "deg" : units.internal_unit(p.dim));
    case ParamType::integer: return "<an integer>";
    case ParamType::boolean: return "<true or false>";
    case ParamType::numbers: return fmt::format("[<{} values>]", p.count > 0 ? std::to_string(p.count) : "the");
    case ParamType::text: {
      if (p.choices.empty()) return "<a name>";
      std::string list;
      for (const auto& c : p.choices) list += (list.empty() ? "" : " | ") + c;
      return "<" + list + ">";
    }
    case ParamType::structured: {
      const std::string shape = p.choices.empty() ? "" : p.choices.front();  // structured(): its shape
      return shape == "list" ? "[...]" : shape == "map" ? "{...}" : "<...>";
    }
  }
  return "<...>";
}

/// " (<doc>): add `<key>: <placeholder>` to '<map>'", or ": <the key's own fix>".
std::string missing_fix(const ParamSpec& p, const DeckNode& map, const UnitSystem& units) {
  if (!p.missing_fix.empty()) return ": " + p.missing_fix;
  return fmt::format(" ({}): add `{}: {}` to {}", p.doc, p.name, value_placeholder(p, units),
                     map.path().empty() ? std::string("the deck") : "'" + map.path() + "'");
}

}  // namespace

double read_quantity(const DeckNode& node, Dimension dim, const UnitSystem& units) {
  const std::string s = node.as_string();
  double value = 0;
  std::string unit;
  if (!split_quantity(s, value, unit)) {
    // A number beyond what a double holds (1e400): say so, not that it is none.
    {
      const char* begin = s.c_str();
      while (*begin == ' ' || *begin == '\t') ++begin;
      char* end = nullptr;
      errno = 0;
      const double v = std::strtod(begin, &end);
      if (end != begin && errno == ERANGE && std::abs(v) > 1)
        node.fail(fmt::format("the number in '{}' is too large for any value (beyond 1.8e308)", s));
    }
    if (dim == Dimension::dimensionless) node.fail("expected a number, got '" + s + "'");
    const char* example = dim == Dimension::length     ? "0.122 mm"
                          : dim == Dimension::pressure ? "61.163 kPa"
                          : dim == Dimension::force    ? "0.1 N"
                          : dim == Dimension::penalty  ? "1e4 N/mm^3"
                          : dim == Dimension::moment   ? "0.5 N*mm"
                                                       : "90 deg";
    node.fail(fmt::format("expected a number with an optional unit ({}, e.g. '{}'), got '{}'",
                          with_article(dimension_name(dim)), example, s));
  }
  try {
    const double v = units.to_internal(value, unit, dim);
    if (!std::isfinite(v)) node.fail("value '" + s + "' is not finite");
    return v;
  } catch (const std::invalid_argument& e) {
    node.fail(unit_advice(s, unit, dim, units, e.what()));
  }
}

Params read_params(const DeckNode& node, const ComponentSpec& spec, const UnitSystem& units,
                   const std::vector<std::string>& extra_keys) {
  std::vector<std::string> allowed = extra_keys;
  for (const auto& p : spec.params) allowed.push_back(p.name);
  node.expect_map_with_keys(allowed);
  Params out;
  out.set_where(node.where());
  for (const auto& p : spec.params) {
    if (p.type == ParamType::structured) {
      if (p.required && !node.has(p.name)) node.required(p.name, missing_fix(p, node, units));
      if (p.required) node.required(p.name);  // present: not null
      continue;  // read by the section itself
    }
    const DeckNode given = node[p.name];
    // A key written without a value is an error, required or not: the sections test for a key's
    // presence (node.has) and would otherwise find it present but unread.
    if (given.yaml().IsDefined() && given.yaml().IsNull()) given.fail("key '" + p.name + "' has no value");
    const bool missing = !given.yaml().IsDefined();
    if (missing) {
      if (p.required) node.required(p.name, missing_fix(p, node, units));
      if (p.default_text.empty()) continue;
    }
    // yaml-cpp nodes have reference semantics (assigning to a missing one throws): build anew.
    const DeckNode v = missing ? DeckNode(YAML::Load(p.default_text), node.file(), given.path(), node.where()) : given;
    Params::Value val;
    val.loc = v.where();
    if (missing) {  // a default stands where the component's map does (params.hpp), not in its own text
      val.loc = node.where();
      val.loc.key = given.path();
    }
    switch (p.type) {
      case ParamType::number:
        val.nums = {read_quantity(v, p.dim, units)};
        val.written = v.as_string();
        break;
      case ParamType::integer: val.nums = {static_cast<double>(v.as_integer())}; break;
      case ParamType::boolean: val.nums = {v.as_bool() ? 1.0 : 0.0}; break;
      case ParamType::text:
        val.str = v.as_string();
        if (!p.choices.empty() && std::find(p.choices.begin(), p.choices.end(), val.str) == p.choices.end()) {
          std::string list;
          for (const auto& c : p.choices) list += (list.empty() ? "" : ", ") + c;
          v.fail("'" + val.str + "' is not one of: " + list + did_you_mean(val.str, p.choices));
        }
        break;
      case ParamType::structured: break;
      case ParamType::numbers: {
        if (!v.is_sequence()) v.fail("expected a list of " + std::string(dimension_name(p.dim)) + " values");
        for (const auto& item : v.items()) val.nums.push_back(read_quantity(item, p.dim, units));
        if (p.count > 0 && static_cast<int>(val.nums.size()) != p.count)
          v.fail(fmt::format("expected {} values, got {}", p.count, val.nums.size()));
        break;
      }
    }
    if (p.type == ParamType::number || p.type == ParamType::integer || p.type == ParamType::numbers) {
      for (double x : val.nums) {
        const bool below = p.min && (p.min_exclusive ? x <= *p.min : x < *p.min);
        const bool above = p.max && x > *p.max;
        if (below || above) v.fail(out_of_range_message(v, p, x, units));
      }
    }
    out.set(p.name, std::move(val));
  }
  return out;
}

}  // namespace tunica
