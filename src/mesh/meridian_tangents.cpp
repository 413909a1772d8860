#include "mesh/meridian_tangents.hpp"

#include <stdexcept>

namespace tunica {

std::vector<Eigen::Vector2d> meridian_tangents(const Meridian& m) {
  const std::size_t n = m.size();
  if (n < 2) throw std::invalid_argument("meridian_tangents: a meridian needs at least two nodes");
  for (std::size_t i = 0; i + 1 < n; ++i)
    if (!((m[i + 1] - m[i]).norm() > 0)) throw std::invalid_argument("meridian_tangents: two consecutive nodes coincide");
  std::vector<Eigen::Vector2d> t(n);
  if (n == 2) {
    t[0] = t[1] = (m[1] - m[0]).normalized();
    return t;
  }
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const Eigen::Vector2d u = m[i] - m[i - 1], v = m[i + 1] - m[i];
    const Eigen::Vector2d s = v.squaredNorm() * u + u.squaredNorm() * v;
    if (!(s.norm() > 0)) throw std::invalid_argument("meridian_tangents: the meridian folds back on itself");
    t[i] = s.normalized();
  }
  const auto reflect = [](const Eigen::Vector2d& ti, const Eigen::Vector2d& chord) {
    const Eigen::Vector2d e = chord.normalized();
    return Eigen::Vector2d(2.0 * ti.dot(e) * e - ti);
  };
  t[0] = reflect(t[1], m[1] - m[0]);
  t[n - 1] = reflect(t[n - 2], m[n - 1] - m[n - 2]);
  return t;
}

}  // namespace tunica
