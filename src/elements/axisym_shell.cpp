// Axisymmetric Kirchhoff–Love shell element (axisym_shell.hpp). Per meridian
// Gauss point ξ_g:
//   y = B u,  y = (r, r_ξ, z_ξ, r_ξξ, z_ξξ),  u = nodal unknowns (8),
// B from the Hermite functions and their ξ-derivatives; the reference Y = B U.
// In the 5 local unknowns, as jets (value, gradient, Hessian):
//   a = √(r_ξ² + z_ξ²),  κ = r_ξ z_ξξ − r_ξξ z_ξ  (k_s = κ/a³),  n_r = z_ξ/a,
//   v(η) = ∫₀^η a (1 + t k_s)(r + t n_r) dt = c₁η + c₂η² + c₃η³,
//   c₁ = a r,  c₂ = ½(r κ/a² + z_ξ),  c₃ = κ z_ξ/(3a³),
// the reference V(ζ) = C₁ζ + C₂ζ² + C₃ζ³ likewise; per thickness point ζ_k:
//   η: v(η) = V(ζ_k)  (layer_distance below),
//   ℓ = a + η κ/a²  (= |∂x_ζ/∂ξ|),  ρ = r + η n_r  (= r_ζ),
//   C₁₁ = ρ² / R_ζ²,  C₂₂ = ℓ² / A_ζ²,
//   R_ζ = R + ζ Z_ξ/A,  A_ζ = A + ζ K/A²  (K = R_ξ Z_ξξ − R_ξξ Z_ξ).
// With dV = w_g w_k (H/2) 2π R_ζ A_ζ and Ŵ_α = ∂Ŵ/∂C_αα = S_α/2,
// Ŵ_αβ = ∂²Ŵ/∂C_αα∂C_ββ = D_αβ/4 (dS = D dE, dC = 2 dE):
//   Π += dV Ŵ,
//   ∂Π/∂y += dV Σ_α Ŵ_α ∇C_αα,
//   ∂²Π/∂y² += dV [Σ_α Ŵ_α ∇²C_αα + Σ_αβ Ŵ_αβ ∇C_αα ∇C_ββᵀ],
// then f += Bᵀ ∂Π/∂y and K += Bᵀ ∂²Π/∂y² B.
#include "elements/axisym_shell.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "core/jet.hpp"
#include "elements/gauss_legendre.hpp"

namespace tunica {

namespace {

using J5 = Jet<5>;
using Local = Eigen::Matrix<double, 5, 1>;
using LocalB = Eigen::Matrix<double, 5, 8>;

/// y = B u at ξ for the Hermite interpolation with tangent length L (elements/hermite_meridian.hpp).
LocalB local_map(double xi, double L) {
  const HermiteBasis hb = hermite_basis(xi, L);
  LocalB B = LocalB::Zero();
  for (int j = 0; j < 4; ++j) {
    B(0, hermite_index(j, 0)) = hb.h[j];
    B(1, hermite_index(j, 0)) = hb.dh[j];
    B(2, hermite_index(j, 1)) = hb.dh[j];
    B(3, hermite_index(j, 0)) = hb.d2h[j];
    B(4, hermite_index(j, 1)) = hb.d2h[j];
  }
  return B;
}

/// y = B u, evaluated relative to node 1's position: the derivative rows of B annihilate a
/// common shift of both nodes' positions (Σ of h′, h″ over the position functions is 0), and
/// row 0 (r) gets it back through Σ h = 1. Same values, but x_ξ and x_ξξ do not come from
/// differences of absolute coordinates, which on elements much shorter than their distance
/// from the axis (e.g. 0.011 mm at r ≈ 0.4 mm) would lose up to r ρ/L² × ε of x_ξξ ~ L²/ρ
/// to cancellation (≈ 1e4 ε there) and put a floor under the Newton residual.
Local local_values(const LocalB& B, const ShellVector& u) {
  ShellVector v = u;
  for (int a = 0; a < 2; ++a) {
    v(4 * a) -= u(0);
    v(4 * a + 1) -= u(1);
  }
  Local y = B * v;
  y(0) += u(0);
  return y;
}

/// The current distance η of a layer from the mid-surface: the root of
///   G(η; y) = c₁η + c₂η² + c₃η³ − V = 0
/// (V, the reference volume, a number) on the branch through η = 0 with G_η > 0,
/// by Newton's method from η = V/c₁; its gradient and Hessian in y by implicit
/// differentiation of G(η(y); y) = 0:
///   η_y  = −G_y / G_η,
///   η_yy = −(G_yy + G_ηy η_yᵀ + η_y G_ηyᵀ + G_ηη η_y η_yᵀ) / G_η.
J5 layer_distance(const J5& c1, const J5& c2, const J5& c3, double V) {
  J5 eta;
  if (V == 0) return eta;  // the mid-surface: η = 0 for every y
  double e = V / c1.v;
  for (int it = 0;; ++it) {
    const double G = ((c3.v * e + c2.v) * e + c1.v) * e - V;
    const double dG = (3.0 * c3.v * e + 2.0 * c2.v) * e + c1.v;
    if (!(dG > 0) || it == 50)
      throw std::domain_error("axisymmetric shell: no layer position (shell folded through its thickness)");
    const double de = G / dG;
    e -= de;
    if (std::abs(de) <= 1e-15 * std::abs(e)) break;
  }
  const double e2 = e * e, e3 = e2 * e;
  const double Ge = c1.v + 2.0 * e * c2.v + 3.0 * e2 * c3.v, Gee = 2.0 * c2.v + 6.0 * e * c3.v;
  if (!(Ge > 0)) throw std::domain_error("axisymmetric shell: no layer position (shell folded through its thickness)");
  const J5::Vec Gy = e * c1.g + e2 * c2.g + e3 * c3.g;
  const J5::Mat Gyy = e * c1.h + e2 * c2.h + e3 * c3.h;
  const J5::Vec Gey = c1.g + 2.0 * e * c2.g + 3.0 * e2 * c3.g;
  eta.v = e;
  eta.g = -Gy / Ge;
  const J5::Mat t = Gey * eta.g.transpose();
  eta.h = -(Gyy + t + t.transpose() + Gee * eta.g * eta.g.transpose()) / Ge;
  return eta;
}

}  // namespace

double hermite_length(const ShellNodes& X) {
  const Eigen::Vector2d chord = X.block<2, 1>(0, 1) - X.block<2, 1>(0, 0);
  const double c = chord.norm();
  if (!(c > 0)) throw std::invalid_argument("axisymmetric shell: reference element has zero length");
  for (int a = 0; a < 2; ++a)
    if (!(std::abs(X.block<2, 1>(2, a).norm() - 1.0) < 1e-8))
      throw std::invalid_argument("axisymmetric shell: reference slopes must be unit tangents");
  const double cos_beta = 0.5 * (X.block<2, 1>(2, 0) + X.block<2, 1>(2, 1)).dot(chord) / c;
  if (!(cos_beta > 0))
    throw std::invalid_argument("axisymmetric shell: reference slopes point against the element");
  return 2.0 * c / (1.0 + cos_beta);
}

double axisym_shell(const ShellNodes& X, const ShellNodes& x, double H, const MembraneMaterial& material,
                    ShellVector& f, ShellMatrix* K, const ShellQuadrature& quadrature,
                    std::vector<ShellPoint>* points) {
  if (!(H > 0)) throw std::invalid_argument("axisymmetric shell: thickness must be positive");
  if (quadrature.meridian < 1 || quadrature.meridian > 16 || quadrature.thickness < 1 || quadrature.thickness > 16)
    throw std::invalid_argument("axisymmetric shell: quadrature points must be in 1..16");
  const double L = hermite_length(X);

  const Eigen::Map<const ShellVector> U(X.data()), u(x.data());
  const GaussRule gm = gauss_legendre(quadrature.meridian), gt = gauss_legendre(quadrature.thickness);
  const double two_pi = 2.0 * std::numbers::pi;

  f.setZero();
  if (K) K->setZero();
  if (points) points->assign(gm.t.size(), ShellPoint{});
  double energy = 0;

  for (std::size_t g = 0; g < gm.t.size(); ++g) {
    const double xi = 0.5 * (1.0 + gm.t[g]), wg = 0.5 * gm.w[g];
    const LocalB B = local_map(xi, L);
    const Local Y = local_values(B, U), y = local_values(B, u);

    // Reference mid-surface and its layers' geometry.
    const double R = Y(0), A = std::hypot(Y(1), Y(2)), kappa_ref = Y(1) * Y(4) - Y(3) * Y(2);
    if (!(R > 0) || !(A > 0))
      throw std::domain_error("axisymmetric shell: reference radius or meridian length not positive at a Gauss point");

    // Current mid-surface, in the local unknowns y.
    if (!(y(0) > 0)) throw std::domain_error("axisymmetric shell: radius not positive at a Gauss point");
    const J5 r = J5::variable(y(0), 0), rp = J5::variable(y(1), 1), zp = J5::variable(y(2), 2),
             rpp = J5::variable(y(3), 3), zpp = J5::variable(y(4), 4);
    const J5 a2 = square(rp) + square(zp);
    if (!(a2.v > 0)) throw std::domain_error("axisymmetric shell: meridian collapsed to a point at a Gauss point");
    const J5 a = sqrt(a2);
    const J5 kappa = rp * zpp - rpp * zp;
    const J5 inv_a2 = inverse(a2);
    const J5 ks_a = kappa * inv_a2;    // a k_s = κ/a²
    const J5 nr = zp * inverse(a);     // n_r
    // Current volume between mid-surface and the layer at distance η, per dξ dθ (/2π):
    //   v(η) = ∫₀^η a (1 + t k_s)(r + t n_r) dt = c₁η + c₂η² + c₃η³.
    const J5 c1 = a * r, c2 = 0.5 * (ks_a * r + zp), c3 = (1.0 / 3.0) * (ks_a * nr);
    // The same for the reference (plain numbers).
    const double C1 = A * R, C2 = 0.5 * (kappa_ref * R / (A * A) + Y(2)), C3 = kappa_ref * Y(2) / (3.0 * A * A * A);

    Jet<5>::Vec grad = Jet<5>::Vec::Zero();
    Jet<5>::Mat hess = Jet<5>::Mat::Zero();
    double Wa = 0;
    ShellPoint* pt = points ? &(*points)[g] : nullptr;
    if (pt) {
      pt->zeta.resize(gt.t.size());
      pt->eta.resize(gt.t.size());
      pt->sigma.resize(2, static_cast<Eigen::Index>(gt.t.size()));
      pt->stretch.resize(2, static_cast<Eigen::Index>(gt.t.size()));
      pt->weight_zeta.resize(gt.t.size());
    }
    for (std::size_t k = 0; k < gt.t.size(); ++k) {
      const double zeta = 0.5 * H * gt.t[k], wz = 0.5 * H * gt.w[k];
      const double Rz = R + zeta * Y(2) / A, Az = A + zeta * kappa_ref / (A * A);
      if (!(Rz > 0) || !(Az > 0))
        throw std::domain_error("axisymmetric shell: reference layer degenerate (thickness beyond a radius of curvature)");
      const J5 eta = layer_distance(c1, c2, c3, ((C3 * zeta + C2) * zeta + C1) * zeta);
      const J5 ell = a + eta * ks_a, rho = r + eta * nr;  // a (1 + η k_s),  r + η n_r
      if (!(ell.v > 0) || !(rho.v > 0))
        throw std::domain_error("axisymmetric shell: layer stretch not positive (shell folded through its thickness)");
      const J5 C11 = (1.0 / (Rz * Rz)) * square(rho), C22 = (1.0 / (Az * Az)) * square(ell);
      const MembraneResponse m = membrane_response(material, Eigen::Vector3d(C11.v, C22.v, 0.0));
      const double dV = wg * wz * two_pi * Rz * Az;
      energy += dV * m.W;
      Wa += wz * m.W * Rz * Az / (R * A);
      grad += dV * (0.5 * m.S(0) * C11.g + 0.5 * m.S(1) * C22.g);
      if (K)
        hess += dV * (0.5 * m.S(0) * C11.h + 0.5 * m.S(1) * C22.h +
                      0.25 * (m.D(0, 0) * C11.g * C11.g.transpose() + m.D(1, 1) * C22.g * C22.g.transpose() +
                              m.D(0, 1) * C11.g * C22.g.transpose() + m.D(1, 0) * C22.g * C11.g.transpose()));
      if (pt) {
        pt->zeta[k] = zeta;
        pt->eta[k] = eta.v;
        pt->sigma.col(static_cast<Eigen::Index>(k)) = Eigen::Vector2d(C11.v * m.S(0), C22.v * m.S(1));
        pt->stretch.col(static_cast<Eigen::Index>(k)) = Eigen::Vector2d(std::sqrt(C11.v), std::sqrt(C22.v));
        pt->weight_zeta[k] = wz;
      }
    }
    f += B.transpose() * grad;
    if (K) *K += B.transpose() * hess * B;

    if (pt) {
      double Zg = 0, zg = 0;
      for (int j = 0; j < 8; j += 2) {  // row 0 of B: the Hermite values at the r unknowns; z uses the same
        Zg += B(0, j) * U(j + 1);
        zg += B(0, j) * u(j + 1);
      }
      pt->R = R;
      pt->Z = Zg;
      pt->r = y(0);
      pt->z = zg;
      pt->lambda = Eigen::Vector3d(y(0) / R, a.v / A, A * R / (a.v * y(0)));
      pt->K = Eigen::Vector2d(Y(2) / (A * R), kappa_ref / (A * A * A));
      pt->k = Eigen::Vector2d(y(2) / (a.v * y(0)), kappa.v / (a2.v * a.v));
      pt->t = Eigen::Vector2d(y(1), y(2)) / a.v;
      pt->T = Eigen::Vector2d(Y(1), Y(2)) / A;
      pt->W = Wa;
      pt->weight = wg * two_pi * R * A;
    }
  }
  if (K) *K = 0.5 * (*K + K->transpose());  // symmetric by construction; remove rounding asymmetry
  return energy;
}

}  // namespace tunica
