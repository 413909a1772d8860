// The inverse 2-node axisymmetric membrane (axisym_membrane_inverse.hpp; theory manual (13.7)).
// Derivatives along the reference coordinate X_k (node a = k / 2, component c = k % 2; δ· the
// derivative along X_k), at each Gauss point (N₀, N₁) = (1 − ξ, ξ):
//   ΔX = X₂ − X₁: δΔX = ±e_c,  L² = |ΔX|²: δL² = 2 ΔX·δΔX,  δL = δL²/(2L),
//   E_s = ½(ℓ²/L² − 1): δE_s = −½ ℓ² δL²/L⁴,   B_s = (−Δx, Δx)/L²: δB_s = −B_s δL²/L²,
//   R = N₀R₁ + N₁R₂: δR = N_a [c = 0],   E_θ = ½(r²/R² − 1): δE_θ = −r² δR/R³,
//   B_θ = (r/R²) N_r: δB_θ = −2 (δR/R) B_θ,   δS = D (δE_θ, δE_s, 0),
//   w = ½ L H 2πR: δw = w (δL/L + δR/R),
//   f = w (S_θ B_θ + S_s B_s): δf = δw (S_θ B_θ + S_s B_s) + w (δS_θ B_θ + S_θ δB_θ + δS_s B_s + S_s δB_s).
// With an imaged thickness h_q (13.12): H_q = h_q λ_s λ_θ = h_q (ℓ/L)(r/R), so w = ½ L H_q 2πR = π ℓ h_q r
// is a function of the imaged nodes alone and δw = 0 (13.13): the δH_q = −H_q (δL/L + δR/R) of the
// area stretch cancels δ(dA₀) exactly.
#include "elements/axisym_membrane_inverse.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace tunica {

void axisym_membrane_inverse(const AxisymNodes& X, const AxisymNodes& x, double H, const MembraneMaterial& material,
                             Eigen::Vector4d& f, Eigen::Matrix4d* KX, const std::array<double, 2>* imaged,
                             std::array<MembranePoint, 2>* points) {
  const Eigen::Vector2d dX = X.col(1) - X.col(0);
  const double L2 = dX.squaredNorm();
  if (!(L2 > 0)) throw std::domain_error("axisymmetric membrane: reference element of zero length");
  const double g = 0.5 / std::sqrt(3.0);
  const double xi[2] = {0.5 - g, 0.5 + g};
  for (double t : xi)
    if (!((1.0 - t) * X(0, 0) + t * X(0, 1) > 0))
      throw std::domain_error("axisymmetric membrane: reference radius not positive at a Gauss point");
  const double L = std::sqrt(L2);
  const Eigen::Vector2d dx = x.col(1) - x.col(0);
  const double l2 = dx.squaredNorm();
  // The reference thickness per Gauss point: H, or h_q λ_s λ_θ from an imaged thickness h_q (13.12).
  std::array<double, 2> Hq{H, H};
  if (imaged)
    for (int q = 0; q < 2; ++q)
      Hq[q] = (*imaged)[q] * (std::sqrt(l2) / L) * (((1.0 - xi[q]) * x(0, 0) + xi[q] * x(0, 1)) /
                                         ((1.0 - xi[q]) * X(0, 0) + xi[q] * X(0, 1)));
  // The residual: the forward element at (X, x).
  axisym_membrane(X, x, Hq, material, f, nullptr, points);
  if (!KX) return;
  KX->setZero();
  const double Es = 0.5 * (l2 / L2 - 1.0);
  Eigen::Vector4d Bs;
  Bs << -dx, dx;
  Bs /= L2;
  for (int q = 0; q < 2; ++q) {
    const double Nq[2] = {1.0 - xi[q], xi[q]};
    const double R = Nq[0] * X(0, 0) + Nq[1] * X(0, 1);
    const double r = Nq[0] * x(0, 0) + Nq[1] * x(0, 1);
    const double Et = 0.5 * (r * r / (R * R) - 1.0);
    const Eigen::Vector4d Nr(Nq[0], 0.0, Nq[1], 0.0);
    const Eigen::Vector4d Bt = (r / (R * R)) * Nr;
    const MembraneResponse m = membrane_response(material, Eigen::Vector3d(2.0 * Et + 1.0, 2.0 * Es + 1.0, 0.0));
    const double w = 0.5 * L * Hq[q] * 2.0 * std::numbers::pi * R;
    const Eigen::Vector4d fq = m.S(0) * Bt + m.S(1) * Bs;
    for (int k = 0; k < 4; ++k) {
      const int a = k / 2, c = k % 2;
      const double dL2 = 2.0 * dX(c) * (a == 1 ? 1.0 : -1.0);
      const double dL = dL2 / (2.0 * L);
      const double dEs = -0.5 * l2 * dL2 / (L2 * L2);
      const Eigen::Vector4d dBs = -Bs * (dL2 / L2);
      const double dR = c == 0 ? Nq[a] : 0.0;
      const double dEt = -r * r * dR / (R * R * R);
      const Eigen::Vector4d dBt = -2.0 * (dR / R) * Bt;
      const Eigen::Vector3d dS = m.D * Eigen::Vector3d(dEt, dEs, 0.0);
      const double dw = imaged ? 0.0 : w * (dL / L + dR / R);  // (13.7), (13.13)
      KX->col(k) += dw * fq + w * (dS(0) * Bt + m.S(0) * dBt + dS(1) * Bs + m.S(1) * dBs);
    }
  }
}

}  // namespace tunica
