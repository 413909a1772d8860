#pragma once
// Definitions of the follower pressure and enclosed volume templates of 3-D membrane elements
// (surface_pressure.hpp; theory manual (6.4)–(6.6)). With g_α = Σ_a x_a ∂N_a/∂ξ^α and n = g1 × g2 (per unit
// parametric area), at each Gauss point (weight w):
//   pressure:  f_a = p Σ_q w N_a n,
//              ∂f_a/∂x_b = p Σ_q w N_a (∂N_b/∂η [g1]× − ∂N_b/∂ξ [g2]×) = p Σ_q w N_a [∂N_b/∂η g1 − ∂N_b/∂ξ g2]×,
//              from δn = δg1 × g2 + g1 × δg2, [v]× u = v × u;
//   volume:    V_e = c Σ_q w (P y)·n,  y = x − p₀,
//              c = ⅓, P = I (about a point) or c = ½, P = I − a aᵀ (about an axis),
//              ∂V_e/∂x_a = c Σ_q w [N_a P n + ∂N_a/∂ξ (g2 × P y) + ∂N_a/∂η (P y × g1)],
//              from δ(P y·n) = δy·P n + P y·(δg1 × g2 + g1 × δg2).
// The Gauss rules integrate these polynomials exactly (tri3: n constant,
// integrands linear; quad4: n linear in ξ and η, integrands of degree ≤ 2 in each).
//
// Included only by the files that instantiate them for a shape (surface_pressure.cpp: tri3 and
// quad4; a new shape: its own file); every other file includes surface_pressure.hpp.
#include "loads/surface_pressure.hpp"

namespace tunica {

namespace detail {

/// [v]×: the matrix of u ↦ v × u.
inline Eigen::Matrix3d cross_matrix(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0, -v.z(), v.y(),  //
      v.z(), 0, -v.x(),   //
      -v.y(), v.x(), 0;
  return m;
}

}  // namespace detail

template <int N>
double subtract_surface_pressure(const SurfaceNodes<N>& x, double p, ElementVector<N>& r, ElementMatrix<N>* K) {
  constexpr int Q = SurfaceShapeTraits<N>::kPoints;
  ElementVector<N> f = ElementVector<N>::Zero();
  for (int q = 0; q < Q; ++q) {
    double xi, eta, w;
    gauss_point<N>(q, xi, eta, w);
    const Eigen::Matrix<double, N, 1> Nq = shape_values<N>(xi, eta);
    const Eigen::Matrix<double, N, 2> dN = shape_derivatives<N>(xi, eta);
    const Eigen::Matrix<double, 3, 2> g = x * dN;
    const Eigen::Vector3d n = g.col(0).cross(g.col(1));
    for (int a = 0; a < N; ++a) f.template segment<3>(3 * a) += (p * w * Nq(a)) * n;  // (6.4)
    if (K) {
      // (6.5): ∂n/∂x_b = ∂N_b/∂η [g1]× − ∂N_b/∂ξ [g2]× = [v_b]×, v_b = ∂N_b/∂η g1 − ∂N_b/∂ξ g2, and
      // ∂f_a/∂x_b = p w N_a [v_b]×: a skew block, zero on its diagonal. Its six entries are
      // subtracted from K in place (entry (i, j) of [v]× is −ε_ijk v_k).
      for (int b = 0; b < N; ++b) {
        const Eigen::Vector3d v = dN(b, 1) * g.col(0) - dN(b, 0) * g.col(1);
        for (int a = 0; a < N; ++a) {
          const double c = p * w * Nq(a);
          auto Kab = K->template block<3, 3>(3 * a, 3 * b);
          Kab(0, 1) += c * v.z();
          Kab(1, 0) -= c * v.z();
          Kab(0, 2) -= c * v.y();
          Kab(2, 0) += c * v.y();
          Kab(1, 2) += c * v.x();
          Kab(2, 1) -= c * v.x();
        }
      }
    }
  }
  r -= f;
  return f.squaredNorm();
}

template <int N>
void surface_pressure(const SurfaceNodes<N>& x, double p, ElementVector<N>& f, ElementMatrix<N>* dfdx) {
  // f_p and ∂f_p/∂x alone: subtracting the load of −p from zero (f_p is linear in p; the negations
  // are exact, so the values are those of the in-place form to the last bit).
  f.setZero();
  if (dfdx) dfdx->setZero();
  subtract_surface_pressure<N>(x, -p, f, dfdx);
}

template <int N>
double enclosed_volume(const SurfaceNodes<N>& x, const VolumeMeasure& how, ElementVector<N>* grad) {
  constexpr int Q = SurfaceShapeTraits<N>::kPoints;
  const double c = how.about_axis ? 0.5 : 1.0 / 3.0;
  Eigen::Matrix3d P = Eigen::Matrix3d::Identity();
  if (how.about_axis) {
    const Eigen::Vector3d a = how.axis.normalized();
    P -= a * a.transpose();
  }
  double V = 0;
  if (grad) grad->setZero();
  for (int q = 0; q < Q; ++q) {
    double xi, eta, w;
    gauss_point<N>(q, xi, eta, w);
    const Eigen::Matrix<double, N, 1> Nq = shape_values<N>(xi, eta);
    const Eigen::Matrix<double, N, 2> dN = shape_derivatives<N>(xi, eta);
    const Eigen::Matrix<double, 3, 2> g = x * dN;
    const Eigen::Vector3d n = g.col(0).cross(g.col(1));
    const Eigen::Vector3d Py = P * (x * Nq - how.point);
    V += c * w * Py.dot(n);
    if (grad) {
      const Eigen::Vector3d Pn = P * n, g2Py = g.col(1).cross(Py), Pyg1 = Py.cross(g.col(0));
      for (int a = 0; a < N; ++a)
        grad->template segment<3>(3 * a) += (c * w) * (Nq(a) * Pn + dN(a, 0) * g2Py + dN(a, 1) * Pyg1);
    }
  }
  return V;
}

}  // namespace tunica
