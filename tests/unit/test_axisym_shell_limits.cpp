// Limits and closed forms of the axisymmetric Kirchhoff–Love shell element
// (elements/axisym_shell.hpp):
//  - meridian_tangents() is exact on lines and arcs, and the Hermite reference
//    meridian through them reproduces a sphere's curvatures;
//  - membrane limit: a stretched, pressurized tube gives the membrane element's
//    nodal forces, and a uniformly inflated sphere the closed-form membrane
//    pressure p = 2μ(H/R)(λ⁻¹ − λ⁻⁷) (theory manual (8.3)), both with a difference
//    O((H/R)²): below a bound, and falling fourfold when H halves;
//  - bending: cylindrical bending of a thin annular plate far from the axis to a
//    uniform curvature κ (meridian bent into a circular arc, no mid-surface strain):
//    Π(κ) + Π(−κ) − 2Π(0) = D κ² × area with the plate stiffness
//    D = E H³/(12(1 − ν²)) = μH³/3 (incompressible neo-Hookean, E = 3μ, ν = ½);
//    and at a finite meridional prestretch λ, Rivlin's exact incompressible
//    bending, D = (H³/12) λ² 𝒟₂₂(λ) (neo-Hookean: μH³/(3λ⁴); Fung from its tangent).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>

#include "../support/material_from_yaml.hpp"
#include "elements/axisym_membrane.hpp"
#include "elements/axisym_shell.hpp"
#include "mesh/meridian.hpp"
#include "mesh/meridian_tangents.hpp"

using namespace tunica;
using tunica::test::material_from_yaml;

namespace {

constexpr double kPi = std::numbers::pi;

/// A shell meridian: node positions and slopes (reference: unit tangents).
struct ShellMeridian {
  Meridian x;
  std::vector<Eigen::Vector2d> d;
};

ShellNodes element(const ShellMeridian& m, int e) {
  ShellNodes n;
  for (int a = 0; a < 2; ++a) {
    n.block<2, 1>(0, a) = m.x[e + a];
    n.block<2, 1>(2, a) = m.d[e + a];
  }
  return n;
}

/// Energy and assembled force; unknowns node-major (r, z, r′, z′).
double assemble(const ShellMeridian& X, const ShellMeridian& x, double H, const MembraneMaterial& mat,
                Eigen::VectorXd& F, const ShellQuadrature& q = {}) {
  const int n = static_cast<int>(X.x.size()) - 1;
  F = Eigen::VectorXd::Zero(4 * (n + 1));
  double energy = 0;
  for (int e = 0; e < n; ++e) {
    ShellVector f;
    energy += axisym_shell(element(X, e), element(x, e), H, mat, f, nullptr, q);
    F.segment<8>(4 * e) += f;
  }
  return energy;
}

Eigen::VectorXd membrane_forces(const Meridian& X, const Meridian& x, double H, const MembraneMaterial& mat) {
  const int n = static_cast<int>(X.size()) - 1;
  Eigen::VectorXd F = Eigen::VectorXd::Zero(2 * (n + 1));
  for (int e = 0; e < n; ++e) {
    AxisymNodes Xe, xe;
    Xe << X[e], X[e + 1];
    xe << x[e], x[e + 1];
    Eigen::Vector4d f;
    axisym_membrane(Xe, xe, H, mat, f, nullptr);
    F.segment<4>(2 * e) += f;
  }
  return F;
}

/// The (u_r, u_z) part of a shell force vector.
Eigen::VectorXd positions(const Eigen::VectorXd& F) {
  Eigen::VectorXd p(F.size() / 2);
  for (int i = 0; i < F.size() / 4; ++i) p.segment<2>(2 * i) = F.segment<2>(4 * i);
  return p;
}

}  // namespace

TEST(AxisymShellLimits, MeridianTangentsAreExactOnLinesAndArcs) {
  const Meridian line = line_meridian({1.0, 0.0}, {1.6, 0.8}, 5);
  for (const auto& t : meridian_tangents(line)) EXPECT_LT((t - Eigen::Vector2d(0.6, 0.8)).norm(), 1e-14);
  const double phi0 = -1.2, phi1 = 1.4;
  const Meridian arc = arc_meridian({0.3, 0.1}, 0.7, phi0, phi1, 7);
  const auto T = meridian_tangents(arc);
  for (int i = 0; i <= 7; ++i) {
    const double phi = phi0 + (phi1 - phi0) * i / 7.0;
    EXPECT_LT((T[i] - Eigen::Vector2d(-std::sin(phi), std::cos(phi))).norm(), 1e-13) << i;
  }
  // The Hermite reference meridian on an 8-element half circle: both curvatures 1/ρ.
  const double rho = 1.3;
  ShellMeridian S{arc_meridian({0, 0}, rho, -kPi / 2, kPi / 2, 8), {}};
  S.d = meridian_tangents(S.x);
  const auto mat = material_from_yaml("{type: neo_hookean, mu: 1}");
  double worst = 0;
  for (int e = 0; e < 8; ++e) {
    ShellVector f;
    std::vector<ShellPoint> pts;
    axisym_shell(element(S, e), element(S, e), 0.01, *mat, f, nullptr, {4, 1}, &pts);
    for (const auto& p : pts) {
      worst = std::max({worst, std::abs(p.K(0) * rho - 1), std::abs(p.K(1) * rho - 1),
                        std::abs(std::hypot(p.R, p.Z) / rho - 1)});
    }
  }
  std::cout << "[ Hermite half circle, 8 elements ] worst relative error of curvatures and radius " << worst << "\n";
  EXPECT_LT(worst, 1e-3);
}

TEST(AxisymShellLimits, StretchedTubeGivesTheMembraneForcesToOrderHOverRSquared) {
  const auto mat = material_from_yaml("{type: fung, c: 0.061163, a1: 0.68238, a2: 0.60558, a4: 0.1067}");
  const double R = 0.763, lt = 1.3, lz = 1.6;
  const int n = 6;
  const Meridian X = line_meridian({R, 0.0}, {R, 0.8}, n);
  Meridian x = X;
  for (auto& p : x) p = Eigen::Vector2d(lt * p(0), lz * p(1));
  ShellMeridian SX{X, meridian_tangents(X)}, Sx{x, {}};
  for (const auto& t : SX.d) Sx.d.push_back(Eigen::Vector2d(lt * t(0), lz * t(1)));
  double err[2];
  const double ratios[2] = {0.02, 0.01};
  for (int k = 0; k < 2; ++k) {
    const double H = ratios[k] * R;
    Eigen::VectorXd F;
    assemble(SX, Sx, H, *mat, F);
    const Eigen::VectorXd Fm = membrane_forces(X, x, H, *mat);
    err[k] = (positions(F) - Fm).norm() / Fm.norm();
    std::cout << "[ tube λθ=1.3 λz=1.6, H/R=" << ratios[k] << " ] |f_shell − f_membrane|/|f_membrane| = " << err[k]
              << "\n";
    EXPECT_LT(err[k], 2.0 * ratios[k] * ratios[k]);
  }
  EXPECT_GT(err[0] / err[1], 3.5);
  EXPECT_LT(err[0] / err[1], 4.5);
}

TEST(AxisymShellLimits, InflatedSphereGivesTheMembranePressureToOrderHOverRSquared) {
  const double mu = 0.3, rho = 1.0;
  const auto mat = material_from_yaml("{type: neo_hookean, mu: 0.3}");
  const int n = 16;
  ShellMeridian SX{arc_meridian({0, 0}, rho, -kPi / 2, kPi / 2, n), {}};
  SX.d = meridian_tangents(SX.x);
  // dx/dλ of the uniform inflation x = λX, x′ = λX′.
  Eigen::VectorXd v(4 * (n + 1));
  for (int i = 0; i <= n; ++i) v.segment<4>(4 * i) << SX.x[i], SX.d[i];
  for (double lambda : {1.2, 1.6}) {
    ShellMeridian Sx = SX;
    for (auto& p : Sx.x) p *= lambda;
    for (auto& d : Sx.d) d *= lambda;
    double err[2];
    const double ratios[2] = {0.02, 0.01};
    for (int k = 0; k < 2; ++k) {
      const double H = ratios[k] * rho;
      Eigen::VectorXd F;
      assemble(SX, Sx, H, *mat, F);
      // Virtual work: dΠ/dλ = p dV/dλ, V = (4/3)π ρ³ λ³.
      const double p = F.dot(v) / (4.0 * kPi * rho * rho * rho * lambda * lambda);
      const double p_exact = 2.0 * mu * (H / rho) * (1.0 / lambda - std::pow(lambda, -7));
      err[k] = std::abs(p / p_exact - 1.0);
      std::cout << "[ sphere λ=" << lambda << ", H/R=" << ratios[k] << " ] |p_shell/p_membrane − 1| = " << err[k]
                << "\n";
      EXPECT_LT(err[k], 2.0 * ratios[k] * ratios[k]);
    }
    EXPECT_GT(err[0] / err[1], 3.5);
    EXPECT_LT(err[0] / err[1], 4.5);
  }
}

namespace {

/// Bending energy of an annular plate R ∈ [R0, R0 + w] (meridian along +r), stretched
/// meridionally by λ and bent about its middle to a uniform meridional curvature ±κ;
/// returns Π(κ) + Π(−κ) − 2Π(0) (the part even in κ; ≈ D κ² × area). Bending moves
/// the meridian radially by −κ²(s − s_c)³/6 about its middle s_c: the hoop prestress
/// (λ ≠ 1) works on that hoop strain to first order, but it is odd about the middle
/// and cancels up to O(w/R0); the hoop-curvature terms are odd in κ and cancel.
double plate_bending_energy(const MembraneMaterial& mat, double R0, double w, double H, double lambda, double kappa,
                            int n) {
  ShellMeridian SX{line_meridian({R0, 0.0}, {R0 + w, 0.0}, n), {}};
  SX.d = meridian_tangents(SX.x);
  const auto bent = [&](double k) {
    ShellMeridian S = SX;
    for (int i = 0; i <= n; ++i) {
      const double s = lambda * w * (i - 0.5 * n) / n;  // current arc length from the middle
      if (k == 0) {
        S.x[i] = Eigen::Vector2d(R0 + 0.5 * lambda * w + s, 0.0);
        S.d[i] = Eigen::Vector2d(lambda, 0.0);
      } else {
        S.x[i] = Eigen::Vector2d(R0 + 0.5 * lambda * w + std::sin(k * s) / k, (1.0 - std::cos(k * s)) / k);
        // Slope length of the best cubic on an arc of angle α per element: 4ρ tan(α/4) = L |x′|,
        // L = w/n the reference Hermite length (≈ λ, exact as α → 0).
        const double alpha = k * lambda * w / n;
        S.d[i] = 4.0 * std::tan(alpha / 4.0) / (k * w / n) * Eigen::Vector2d(std::cos(k * s), std::sin(k * s));
      }
    }
    Eigen::VectorXd F;
    return assemble(SX, S, H, mat, F);
  };
  return bent(kappa) + bent(-kappa) - 2.0 * bent(0.0);
}

}  // namespace

TEST(AxisymShellLimits, SmallStrainBendingStiffnessIsThePlateStiffness) {
  const double mu = 0.3, R0 = 1e3, w = 0.1, H = 0.01, kappa = 0.5;
  const auto mat = material_from_yaml("{type: neo_hookean, mu: 0.3}");
  const double area = kPi * ((R0 + w) * (R0 + w) - R0 * R0);
  const double D = mu * H * H * H / 3.0;  // E H³/(12(1 − ν²)), E = 3μ, ν = ½
  const double e2 = plate_bending_energy(*mat, R0, w, H, 1.0, kappa, 8);
  const double err = std::abs(e2 / (D * kappa * kappa * area) - 1.0);
  std::cout << "[ plate bending, small strain ] |Π_bend/(½Dκ²A) − 1| = " << err << "\n";
  EXPECT_LT(err, 1e-4);
}

TEST(AxisymShellLimits, FiniteStrainBendingMatchesRivlinsIncompressibleBending) {
  const double R0 = 1e3, w = 0.1, H = 0.01, kappa = 0.5;
  const double area = kPi * ((R0 + w) * (R0 + w) - R0 * R0);
  const char* kMats[] = {"{type: neo_hookean, mu: 0.3}",
                         "{type: fung, c: 0.061163, a1: 0.68238, a2: 0.60558, a4: 0.1067}"};
  for (const char* yaml : kMats) {
    const auto mat = material_from_yaml(yaml);
    for (double lambda : {1.3, 1.6}) {
      // Plane strain in the hoop direction (λ_θ = 1): D = (H³/12) λ² 𝒟₂₂ per reference area.
      const MembraneResponse m = membrane_response(*mat, Eigen::Vector3d(1.0, lambda * lambda, 0.0));
      const double D = H * H * H / 12.0 * lambda * lambda * m.D(1, 1);
      if (std::string(yaml).find("neo") != std::string::npos) {
        EXPECT_NEAR(D, 0.3 * H * H * H / (3.0 * std::pow(lambda, 4)), 1e-12 * D);
      }
      const double e2 = plate_bending_energy(*mat, R0, w, H, lambda, kappa, 8);
      const double err = std::abs(e2 / (D * kappa * kappa * area) - 1.0);
      std::cout << "[ plate bending at λ=" << lambda << ", " << yaml << " ] |Π_bend/(½Dκ²A) − 1| = " << err << "\n";
      EXPECT_LT(err, 1e-3) << yaml << " λ=" << lambda;
    }
  }
}
