#include "io/params.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tunica {

ParamSpec number(std::string name, Dimension dim, std::string doc) {
  ParamSpec p;
  p.name = std::move(name);
  p.type = ParamType::number;
  p.dim = dim;
  p.doc = std::move(doc);
  return p;
}
ParamSpec integer(std::string name, std::string doc) {
  ParamSpec p = number(std::move(name), Dimension::dimensionless, std::move(doc));
  p.type = ParamType::integer;
  return p;
}
ParamSpec text(std::string name, std::string doc) {
  ParamSpec p = number(std::move(name), Dimension::dimensionless, std::move(doc));
  p.type = ParamType::text;
  return p;
}
ParamSpec boolean(std::string name, std::string doc) {
  ParamSpec p = number(std::move(name), Dimension::dimensionless, std::move(doc));
  p.type = ParamType::boolean;
  return p;
}
ParamSpec numbers(std::string name, Dimension dim, int count, std::string doc) {
  ParamSpec p = number(std::move(name), dim, std::move(doc));
  p.type = ParamType::numbers;
  p.count = count;
  return p;
}
ParamSpec structured(std::string name, std::string shape, std::string doc) {
  ParamSpec p = number(std::move(name), Dimension::dimensionless, std::move(doc));
  p.type = ParamType::structured;
  p.default_text = "";
  p.choices = {std::move(shape)};
  return p;
}
ParamSpec required(ParamSpec p) {
  p.required = true;
  return p;
}
ParamSpec with_default(ParamSpec p, std::string default_text) {
  p.default_text = std::move(default_text);
  return p;
}
ParamSpec positive(ParamSpec p) {
  p.min = 0.0;
  p.min_exclusive = true;
  return p;
}
ParamSpec at_least(ParamSpec p, double min) {
  p.min = min;
  return p;
}
ParamSpec at_most(ParamSpec p, double max) {
  p.max = max;
  return p;
}
ParamSpec one_of(ParamSpec p, std::vector<std::string> choices) {
  p.choices = std::move(choices);
  return p;
}

const Params::Value& Params::get(const std::string& name) const {
  auto it = values_.find(name);
  if (it == values_.end()) throw std::logic_error("parameter '" + name + "' was not read");
  return it->second;
}
double Params::number(const std::string& name) const { return get(name).nums.at(0); }
long Params::integer(const std::string& name) const { return std::lround(get(name).nums.at(0)); }
const std::string& Params::text(const std::string& name) const { return get(name).str; }
bool Params::boolean(const std::string& name) const { return get(name).nums.at(0) != 0.0; }
const std::vector<double>& Params::numbers(const std::string& name) const { return get(name).nums; }
const SourceLocation& Params::where(const std::string& name) const { return get(name).loc; }
void Params::fail(const std::string& name, const std::string& what) const {
  throw InputError(has(name) ? where(name) : self_, what);
}

double read_quantity(const DeckNode& node, Dimension dim, const UnitSystem& units) {
  const std::string s = node.as_string();
  double value = 0;
  std::string unit;
  if (!split_quantity(s, value, unit)) {
    node.fail(dim == Dimension::dimensionless
                  ? "expected a number, got '" + s + "'"
                  : "expected a number with an optional unit (a " + std::string(dimension_name(dim)) +
                        ", e.g. '" + (dim == Dimension::length     ? "0.122 mm"
                                      : dim == Dimension::pressure ? "61.163 kPa"
                                      : dim == Dimension::force    ? "0.1 N"
                                      : dim == Dimension::penalty  ? "1e4 N/mm^3"
                                      : dim == Dimension::moment   ? "0.5 N*mm"
                                                                   : "90 deg") +
                        "'), got '" + s + "'");
  }
  try {
    const double v = units.to_internal(value, unit, dim);
    if (!std::isfinite(v)) node.fail("value '" + s + "' is not finite");
    return v;
  } catch (const std::invalid_argument& e) {
    node.fail(std::string(e.what()) + " (in '" + s + "'; expected a " + dimension_name(dim) + ")");
  }
}

static std::string range_text(const ParamSpec& p) {
  std::string r;
  if (p.min) r += (p.min_exclusive ? "> " : ">= ") + fmt::format("{:g}", *p.min);
  if (p.max) r += (r.empty() ? "" : ", ") + fmt::format("<= {:g}", *p.max);
  return r;
}

Params read_params(const DeckNode& node, const ComponentSpec& spec, const UnitSystem& units,
                   const std::vector<std::string>& extra_keys) {
  std::vector<std::string> allowed = extra_keys;
  for (const auto& p : spec.params) allowed.push_back(p.name);
  node.expect_map_with_keys(allowed);
  Params out;
  out.self_ = node.where();
  for (const auto& p : spec.params) {
    if (p.type == ParamType::structured) {
      if (p.required) node.required(p.name);
      continue;  // read by the section itself
    }
    const DeckNode given = node[p.name];
    // A key written without a value is an error, required or not: the sections test for a key's
    // presence (node.has) and would otherwise find it present but unread.
    if (given.yaml().IsDefined() && given.yaml().IsNull()) given.fail("key '" + p.name + "' has no value");
    const bool missing = !given.yaml().IsDefined();
    if (missing) {
      if (p.required) {
        SourceLocation w = node.where();
        w.key = given.path();
        throw InputError(w, "missing required key '" + p.name + "' (" + p.doc + ")");
      }
      if (p.default_text.empty()) continue;
    }
    // yaml-cpp nodes have reference semantics (assigning to a missing one throws): build anew.
    const DeckNode v = missing ? DeckNode(YAML::Load(p.default_text), node.file(), given.path(), node.where()) : given;
    Params::Value val;
    val.loc = v.where();
    switch (p.type) {
      case ParamType::number: val.nums = {read_quantity(v, p.dim, units)}; break;
      case ParamType::integer: val.nums = {static_cast<double>(v.as_integer())}; break;
      case ParamType::boolean: val.nums = {v.as_bool() ? 1.0 : 0.0}; break;
      case ParamType::text:
        val.str = v.as_string();
        if (!p.choices.empty() && std::find(p.choices.begin(), p.choices.end(), val.str) == p.choices.end()) {
          std::string list;
          for (const auto& c : p.choices) list += (list.empty() ? "" : ", ") + c;
          v.fail("'" + val.str + "' is not one of: " + list);
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
        if (below || above)
          v.fail(fmt::format("value {:g} is out of range (must be {})", x, range_text(p)));
      }
    }
    out.values_[p.name] = std::move(val);
  }
  return out;
}

std::string params_markdown(const ComponentSpec& spec) {
  std::string s = "| key | type | unit | required / default | range | meaning |\n|---|---|---|---|---|---|\n";
  for (const auto& p : spec.params) {
    const char* type = p.type == ParamType::number    ? "number"
                       : p.type == ParamType::integer ? "integer"
                       : p.type == ParamType::text    ? "text"
                       : p.type == ParamType::boolean ? "boolean"
                       : p.type == ParamType::numbers ? "list of numbers"
                                                      : "";
    std::string type_s = p.type == ParamType::structured ? p.choices.front() : type;
    if (p.type == ParamType::numbers && p.count > 0) type_s += fmt::format(" ({})", p.count);
    std::string range = range_text(p);
    if (!p.choices.empty() && p.type != ParamType::structured) {
      for (const auto& c : p.choices) range += (range.empty() ? "`" : ", `") + c + "`";
    }
    const std::string dim = p.dim == Dimension::dimensionless ? "–" : dimension_name(p.dim);
    const std::string req = p.required ? "required" : (p.default_text.empty() ? "optional" : "`" + p.default_text + "`");
    std::string doc;  // a '|' would end the Markdown cell
    for (char c : p.doc) {
      if (c == '|') doc.push_back('\\');
      doc.push_back(c);
    }
    s += fmt::format("| `{}` | {} | {} | {} | {} | {} |\n", p.name, type_s, dim, req, range.empty() ? "–" : range, doc);
  }
  return s;
}

}  // namespace tunica
