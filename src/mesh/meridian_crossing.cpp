#include "mesh/meridian_crossing.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <vector>

namespace tunica {

namespace {

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a(0) * b(1) - a(1) * b(0); }

/// A point that segments p0p1 and q0q1 share (within tol), if any.
std::optional<Eigen::Vector2d> meet(const Eigen::Vector2d& p0, const Eigen::Vector2d& p1, const Eigen::Vector2d& q0,
                                    const Eigen::Vector2d& q1, double tol) {
  const Eigen::Vector2d r = p1 - p0, s = q1 - q0;
  const double denom = cross(r, s);
  const auto on = [&](const Eigen::Vector2d& x, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    const Eigen::Vector2d ab = b - a;
    const double t = std::clamp((x - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    return (a + t * ab - x).norm() <= tol;
  };
  if (std::abs(denom) > tol * (r.norm() + s.norm())) {
    const double t = cross(q0 - p0, s) / denom, u = cross(q0 - p0, r) / denom;
    const double et = tol / r.norm(), eu = tol / s.norm();
    if (t >= -et && t <= 1 + et && u >= -eu && u <= 1 + eu) return Eigen::Vector2d(p0 + std::clamp(t, 0.0, 1.0) * r);
    return std::nullopt;
  }
  // Parallel: they share a point only where one's end lies on the other.
  for (const auto& [x, a, b] : {std::tuple{q0, p0, p1}, std::tuple{q1, p0, p1}, std::tuple{p0, q0, q1},
                                std::tuple{p1, q0, q1}})
    if (on(x, a, b)) return x;
  return std::nullopt;
}

}  // namespace

std::optional<MeridianCrossing> meridian_crossing(const Meridian& m) {
  const int n = static_cast<int>(m.size()) - 1;  // elements
  if (n < 2) return std::nullopt;
  double longest = 0;
  Eigen::Vector2d lo = m.front(), hi = lo;
  for (int e = 0; e < n; ++e) longest = std::max(longest, (m[e + 1] - m[e]).norm());
  for (const auto& x : m) lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
  const double tol = 1e-9 * std::max((hi - lo).norm(), longest);
  if (!(longest > 0)) return std::nullopt;
  // Neighbours fold back when the second runs back along the first.
  std::optional<MeridianCrossing> found;
  const auto keep = [&](int a, int b, const Eigen::Vector2d& at) {
    if (!found || b < found->second || (b == found->second && a > found->first)) found = MeridianCrossing{a, b, at};
  };
  for (int e = 0; e + 1 < n; ++e) {
    const Eigen::Vector2d u = m[e + 1] - m[e], v = m[e + 2] - m[e + 1];
    if (std::abs(cross(u, v)) <= 1e-12 * u.norm() * v.norm() && u.dot(v) < 0) keep(e, e + 1, m[e + 1]);
  }
  // Elements that are not neighbours: those in one cell of a grid of the longest element's size.
  const double h = longest;
  const auto cell = [&](double x) { return static_cast<long long>(std::floor((x - lo(0) + h) / h)); };
  const auto celly = [&](double y) { return static_cast<long long>(std::floor((y - lo(1) + h) / h)); };
  std::unordered_map<long long, std::vector<int>> grid;
  const long long wide = cell(hi(0)) + 2;
  for (int e = 0; e < n; ++e) {
    const Eigen::Vector2d a = m[e].cwiseMin(m[e + 1]), b = m[e].cwiseMax(m[e + 1]);
    for (long long i = cell(a(0) - tol); i <= cell(b(0) + tol); ++i)
      for (long long j = celly(a(1) - tol); j <= celly(b(1) + tol); ++j) grid[j * wide + i].push_back(e);
  }
  for (const auto& [key, elements] : grid)
    for (std::size_t p = 0; p < elements.size(); ++p)
      for (std::size_t q = p + 1; q < elements.size(); ++q) {
        const int a = std::min(elements[p], elements[q]), b = std::max(elements[p], elements[q]);
        if (b - a < 2) continue;
        if (const auto at = meet(m[a], m[a + 1], m[b], m[b + 1], tol)) keep(a, b, *at);
      }
  return found;
}

}  // namespace tunica
