#include "mesh/meridian_csv.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <vector>

#include "core/errors.hpp"
#include "core/limits.hpp"
#include "core/printable.hpp"

namespace tunica {

namespace {

std::vector<std::string> split_fields(const std::string& line) {
  std::vector<std::string> out(1);
  for (char c : line) {
    if (c == ',') out.emplace_back();
    else if (c != '\r') out.back() += c;
  }
  for (std::string& f : out) {
    const auto a = f.find_first_not_of(" \t"), b = f.find_last_not_of(" \t");
    f = a == std::string::npos ? std::string() : f.substr(a, b - a + 1);
  }
  return out;
}

}  // namespace

Meridian parse_meridian_csv(const std::string& text, const std::string& file, const UnitSystem& units, long first,
                            long last) {
  const auto fail = [&](int line, const std::string& what) { throw InputError({file, line, 1, ""}, what); };
  std::size_t pos = 0;
  int line = 0;
  const auto next = [&](std::string& out) {
    if (pos >= text.size()) return false;
    const std::size_t end = std::min(text.find('\n', pos), text.size());
    out = text.substr(pos, end - pos);
    pos = end + 1;
    ++line;
    return true;
  };
  std::string header;
  if (!next(header)) fail(1, "the file is empty: a meridian CSV starts with the header node,R_<unit>,Z_<unit>");
  const std::vector<std::string> h = split_fields(header);
  const auto unit_of = [](const std::string& f, char axis) {
    return f.size() > 2 && f[0] == axis && f[1] == '_' ? f.substr(2) : std::string();
  };
  if (h.size() != 3 || h[0] != "node" || unit_of(h[1], 'R').empty() || unit_of(h[2], 'Z') != unit_of(h[1], 'R'))
    fail(1, fmt::format("the header is '{}': a meridian CSV starts with node,R_<unit>,Z_<unit> (as an axisymmetric "
                        "inverse step writes reference_<step>.csv, e.g. node,R_mm,Z_mm)",
                        printable(header, 120)));
  const std::string unit = unit_of(h[1], 'R');
  double scale = 0;
  try {
    scale = units.to_internal(1.0, unit, Dimension::length);
  } catch (const std::invalid_argument&) {
    fail(1, fmt::format("the header's unit '{}' is not a length unit (e.g. R_mm, R_m, R_um)", printable(unit, 40)));
  }
  Meridian points;
  std::string row;
  long node = 0;
  while (next(row)) {
    if (split_fields(row) == std::vector<std::string>{""}) continue;  // a blank line (the last newline)
    const std::vector<std::string> f = split_fields(row);
    if (f.size() != 3) fail(line, fmt::format("expected 3 fields (node, R, Z), found {}", f.size()));
    double v[3];
    for (int k = 0; k < 3; ++k) {
      char* end = nullptr;
      errno = 0;
      v[k] = std::strtod(f[k].c_str(), &end);
      if (f[k].empty() || *end != '\0' || errno == ERANGE || !std::isfinite(v[k]))
        fail(line, fmt::format("field {} ('{}') is not a finite number", k + 1, printable(f[k], 40)));
    }
    if (v[0] != static_cast<double>(node + 1))
      fail(line, fmt::format("node {} follows node {}: the nodes are numbered 1, 2, 3, … in order", f[0], node));
    ++node;
    if (node > kMaxNodes) fail(line, fmt::format("the file has more than {} nodes", kMaxNodes));
    if (first > 0 && (node < first || node > last)) continue;
    if (v[1] < 0) fail(line, fmt::format("R = {} is negative: a meridian stays at R ≥ 0", f[1]));
    const Eigen::Vector2d x(v[1] * scale, v[2] * scale);
    if (!x.allFinite()) fail(line, fmt::format("R = {}, Z = {} in {} is beyond what a model holds", f[1], f[2], unit));
    points.push_back(x);
  }
  if (first > 0 && last > node)
    fail(line, fmt::format("the file ends at node {}, before node {} of `nodes: [{}, {}]`", node, last, first, last));
  if (points.size() < 2) fail(line, "the file holds fewer than 2 nodes: a meridian needs at least one element");
  return points;
}

}  // namespace tunica
