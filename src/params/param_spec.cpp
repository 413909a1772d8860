#include "params/param_spec.hpp"

#include <fmt/format.h>

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
ParamSpec explaining_range(ParamSpec p, std::string why) {
  p.range_fix = std::move(why);
  return p;
}

ParamSpec one_of(ParamSpec p, std::vector<std::string> choices) {
  p.choices = std::move(choices);
  return p;
}

std::string range_text(const ParamSpec& p) {
  std::string r;
  if (p.min) r += (p.min_exclusive ? "> " : ">= ") + fmt::format("{:g}", *p.min);
  if (p.max) r += (r.empty() ? "" : ", ") + fmt::format("<= {:g}", *p.max);
  return r;
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
