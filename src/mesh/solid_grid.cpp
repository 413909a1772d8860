#include "mesh/solid_grid.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace tunica {

double profile_radius(const RadiusProfile& p, double z, double z0, double z1) {
  const double zc = 0.5 * (z0 + z1), L = z1 - z0;
  switch (p.type) {
    case RadiusProfile::Type::constant: return p.radius;
    case RadiusProfile::Type::polyline: {
      const auto& q = p.points;
      const double tol = 1e-12 * std::max(1.0, std::abs(L));
      for (std::size_t k = 0; k + 1 < q.size(); ++k)
        if (z >= q[k](1) - tol && z <= q[k + 1](1) + tol) {
          const double t = std::clamp((z - q[k](1)) / (q[k + 1](1) - q[k](1)), 0.0, 1.0);
          return q[k](0) + t * (q[k + 1](0) - q[k](0));  // linear interpolation between the two points
        }
      throw std::invalid_argument(fmt::format("the polyline does not reach z = {:g} (its points span z = {:g} … {:g})",
                                              z, q.front()(1), q.back()(1)));
    }
    case RadiusProfile::Type::cosine:
      // r = r_e + (r_c − r_e) ½ (1 + cos(2π (z − z_c)/L)): r_c at z_c, r_e and zero slope at both ends.
      return p.radius_ends + (p.radius_centre - p.radius_ends) * 0.5 * (1.0 + std::cos(2.0 * std::numbers::pi * (z - zc) / L));
    case RadiusProfile::Type::circular: {
      // Arc of radius ρ = (a² + d²)/(2|d|) (a = L/2, d = r_e − r_c) with its centre on z = z_c:
      // r = r_c + sign(d) (ρ − √(ρ² − (z − z_c)²)).
      const double a = 0.5 * L, d = p.radius_ends - p.radius_centre;
      if (d == 0) return p.radius_ends;
      if (std::abs(d) > a)
        throw std::invalid_argument(fmt::format(
            "a circular profile needs |radius_ends − radius_centre| = {:g} ≤ half the length {:g}", std::abs(d), a));
      const double rho = (a * a + d * d) / (2.0 * std::abs(d)), s = z - zc;
      return p.radius_centre + std::copysign(rho - std::sqrt(std::max(0.0, rho * rho - s * s)), d);
    }
  }
  return 0;
}

SolidGrid solid_grid(const SolidGridSpec& s) {
  if (!(s.z1 > s.z0)) throw std::invalid_argument(fmt::format("z1 = {:g} must exceed z0 = {:g}", s.z1, s.z0));
  if (s.elements_r < 1 || s.elements_z < 1) throw std::invalid_argument("the element counts must be at least 1");
  for (const RadiusProfile* p : {&s.inner, &s.outer})
    if (p->type == RadiusProfile::Type::polyline) {
      if (p->points.size() < 2) throw std::invalid_argument("a polyline profile needs at least 2 points");
      for (std::size_t k = 0; k + 1 < p->points.size(); ++k)
        if (!(p->points[k + 1](1) > p->points[k](1)))
          throw std::invalid_argument(fmt::format("the z of a polyline profile must increase strictly (point {})", k + 1));
    }
  const int nr = s.elements_r, nz = s.elements_z;
  SolidGrid g;
  g.nodes.reserve(static_cast<std::size_t>(nr + 1) * (nz + 1));
  for (int j = 0; j <= nz; ++j) {
    const double z = j == nz ? s.z1 : s.z0 + (s.z1 - s.z0) * j / nz;
    const double ri = profile_radius(s.inner, z, s.z0, s.z1), ro = profile_radius(s.outer, z, s.z0, s.z1);
    if (!(ri > 0)) throw std::invalid_argument(fmt::format("the inner radius {:g} at z = {:g} is not positive", ri, z));
    if (!(ro > ri))
      throw std::invalid_argument(
          fmt::format("the inner radius {:g} is not below the outer radius {:g} at z = {:g}", ri, ro, z));
    for (int i = 0; i <= nr; ++i) g.nodes.emplace_back(ri + (ro - ri) * i / nr, z);
  }
  const auto node = [&](int i, int j) { return j * (nr + 1) + i; };
  for (int j = 0; j < nz; ++j)
    for (int i = 0; i < nr; ++i) {
      const int q[4] = {node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)};
      // Each corner's det(∂X/∂ξ) is ¼ of the cross product of its two edges (counter-clockwise).
      double longest = 0;
      for (int a = 0; a < 4; ++a) longest = std::max(longest, (g.nodes[q[(a + 1) % 4]] - g.nodes[q[a]]).squaredNorm());
      for (int a = 0; a < 4; ++a) {
        const Eigen::Vector2d e1 = g.nodes[q[(a + 1) % 4]] - g.nodes[q[a]], e0 = g.nodes[q[(a + 3) % 4]] - g.nodes[q[a]];
        if (!(e1(0) * e0(1) - e1(1) * e0(0) > 1e-12 * longest))
          throw std::invalid_argument(fmt::format("element {} (radial {}, axial {}) is degenerate or inverted", j * nr + i, i, j));
      }
      g.quads.insert(g.quads.end(), q, q + 4);
    }
  for (int j = 0; j <= nz; ++j) {
    g.inner.push_back(node(0, j));
    g.outer.push_back(node(nr, j));
  }
  for (int i = 0; i <= nr; ++i) {
    g.bottom.push_back(node(i, 0));
    g.top.push_back(node(i, nz));
  }
  return g;
}

}  // namespace tunica
