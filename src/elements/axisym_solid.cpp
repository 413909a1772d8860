// Four-node axisymmetric solid, displacement (Q1) and mean-dilatation (Q1/P0) forms
// (theory manual §10, (10.1)–(10.5)).
//
// Kinematics at a Gauss point (ξ, η), shape functions N_a, nodes X_a = (R_a, Z_a):
//   ∂X/∂ξ = Σ_a X_a ⊗ ∂N_a/∂ξ,   G_a = ∂N_a/∂X = (∂X/∂ξ)^(−T) ∂N_a/∂ξ,
//   F_ij = Σ_a x_ia G_ja (i, j ∈ {r, z}),   F_θθ = r/R,   J = det F_2×2 · r/R,
//   C = FᵀF = [[C_rr, C_rz, 0], [C_rz, C_zz, 0], [0, 0, (r/R)²]],
//   dV = w_g 2πR det(∂X/∂ξ).
// Strain variation δE = B δx in the order (δE_rr, δE_zz, δE_θθ, 2δE_rz), node a:
//   δE_rr  = G_ra (F_rr δr_a + F_zr δz_a)
//   δE_zz  = G_za (F_rz δr_a + F_zz δz_a)
//   δE_θθ  = (r/R²) N_a δr_a
//   2δE_rz = (G_za F_rr + G_ra F_rz) δr_a + (G_za F_zr + G_ra F_zz) δz_a
// Second variation (geometric stiffness) for a stress S:
//   S : Δ δE = Σ_ab (G_aᵀ S_2×2 G_b)(δx_a·Δx_b) + S_θθ N_a N_b δr_a Δr_b / R².
// A Gauss point with stress S and tangent D = 2 ∂S/∂C adds
//   f += w Bᵀ S,   K += w (Bᵀ D B + K_geo(S)).
//
// Displacement form:  Π_e = Σ_g w [W_iso(C̄) + U(J)]:
//   S = S_iso + J U'(J) C⁻¹,  D = 𝒞_iso + J (U' + J U'') C⁻¹⊗C⁻¹ − 2 J U' C⁻¹⊙C⁻¹.
//
// Mean-dilatation form (Q1/P0). We follow Simo, Taylor & Pister, CMAME 51 (1985)
// 177–208, in the energy form of Bonet & Wood, Nonlinear Continuum Mechanics for
// Finite Element Analysis (2nd ed., 2008) §8.6 ("mean dilatation"). The three-field
// functional with an element-constant dilatation θ and pressure p,
//   Π(x, θ, p) = Σ_g w W_iso(C̄) + V U(θ) + p (v − θ V),
//   v = Σ_g w J = ∫ 2π r da (the current element volume, exact under 2×2 Gauss:
//       r det(∂x/∂ξ) is at most quadratic in each of ξ, η),   V = Σ_g w,
// is stationary in p at θ = v/V and in θ at p = U'(θ). Condensing both
// (statically, element by element) leaves the displacement-only energy
//   Π_e(x) = Σ_g w W_iso(C̄(C_g)) + V U(θ(x)),   θ = v/V.
// W_iso needs no modification: the modified gradient F̄ = (θ/J)^(1/3) F of
// Simo–Taylor–Pister has the same isochoric part C̄ as F. Derivatives:
//   ∂v/∂x = b,  b = Σ_g w Bᵀ (J C⁻¹)                      (dJ/dE = J C⁻¹),
//   ∂²v/∂x² = Σ_g w [Bᵀ D_J B + K_geo(J C⁻¹)],  D_J = J C⁻¹⊗C⁻¹ − 2 J C⁻¹⊙C⁻¹,
//   f = ∂Π_e/∂x = Σ_g w Bᵀ S_iso + U'(θ) b
//     = Σ_g w Bᵀ (S_iso + p J C⁻¹),                         p = U'(θ),
//   K = ∂²Π_e/∂x² = Σ_g w [Bᵀ (𝒞_iso + p D_J) B + K_geo(S_iso + p J C⁻¹)]
//       + (U''(θ)/V) b bᵀ.
// The last, rank-one term is the condensed pressure–dilatation coupling
// (Simo–Taylor–Pister's K_pθ K_θθ⁻¹ K_θp). The Cauchy stress at a point is
//   σ = J⁻¹ F S Fᵀ = J⁻¹ F S_iso Fᵀ + p I  (deviatoric part + element pressure).
#include "elements/axisym_solid.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace tunica {

namespace {

using Matrix48 = Eigen::Matrix<double, 4, 8>;
using Matrix24 = Eigen::Matrix<double, 2, 4>;

/// Everything one Gauss point needs, computed once.
struct Kinematics {
  Eigen::Vector4d N;
  Matrix24 G;           ///< ∂N_a/∂X (rows r, z)
  Eigen::Matrix3d F;    ///< in (r, z, θ)
  Eigen::Matrix3d C, Cinv;
  double R = 0, Z = 0, r = 0, z = 0, J = 0, w = 0;
  Matrix48 B;
};

Kinematics kinematics(const SolidNodes& X, const SolidNodes& x, double xi, double eta) {
  // Nodes at (ξ, η) = (−1,−1), (1,−1), (1,1), (−1,1): N_a = ¼(1 + ξ_a ξ)(1 + η_a η).
  static constexpr double xa[4] = {-1, 1, 1, -1}, ea[4] = {-1, -1, 1, 1};
  Kinematics k;
  Matrix24 dN;  // rows ∂/∂ξ, ∂/∂η
  for (int a = 0; a < 4; ++a) {
    k.N(a) = 0.25 * (1 + xa[a] * xi) * (1 + ea[a] * eta);
    dN(0, a) = 0.25 * xa[a] * (1 + ea[a] * eta);
    dN(1, a) = 0.25 * ea[a] * (1 + xa[a] * xi);
  }
  const Eigen::Matrix2d J0 = X * dN.transpose();  // J0(i, k) = ∂X_i/∂ξ_k
  const double det0 = J0.determinant();
  if (!(det0 > 0)) throw std::domain_error("axisymmetric solid: reference element inverted or degenerate");
  k.G = J0.inverse().transpose() * dN;
  k.R = X.row(0).dot(k.N);
  k.Z = X.row(1).dot(k.N);
  k.r = x.row(0).dot(k.N);
  k.z = x.row(1).dot(k.N);
  if (!(k.R > 0)) throw std::domain_error("axisymmetric solid: reference radius not positive at a Gauss point");
  if (!(k.r > 0)) throw std::domain_error("axisymmetric solid: radius not positive at a Gauss point");
  const Eigen::Matrix2d F2 = x * k.G.transpose();  // F(i, j) = Σ_a x_ia G_ja
  const double Ft = k.r / k.R;
  k.F.setZero();
  k.F.topLeftCorner<2, 2>() = F2;
  k.F(2, 2) = Ft;
  k.J = F2.determinant() * Ft;
  if (!(k.J > 0)) throw std::domain_error("axisymmetric solid: J not positive at a Gauss point");
  k.C = k.F.transpose() * k.F;
  k.Cinv.setZero();
  k.Cinv.topLeftCorner<2, 2>() = k.C.topLeftCorner<2, 2>().inverse();
  k.Cinv(2, 2) = 1.0 / k.C(2, 2);
  k.w = 2.0 * std::numbers::pi * k.R * det0;  // Gauss weights are 1 for 2×2
  for (int a = 0; a < 4; ++a) {
    const double Gr = k.G(0, a), Gz = k.G(1, a);
    k.B(0, 2 * a) = Gr * F2(0, 0);
    k.B(0, 2 * a + 1) = Gr * F2(1, 0);
    k.B(1, 2 * a) = Gz * F2(0, 1);
    k.B(1, 2 * a + 1) = Gz * F2(1, 1);
    k.B(2, 2 * a) = k.N(a) * k.r / (k.R * k.R);
    k.B(2, 2 * a + 1) = 0;
    k.B(3, 2 * a) = Gz * F2(0, 0) + Gr * F2(0, 1);
    k.B(3, 2 * a + 1) = Gz * F2(1, 0) + Gr * F2(1, 1);
  }
  return k;
}

/// f += w Bᵀ S, K += w (Bᵀ D B + K_geo(S)) with the axisymmetric (rr, zz, θθ, rz)
/// block of the Voigt stress S and tangent D.
void add_point(const Kinematics& k, const Voigt6& S, const Voigt66& D, SolidVector& f, SolidMatrix* K) {
  const Eigen::Vector4d s = S.head<4>();
  f += k.w * k.B.transpose() * s;
  if (!K) return;
  *K += k.w * k.B.transpose() * D.topLeftCorner<4, 4>() * k.B;
  Eigen::Matrix2d S2;
  S2 << s(0), s(3), s(3), s(1);
  const Eigen::Matrix4d GSG = k.G.transpose() * S2 * k.G;
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) {
      const double g = k.w * GSG(a, b);
      (*K)(2 * a, 2 * b) += g + k.w * s(2) * k.N(a) * k.N(b) / (k.R * k.R);
      (*K)(2 * a + 1, 2 * b + 1) += g;
    }
}

}  // namespace

double axisym_solid(const SolidNodes& X, const SolidNodes& x, const SolidMaterial& material,
                    SolidFormulation formulation, SolidVector& f, SolidMatrix* K,
                    std::array<SolidPoint, 4>* points) {
  constexpr double g = 0.57735026918962576451;  // 1/√3
  static constexpr double gxi[4] = {-g, g, g, -g}, geta[4] = {-g, -g, g, g};
  std::array<Kinematics, 4> kin;
  double V = 0, v = 0;
  for (int q = 0; q < 4; ++q) {
    kin[q] = kinematics(X, x, gxi[q], geta[q]);
    V += kin[q].w;
    v += kin[q].w * kin[q].J;
  }
  const bool mixed = formulation == SolidFormulation::mean_dilatation;
  // Mixed: element dilatation θ = v/V and pressure p = U'(θ), shared by all points.
  const double theta_e = v / V;
  if (mixed && !(theta_e > 0)) throw std::domain_error("axisymmetric solid: element volume not positive");
  const VolumetricResponse vol_e = mixed ? material.volumetric(theta_e) : VolumetricResponse{};

  f.setZero();
  if (K) K->setZero();
  SolidVector b = SolidVector::Zero();  // ∂v/∂x (mixed)
  double energy = 0;
  for (int q = 0; q < 4; ++q) {
    const Kinematics& k = kin[q];
    const IsochoricResponse iso = material.isochoric(k.C);
    Voigt6 S = iso.S;
    Voigt66 D = iso.D;
    double theta, p, U;
    if (mixed) {
      // S = S_iso + p J C⁻¹, D = 𝒞_iso + p D_J (p fixed: its variation is the rank-one term below).
      theta = theta_e;
      p = vol_e.dU;
      U = vol_e.U;
      add_volumetric_stress(k.Cinv, k.J, p, 0.0, S, D);
      b += k.w * k.J * k.B.transpose() * to_voigt(k.Cinv).head<4>();
    } else {
      // S = S_iso + J U'(J) C⁻¹, D = 𝒞_iso + 𝒞_vol(U'(J), U''(J)).
      const VolumetricResponse vol = material.volumetric(k.J);
      theta = k.J;
      p = vol.dU;
      U = vol.U;
      add_volumetric_stress(k.Cinv, k.J, p, vol.d2U, S, D);
    }
    add_point(k, S, D, f, K);
    energy += k.w * (iso.W + U);
    if (points) {
      SolidPoint& pt = (*points)[q];
      pt.R = k.R;
      pt.Z = k.Z;
      pt.r = k.r;
      pt.z = k.z;
      const Eigen::Matrix3d sigma = k.F * from_voigt(S) * k.F.transpose() / k.J;  // σ = J⁻¹ F S Fᵀ
      pt.sigma = Eigen::Vector4d(sigma(0, 0), sigma(1, 1), sigma(2, 2), sigma(0, 1));
      pt.p = p;
      pt.J = k.J;
      pt.theta = theta;
      pt.W = iso.W + U;
      pt.weight = k.w;
    }
  }
  // Condensed pressure–dilatation term: ∂²(V U(θ))/∂x² ⊃ V U''(θ) (b/V)(b/V)ᵀ.
  if (mixed && K) *K += (vol_e.d2U / V) * b * b.transpose();
  return energy;
}

}  // namespace tunica
