// Node-to-segment and node-to-vertex penalty contact; formulas in the header.
//
// Derivation of the segment terms. With x_s − x_1 = ξ a + g n (n ⊥ a):
//   δt = n (n·δa)/ℓ,  δn = −t (n·δa)/ℓ  (n is t turned by a fixed angle),
//   δg = n·(δx_s − δx_1) + (x_s − x_1)·δn = n·(δx_s − δx_1) − ξ n·δa = N·δu,
//   δξ = [a·(δx_s − δx_1) + (x_s − x_1)·δa − 2ξ a·δa]/ℓ² = [t·(δx_s − δx_1 − ξ δa) + (g/ℓ) n·δa]/ℓ
//      = (T + (g/ℓ) D)·δu / ℓ,
//   Δδg = Δn·(δx_s − δx_1 − ξ δa) − Δξ n·δa = −(D·Δu)(T·δu)/ℓ − (D·δu)(T + (g/ℓ) D)·Δu/ℓ,
// which is the symmetric form in the header (the offset c is a constant).
#include "contact/axisym_contact.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace tunica {

namespace {

ContactPoint state(double gap, const ContactLaw& law, double area, double xi, const Eigen::Vector2d& normal) {
  ContactPoint p;
  p.gap = gap;
  p.xi = xi;
  p.normal = normal;
  p.active = law.touching(gap);
  if (p.active) {
    p.pressure = law.pressure(gap);
    p.energy = law.energy(gap) * area;
  }
  return p;
}

}  // namespace

ContactPoint node_to_segment(const Eigen::Vector2d& xs, const Eigen::Vector2d& x1, const Eigen::Vector2d& x2,
                             double area, const ContactLaw& law, ContactVector6& f, ContactMatrix6* K) {
  const Eigen::Vector2d a = x2 - x1;
  const double l = a.norm();
  if (!(l > 0)) throw std::domain_error("contact: master segment of zero length");
  const Eigen::Vector2d t = a / l, n(t(1), -t(0));
  const Eigen::Vector2d rel = xs - x1;
  const double xi = rel.dot(t) / l;
  const double g = rel.dot(n);
  const ContactPoint p = state(g - law.offset, law, area, xi, n);
  f.setZero();
  if (K) K->setZero();
  if (!p.active) return p;

  // f = −A_s p N, K = A_s [p′ N⊗N − p Δδg_N] (p′ = dp/d(−g_N); ε and ε g_N's negative unsmoothed).
  const double pA = p.pressure * area, kA = law.stiffness(p.gap) * area;
  ContactVector6 N, T, D;
  N << n, -(1 - xi) * n, -xi * n;
  T << t, -(1 - xi) * t, -xi * t;
  D << 0, 0, -n, n;
  f = -pA * N;
  if (K) {
    const ContactMatrix6 TD = T * D.transpose();
    *K = kA * N * N.transpose() + (pA / l) * (TD + TD.transpose()) + (pA * g / (l * l)) * D * D.transpose();
  }
  return p;
}

ContactPoint node_to_vertex(const Eigen::Vector2d& xs, const Eigen::Vector2d& xv, double side, double area,
                            const ContactLaw& law, Eigen::Vector4d& f, Eigen::Matrix4d* K) {
  const double sigma = side < 0 ? -1.0 : 1.0;
  const Eigen::Vector2d r = xs - xv;
  const double d = r.norm();
  f.setZero();
  if (K) K->setZero();
  const double gN = sigma * d - law.offset;
  if (!law.touching(gN)) return state(gN, law, area, 0, d > 0 ? Eigen::Vector2d(sigma * r / d) : Eigen::Vector2d::Zero());
  if (!(d > 0)) throw std::domain_error("contact: slave node on a master vertex (contact direction undefined)");
  const Eigen::Vector2d e = r / d;
  const ContactPoint p = state(gN, law, area, 0, sigma * e);

  const double pA = p.pressure * area, kA = law.stiffness(gN) * area;
  Eigen::Vector4d G;
  G << sigma * e, -sigma * e;
  f = -pA * G;
  if (K) {
    const Eigen::Matrix2d P = Eigen::Matrix2d::Identity() - e * e.transpose();
    Eigen::Matrix4d H;
    H << P, -P, -P, P;
    *K = kA * G * G.transpose() - (pA * sigma / d) * H;
  }
  return p;
}

ContactPoint chain_contact(const Eigen::Vector2d& xs, const Eigen::Ref<const Eigen::Matrix2Xd>& chain,
                           const ChainProjection& where, double area, const ContactLaw& law, ContactVector6& f,
                           ContactMatrix6* K) {
  f.setZero();
  if (K) K->setZero();
  const int k = where.segment;
  switch (where.feature) {
    case ChainFeature::none:
      return ContactPoint{};
    case ChainFeature::segment:
      return node_to_segment(xs, chain.col(k), chain.col(k + 1), area, law, f, K);
    case ChainFeature::vertex: {
      Eigen::Vector4d fv;
      Eigen::Matrix4d Kv;
      const double side = where.signed_distance < 0 ? -1.0 : 1.0;
      ContactPoint p = node_to_vertex(xs, chain.col(k + 1), side, area, law, fv, K ? &Kv : nullptr);
      p.xi = where.xi;
      // (slave, P_k, P_{k+1}) ← (slave, vertex): rows and columns 0–1 and 4–5.
      const int map[4] = {0, 1, 4, 5};
      for (int i = 0; i < 4; ++i) {
        f(map[i]) = fv(i);
        if (K)
          for (int j = 0; j < 4; ++j) (*K)(map[i], map[j]) = Kv(i, j);
      }
      return p;
    }
  }
  return ContactPoint{};
}

Eigen::VectorXd slave_tributary_areas(const Eigen::Ref<const Eigen::Matrix2Xd>& reference_chain) {
  const Eigen::Index m = reference_chain.cols();
  Eigen::VectorXd A = Eigen::VectorXd::Zero(m), cones = Eigen::VectorXd::Zero(m);
  for (Eigen::Index j = 0; j + 1 < m; ++j) {
    const double L = (reference_chain.col(j + 1) - reference_chain.col(j)).norm();
    A(j) += 0.5 * L;
    A(j + 1) += 0.5 * L;
    // A node on the axis (a pole): the consistent area ∫ N_s 2π r ds, 2π L (R_s/3 + R_other/6) per
    // element, the weight a pressure load gives it, so that a flat patch carries p_c = p there too
    // (the lumped 2π R_s L/2 is 0 there, and a pole would go through unresisted).
    const double Rj = reference_chain(0, j), Rk = reference_chain(0, j + 1);
    cones(j) += 2 * std::numbers::pi * L * (Rj / 3 + Rk / 6);
    cones(j + 1) += 2 * std::numbers::pi * L * (Rk / 3 + Rj / 6);
  }
  for (Eigen::Index i = 0; i < m; ++i)
    A(i) = reference_chain(0, i) > 0 ? A(i) * 2.0 * std::numbers::pi * reference_chain(0, i) : cones(i);
  return A;
}

}  // namespace tunica
