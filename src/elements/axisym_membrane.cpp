#include "elements/axisym_membrane.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "elements/collapse.hpp"

namespace tunica {

void axisym_membrane(const AxisymNodes& X, const AxisymNodes& x, double H, const MembraneMaterial& material,
                     Eigen::Vector4d& f, Eigen::Matrix4d* K, std::array<MembranePoint, 2>* points) {
  axisym_membrane(X, x, std::array<double, 2>{H, H}, material, f, K, points);
}

void axisym_membrane(const AxisymNodes& X, const AxisymNodes& x, const std::array<double, 2>& Hq,
                     const MembraneMaterial& material, Eigen::Vector4d& f, Eigen::Matrix4d* K,
                     std::array<MembranePoint, 2>* points) {
  axisym_membrane(X, x, Hq, AxisymPrestretch{Eigen::Vector2d::Ones(), Eigen::Vector2d::Ones()}, material, f, K,
                  points);
}

void axisym_membrane(const AxisymNodes& X, const AxisymNodes& x, const std::array<double, 2>& Hq,
                     const AxisymPrestretch& prestretch, const MembraneMaterial& material, Eigen::Vector4d& f,
                     Eigen::Matrix4d* K, std::array<MembranePoint, 2>* points) {
  const Eigen::Vector2d dX = X.col(1) - X.col(0);
  const Eigen::Vector2d dx = x.col(1) - x.col(0);
  const double L2 = dX.squaredNorm();
  const double L = std::sqrt(L2);
  const double l2 = dx.squaredNorm();
  if (!(l2 > 0)) throw std::domain_error("axisymmetric membrane: element collapsed to a point");


  f.setZero();
  if (K) K->setZero();
  const double g = 0.5 / std::sqrt(3.0);
  const double xi[2] = {0.5 - g, 0.5 + g};
  for (int q = 0; q < 2; ++q) {
    const double H = Hq[q];
    const double N0 = 1.0 - xi[q], N1 = xi[q];
    const double R = N0 * X(0, 0) + N1 * X(0, 1);
    // The stress-free radius and meridian length at the point: R̃ = R/P_θ, L̃ = L/P_s ((13.23); 1 without
    // a prestress step).
    const double Pt = prestretch[q](0), Ps = prestretch[q](1);
    const double Rf = R / Pt, Lf = L / Ps, Lf2 = Lf * Lf;
    // Meridional strain (theory manual (5.2)): E_s = ½(ℓ²/L̃² − 1), ∂E_s/∂u = (−Δx, Δx)/L̃²,
    // ∂²E_s/∂u² = [[I, −I], [−I, I]]/L̃².
    const double Es = 0.5 * (l2 / Lf2 - 1.0);
    Eigen::Vector4d Bs;
    Bs << -dx, dx;
    Bs /= Lf2;
    const double r = N0 * x(0, 0) + N1 * x(0, 1);
    if (!(r > 0)) throw std::domain_error("axisymmetric membrane: radius not positive at a Gauss point");
    if (!(r * std::sqrt(l2) > kCollapsedAreaStretch * Rf * Lf))  // λθ λs = (r/R̃)(ℓ/L̃)
      throw std::domain_error(collapse_message("axisymmetric membrane: at a Gauss point"));
    // Hoop strain (theory manual (5.3)): E_θ = ½(r²/R̃² − 1), ∂E_θ/∂u = r N_r / R̃², ∂²E_θ/∂u² = N_r N_rᵀ / R̃².
    const double Et = 0.5 * (r * r / (Rf * Rf) - 1.0);
    const Eigen::Vector4d Nr(N0, 0.0, N1, 0.0);
    const Eigen::Vector4d Bt = (r / (Rf * Rf)) * Nr;

    const MembraneResponse m = membrane_response(material, Eigen::Vector3d(2.0 * Et + 1.0, 2.0 * Es + 1.0, 0.0));
    const double w = 0.5 * Lf * H * 2.0 * std::numbers::pi * Rf;  // Gauss weight × dV₀
    f += w * (m.S(0) * Bt + m.S(1) * Bs);
    if (K) {
      *K += w * (m.D(0, 0) * Bt * Bt.transpose() + m.D(0, 1) * Bt * Bs.transpose() +
                 m.D(1, 0) * Bs * Bt.transpose() + m.D(1, 1) * Bs * Bs.transpose());
      *K += w * (m.S(0) / (Rf * Rf)) * Nr * Nr.transpose();
      Eigen::Matrix4d Gs;
      Gs << Eigen::Matrix2d::Identity(), -Eigen::Matrix2d::Identity(), -Eigen::Matrix2d::Identity(),
          Eigen::Matrix2d::Identity();
      *K += w * (m.S(1) / Lf2) * Gs;
    }
    if (points) {
      MembranePoint& p = (*points)[q];
      p.R = R;
      p.r = r;
      p.z = N0 * x(1, 0) + N1 * x(1, 1);
      p.X = Eigen::Vector3d(R, N0 * X(1, 0) + N1 * X(1, 1), 0.0);
      p.x = Eigen::Vector3d(r, p.z, 0.0);
      p.lambda = Eigen::Vector3d(r / Rf, std::sqrt(l2) / Lf, std::sqrt(m.C33));
      p.E = Eigen::Vector3d(Et, Es, 0.0);
      p.S = Eigen::Vector3d(m.S(0), m.S(1), 0.0);
      p.sigma = Eigen::Vector2d(p.lambda(0) * p.lambda(0) * m.S(0), p.lambda(1) * p.lambda(1) * m.S(1));
      p.sigma_principal = Eigen::Vector2d(p.sigma.maxCoeff(), p.sigma.minCoeff());
      // Global axes of the meridian plane θ = 0: x = r, y = hoop, z = z.
      const Eigen::Vector3d t(dx(0) / std::sqrt(l2), 0.0, dx(1) / std::sqrt(l2));
      p.e1 = Eigen::Vector3d::UnitY();
      p.e2 = Eigen::Vector3d(dX(0) / L, 0.0, dX(1) / L);
      p.cauchy = p.sigma(0) * p.e1 * p.e1.transpose() + p.sigma(1) * t * t.transpose();
      p.thickness = p.lambda(2) * H;
      p.reference_thickness = H;
      p.W = m.W;
      p.weight = w;
    }
  }
}

}  // namespace tunica
