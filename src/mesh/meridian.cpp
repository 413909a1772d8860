#include "mesh/meridian.hpp"

#include <algorithm>
#include <cmath>

namespace tunica {

Meridian line_meridian(const Eigen::Vector2d& a, const Eigen::Vector2d& b, int n) {
  Meridian m(n + 1);
  for (int i = 0; i <= n; ++i) m[i] = a + (b - a) * (static_cast<double>(i) / n);
  return m;
}

Meridian arc_meridian(const Eigen::Vector2d& center, double rho, double phi0, double phi1, int n) {
  Meridian m(n + 1);
  // A pole on the axis lies exactly on it; so does a node less than a thousandth of an element
  // beyond it, as written angles put it (1.5708 for π/2 is 4·10⁻⁶ rad past the pole), the same
  // tolerance as a tube's columns on the planes x = 0, y = 0 (surface_generators.cpp).
  const double beyond = std::max(1e-12 * rho, kOnAxisFraction * rho * std::abs(phi1 - phi0) / n);
  for (int i = 0; i <= n; ++i) {
    const double phi = phi0 + (phi1 - phi0) * (static_cast<double>(i) / n);
    double r = center(0) + rho * std::cos(phi);
    if (std::abs(r) < 1e-12 * rho || (r < 0 && r >= -beyond)) r = 0.0;
    m[i] = Eigen::Vector2d(r, center(1) + rho * std::sin(phi));
  }
  return m;
}

static const ParamSpec kElements =
    required(at_most(at_least(integer("elements", "number of elements along the meridian"), 1), 1e7));

const std::map<std::string, MeridianType>& meridian_types() {
  static const std::map<std::string, MeridianType> types = {
      {"line",
       {ComponentSpec{"mesh", "line", "Straight meridian from `from` to `to`, points given as [r, z].",
                      {required(numbers("from", Dimension::length, 2, "first point [r, z]")),
                       required(numbers("to", Dimension::length, 2, "last point [r, z]")), kElements}},
        [](const Params& p) {
          const auto& a = p.numbers("from");
          const auto& b = p.numbers("to");
          return line_meridian({a[0], a[1]}, {b[0], b[1]}, static_cast<int>(p.integer("elements")));
        }}},
      {"arc",
       {ComponentSpec{"mesh", "arc",
                      "Circular-arc meridian about `center`; angles from the +r axis towards +z "
                      "(−90 deg = lower pole, 0 = equator, 90 deg = upper pole). A node less than a thousandth "
                      "of an element beyond the axis lies on it (`end_angle: 1.5708`).",
                      {required(numbers("center", Dimension::length, 2, "centre [r, z]")),
                       required(positive(number("radius", Dimension::length, "arc radius"))),
                       required(number("start_angle", Dimension::angle, "angle of the first node")),
                       required(number("end_angle", Dimension::angle, "angle of the last node")), kElements}},
        [](const Params& p) {
          const auto& c = p.numbers("center");
          return arc_meridian({c[0], c[1]}, p.number("radius"), p.number("start_angle"), p.number("end_angle"),
                              static_cast<int>(p.integer("elements")));
        }}},
  };
  return types;
}

}  // namespace tunica
