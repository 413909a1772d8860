#include "contact/contact_search.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tunica {

Eigen::Vector2d segment_normal(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d d = b - a;
  const double l = d.norm();
  if (!(l > 0)) throw std::domain_error("contact: master segment of zero length");
  return Eigen::Vector2d(d(1), -d(0)) / l;
}

ChainProjection project_on_chain(const Eigen::Vector2d& x, const Eigen::Ref<const Eigen::Matrix2Xd>& chain,
                                 double search_radius, double end_tolerance) {
  const int m = static_cast<int>(chain.cols());
  if (m < 2) throw std::invalid_argument("contact: a master chain needs at least two nodes");

  // Linear scan; squared distances; strict '<' keeps the lowest index on ties.
  double best2 = search_radius * search_radius;
  int k_best = -1;
  double xi_best = 0;
  for (int k = 0; k + 1 < m; ++k) {
    const Eigen::Vector2d a = chain.col(k), b = chain.col(k + 1);
    // Bounding-box pre-filter: the distance to the box bounds the distance to the segment from below.
    const double dr = std::max({std::min(a(0), b(0)) - x(0), x(0) - std::max(a(0), b(0)), 0.0});
    const double dz = std::max({std::min(a(1), b(1)) - x(1), x(1) - std::max(a(1), b(1)), 0.0});
    if (dr * dr + dz * dz > best2) continue;
    const Eigen::Vector2d ab = b - a;
    const double l2 = ab.squaredNorm();
    if (!(l2 > 0)) throw std::domain_error("contact: master segment of zero length");
    const double xi = (x - a).dot(ab) / l2;
    // The clamped closest point is exactly a node when clamped, so that a node
    // shared by two segments gives the same distance (bit for bit) to both.
    const double d2 = xi <= 0 ? (x - a).squaredNorm() : xi >= 1 ? (x - b).squaredNorm() : (x - a - xi * ab).squaredNorm();
    if (d2 < best2) {
      best2 = d2;
      k_best = k;
      xi_best = xi;
    }
  }

  ChainProjection p;
  if (k_best < 0) return p;
  const Eigen::Vector2d a = chain.col(k_best), b = chain.col(k_best + 1);
  // Within the end tolerance beyond the first or last node: still that end segment.
  const bool near_start = k_best == 0 && xi_best < 0 && xi_best >= -end_tolerance;
  const bool near_end = k_best == m - 2 && xi_best > 1 && xi_best <= 1 + end_tolerance;
  if ((xi_best >= 0 && xi_best <= 1) || near_start || near_end) {
    p.feature = ChainFeature::segment;
    p.segment = k_best;
    p.xi = xi_best;
    p.signed_distance = (x - a).dot(segment_normal(a, b));
    p.distance = std::abs(p.signed_distance);
    return p;
  }
  const int v = xi_best < 0 ? k_best : k_best + 1;
  if (v == 0 || v == m - 1) return p;  // beyond an end of the chain: no side, no contact
  const Eigen::Vector2d xv = chain.col(v);
  const Eigen::Vector2d na = segment_normal(chain.col(v - 1), xv), nb = segment_normal(xv, chain.col(v + 1));
  const Eigen::Vector2d bis = na + nb;
  const Eigen::Vector2d rel = x - xv;
  // Side of the corner: along the bisecting normal; for a hairpin (n_a = −n_b), the line of segment v−1.
  const double side_test = bis.squaredNorm() > 1e-24 ? rel.dot(bis) : rel.dot(na);
  p.feature = ChainFeature::vertex;
  p.segment = v - 1;
  p.vertex = v;
  p.xi = (x - chain.col(v - 1)).dot(xv - chain.col(v - 1)) / (xv - chain.col(v - 1)).squaredNorm();
  p.distance = rel.norm();
  p.signed_distance = side_test < 0 ? -p.distance : p.distance;
  return p;
}

std::vector<ChainProjection> search_chain(const Eigen::Ref<const Eigen::Matrix2Xd>& slaves,
                                          const Eigen::Ref<const Eigen::Matrix2Xd>& chain, double search_radius) {
  std::vector<ChainProjection> out;
  out.reserve(slaves.cols());
  for (Eigen::Index i = 0; i < slaves.cols(); ++i) out.push_back(project_on_chain(slaves.col(i), chain, search_radius));
  return out;
}

}  // namespace tunica
