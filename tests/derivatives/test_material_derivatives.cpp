// Finite-difference checks of every built-in material (theory manual §2.1, §3, §8):
//  - the material's own derivatives of W(C11, C22, C12, C33);
//  - the plane-stress incompressible reduction: S against the reduced energy
//    Ŵ(C) = W(C, 1/det C), and the tangent D against S,
// at random admissible, sheared states (C12 ≠ 0), relative error below 1e-6.
#include <gtest/gtest.h>

#include <random>

#include "../support/fd.hpp"
#include "../support/material_from_yaml.hpp"
#include "io/deck.hpp"
#include "materials/fung.hpp"
#include "materials/membrane_material.hpp"

using namespace tunica;
using tunica::test::fd_gradient;
using tunica::test::fd_jacobian;
using tunica::test::material_from_yaml;
using tunica::test::relative_error;

namespace {


const std::vector<std::pair<std::string, std::string>> kMaterials = {
    {"fung 2-D (paper)", "{type: fung, c: 0.061163, a1: 0.68238, a2: 0.60558, a4: 0.1067}"},
    {"fung 3-D + shear", "{type: fung, c: 0.05, a1: 1.1, a2: 0.7, a3: 0.9, a4: 0.2, a5: 0.15, a6: -0.1, a7: 0.8}"},
    {"neo_hookean", "{type: neo_hookean, mu: 0.3}"},
    {"mooney_rivlin", "{type: mooney_rivlin, b1: 0.2, b2: 0.05}"},
};

/// Random in-plane C = FᵀF with stretches in [0.7, 1.5] and shear.
Eigen::Vector3d random_C(std::mt19937& rng) {
  std::uniform_real_distribution<double> s(0.7, 1.5), g(-0.3, 0.3);
  Eigen::Matrix2d F;
  F << s(rng), g(rng), g(rng), s(rng);
  const Eigen::Matrix2d C = F.transpose() * F;
  return Eigen::Vector3d(C(0, 0), C(1, 1), C(0, 1));
}

}  // namespace

TEST(MaterialDerivatives, EnergyGradientAndHessianMatchFiniteDifferences) {
  std::mt19937 rng(1);
  for (const auto& [label, yaml] : kMaterials) {
    const auto m = material_from_yaml(yaml);
    for (int k = 0; k < 20; ++k) {
      const Eigen::Vector3d C = random_C(rng);
      const Eigen::Vector4d v(C(0), C(1), C(2), 1.0 / (C(0) * C(1) - C(2) * C(2)));
      const EnergyDerivatives e = m->energy(v);
      const auto W = [&](const Eigen::VectorXd& x) { return m->energy(x).W; };
      const auto dW = [&](const Eigen::VectorXd& x) -> Eigen::VectorXd { return m->energy(x).dW; };
      EXPECT_LT(relative_error(e.dW, fd_gradient(W, v, 1e-6), 1e-8), 1e-6) << label;
      EXPECT_LT(relative_error(e.d2W, fd_jacobian(dW, v, 1e-6), 1e-8), 1e-6) << label;
    }
  }
}

TEST(MaterialDerivatives, StressIsTheDerivativeOfTheReducedEnergyAndTangentOfStress) {
  std::mt19937 rng(2);
  for (const auto& [label, yaml] : kMaterials) {
    const auto m = material_from_yaml(yaml);
    for (int k = 0; k < 20; ++k) {
      const Eigen::Vector3d C = random_C(rng);
      const MembraneResponse r = membrane_response(*m, C);
      // Ŵ as a function of x = (C11, C22, C12): S = (2 ∂Ŵ/∂x1, 2 ∂Ŵ/∂x2, ∂Ŵ/∂x3).
      const auto What = [&](const Eigen::VectorXd& x) { return membrane_response(*m, x).W; };
      const Eigen::VectorXd g = fd_gradient(What, C, 1e-6);
      EXPECT_LT(relative_error(r.S, Eigen::Vector3d(2 * g(0), 2 * g(1), g(2)), 1e-8), 1e-6) << label;
      // D = dS/dE with dE = (dC11/2, dC22/2, dC12) (engineering shear 2 dE12 = dC12).
      const auto S = [&](const Eigen::VectorXd& x) -> Eigen::VectorXd { return membrane_response(*m, x).S; };
      Eigen::MatrixXd J = fd_jacobian(S, C, 1e-6);
      J.col(0) *= 2.0;
      J.col(1) *= 2.0;
      EXPECT_LT(relative_error(r.D, J, 1e-8), 1e-6) << label;
      EXPECT_LT(relative_error(r.D, r.D.transpose(), 1e-8), 1e-12) << label << ": tangent must be symmetric";
    }
  }
}

TEST(MaterialDerivatives, FungTwoDimensionalApproachMatchesThePaperClosedForms) {
  // Theory manual (3.2): S1 = 2c(a1E1 + a4E2)e^Q, D11 = 2c[a1 + 2(a1E1 + a4E2)²]e^Q, ...
  const double c = 0.061163, a1 = 0.68238, a2 = 0.60558, a4 = 0.1067;
  const auto m = material_from_yaml("{type: fung, c: 0.061163, a1: 0.68238, a2: 0.60558, a4: 0.1067}");
  for (double l1 : {0.87, 1.0, 1.3, 1.69})
    for (double l2 : {1.0, 1.6}) {
      const double E1 = 0.5 * (l1 * l1 - 1), E2 = 0.5 * (l2 * l2 - 1);
      const double eQ = std::exp(a1 * E1 * E1 + a2 * E2 * E2 + 2 * a4 * E1 * E2);
      const double s1 = a1 * E1 + a4 * E2, s2 = a4 * E1 + a2 * E2;
      const MembraneResponse r = membrane_response(*m, Eigen::Vector3d(l1 * l1, l2 * l2, 0));
      EXPECT_NEAR(r.S(0), 2 * c * s1 * eQ, 1e-13);
      EXPECT_NEAR(r.S(1), 2 * c * s2 * eQ, 1e-13);
      EXPECT_NEAR(r.D(0, 0), 2 * c * (a1 + 2 * s1 * s1) * eQ, 1e-12);
      EXPECT_NEAR(r.D(1, 1), 2 * c * (a2 + 2 * s2 * s2) * eQ, 1e-12);
      EXPECT_NEAR(r.D(0, 1), 2 * c * (a4 + 2 * s1 * s2) * eQ, 1e-12);
      EXPECT_NEAR(r.C33, 1.0 / (l1 * l1 * l2 * l2), 1e-15);
    }
}

TEST(MaterialDerivatives, NeoHookeanEquibiaxialStressMatchesClosedForm) {
  // S_α = μ(1 − λ3²/λα²) with λ3 = 1/λ² (equibiaxial): σ = μ(λ² − λ⁻⁴) (theory manual (8.3), the balloon).
  const auto m = material_from_yaml("{type: neo_hookean, mu: 0.3}");
  for (double l : {0.9, 1.2, 1.383, 2.0}) {
    const MembraneResponse r = membrane_response(*m, Eigen::Vector3d(l * l, l * l, 0));
    EXPECT_NEAR(l * l * r.S(0), 0.3 * (l * l - std::pow(l, -4)), 1e-14);
    EXPECT_NEAR(r.S(0), r.S(1), 1e-15);
  }
}

TEST(MaterialDerivatives, FungConvexityCheck) {
  Eigen::Matrix3d A;
  A << 0.68238, 0.1067, 0, 0.1067, 0.60558, 0, 0, 0, 0;
  EXPECT_TRUE(FungMaterial::is_convex(A, 0));
  A(0, 1) = A(1, 0) = 0.7;
  EXPECT_FALSE(FungMaterial::is_convex(A, 0));
  A << 1, 0.2, 0.1, 0.2, 1, 0.1, 0.1, 0.1, -0.5;
  EXPECT_FALSE(FungMaterial::is_convex(A, 0));
  A(2, 2) = 0.5;
  EXPECT_TRUE(FungMaterial::is_convex(A, 0.1));
  EXPECT_FALSE(FungMaterial::is_convex(A, -0.1));
}
