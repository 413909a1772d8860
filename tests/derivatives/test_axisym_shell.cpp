// Finite-difference and consistency checks of the axisymmetric Kirchhoff–Love
// shell element (elements/axisym_shell.hpp):
//  - the internal force is the gradient of the element energy (11.3), and the tangent
//    the Jacobian of the force (central differences, relative error < 1e-7), at
//    random curved reference elements in stretched (0.8–1.6), bent, rotated states, for
//    every registered material and each of its samples (tests/support/material_registry.hpp),
//    with 1 to 7 thickness points; the tangent is symmetric;
//  - zero energy and force in the reference state; a translation along the axis
//    changes neither energy nor force, and the force does no work on it (every material);
//  - Σ W·weight over the output points is the element energy;
//  - std::domain_error for a non-positive radius, a collapsed meridian, a layer
//    folded through the thickness; std::invalid_argument for bad reference data.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "../support/fd.hpp"
#include "../support/material_registry.hpp"
#include "elements/axisym_shell.hpp"

using namespace tunica;
using tunica::test::fd_gradient;
using tunica::test::fd_jacobian;
using tunica::test::MaterialCase;
using tunica::test::material_from_yaml;
using tunica::test::relative_error;

namespace {

// The paper's Fung law, for the output check below.
const char* kRatAorta = "{type: fung, c: 0.061163, a1: 0.68238, a2: 0.60558, a4: 0.1067}";

Eigen::Matrix2d rotation(double t) {
  Eigen::Matrix2d Q;
  Q << std::cos(t), -std::sin(t), std::sin(t), std::cos(t);
  return Q;
}

ShellNodes unflat(const Eigen::VectorXd& v) { return Eigen::Map<const ShellNodes>(v.data()); }
Eigen::VectorXd flat(const ShellNodes& x) { return Eigen::Map<const Eigen::VectorXd>(x.data(), 8); }

/// Random curved reference element (any direction in the (r, z) plane, end slopes
/// turned ±0.4 rad from the chord) and a current state: stretched differently in r
/// and z, rotated by up to ±0.6 rad about the element centre (a finite rotation of
/// the meridian), slopes stretched, turned and perturbed (bending).
void random_state(std::mt19937& rng, ShellNodes& X, ShellNodes& x) {
  std::uniform_real_distribution<double> u(0, 1), s(-1, 1);
  const double dir = 6.283 * u(rng), len = 0.3 + 0.3 * u(rng);
  const Eigen::Vector2d X1(0.8 + u(rng), s(rng)), e(std::cos(dir), std::sin(dir));
  X.block<2, 1>(0, 0) = X1;
  X.block<2, 1>(0, 1) = X1 + len * e;
  X.block<2, 1>(2, 0) = rotation(0.4 * s(rng)) * e;
  X.block<2, 1>(2, 1) = rotation(0.4 * s(rng)) * e;
  const Eigen::Matrix2d F = rotation(0.6 * s(rng)) * Eigen::Vector2d(0.8 + 0.8 * u(rng), 0.8 + 0.8 * u(rng)).asDiagonal();
  const Eigen::Vector2d centre = 0.5 * (X.block<2, 1>(0, 0) + X.block<2, 1>(0, 1));
  for (int a = 0; a < 2; ++a) {
    x.block<2, 1>(0, a) = centre + F * (X.block<2, 1>(0, a) - centre) + 0.03 * Eigen::Vector2d(s(rng), s(rng));
    x.block<2, 1>(2, a) = rotation(0.2 * s(rng)) * F * X.block<2, 1>(2, a) + 0.05 * Eigen::Vector2d(s(rng), s(rng));
  }
  x(0, 0) += 0.3;  // keep away from the axis after the rotation
  x(0, 1) += 0.3;
}

/// The element over every registered material × sample; the frame is the element's (1 = hoop).
class AxisymShellFd : public ::testing::TestWithParam<MaterialCase> {
protected:
  void SetUp() override { m = tunica::test::make_membrane(GetParam()); }
  std::unique_ptr<MembraneMaterial> m;
};

INSTANTIATE_TEST_SUITE_P(Registry, AxisymShellFd, ::testing::ValuesIn(tunica::test::membrane_cases()),
                         tunica::test::case_name);

}  // namespace

TEST_P(AxisymShellFd, InternalForceIsTheGradientOfTheEnergy) {
  std::mt19937 rng(11);
  double worst = 0;
  for (int k = 0; k < 8; ++k) {
    ShellNodes X, x;
    random_state(rng, X, x);
    const double H = 0.06;
    const ShellQuadrature q{3, 1 + 2 * (k % 4)};
    ShellVector f;
    axisym_shell(X, x, H, *m, f, nullptr, q);
    const auto energy = [&](const Eigen::VectorXd& v) {
      ShellVector g;
      return axisym_shell(X, unflat(v), H, *m, g, nullptr, q);
    };
    const double err = relative_error(f, fd_gradient(energy, flat(x), 1e-6));
    worst = std::max(worst, err);
    EXPECT_LT(err, tunica::test::kFdTolerance) << "state " << k;
  }
  tunica::test::record_error("worst_relative_error", worst);
}

TEST_P(AxisymShellFd, TangentIsTheJacobianOfTheForceAndSymmetric) {
  std::mt19937 rng(12);
  double worst = 0;
  for (int k = 0; k < 8; ++k) {
    ShellNodes X, x;
    random_state(rng, X, x);
    const double H = 0.06;
    const ShellQuadrature q{2 + k % 3, 5};
    const auto force = [&](const Eigen::VectorXd& v) -> Eigen::VectorXd {
      ShellVector g;
      axisym_shell(X, unflat(v), H, *m, g, nullptr, q);
      return g;
    };
    ShellVector f;
    ShellMatrix K;
    axisym_shell(X, x, H, *m, f, &K, q);
    const double err = relative_error(K, fd_jacobian(force, flat(x), 1e-6));
    worst = std::max(worst, err);
    EXPECT_LT(err, tunica::test::kFdTolerance) << "state " << k;
    EXPECT_LT((K - K.transpose()).norm(), 1e-14 * K.norm());
  }
  tunica::test::record_error("worst_relative_error", worst);
}

TEST_P(AxisymShellFd, ReferenceStateIsStressFreeAndAxialTranslationIsFree) {
  std::mt19937 rng(13);
  ShellNodes X, x;
  random_state(rng, X, x);
  ShellVector f;
  ShellMatrix K;
  // Energy and force scales of the element: modulus × volume (H × area ~ 0.06 × 2π × 1 × 0.5).
  const double scale = tunica::test::sample_scale(*m) * 0.2;
  EXPECT_NEAR(axisym_shell(X, X, 0.06, *m, f, &K), 0.0, 1e-13 * scale);
  EXPECT_LT(f.norm(), 1e-13 * scale);
  // Rigid translation along z of the reference: still stress free.
  ShellNodes Xt = X;
  Xt.row(1).array() += 0.37;
  EXPECT_LT(std::abs(axisym_shell(X, Xt, 0.06, *m, f, nullptr)), 1e-13 * scale);
  EXPECT_LT(f.norm(), 1e-13 * scale);
  // A deformed state translated along z: same energy and force; f does no work on the translation.
  ShellVector f0, f1;
  const double e0 = axisym_shell(X, x, 0.06, *m, f0, nullptr);
  ShellNodes xt = x;
  xt.row(1).array() += -0.21;
  const double e1 = axisym_shell(X, xt, 0.06, *m, f1, nullptr);
  EXPECT_NEAR(e1, e0, 1e-14 * std::abs(e0));
  EXPECT_LT((f1 - f0).norm(), 1e-13 * f0.norm());
  EXPECT_LT(std::abs(f0(1) + f0(5)), 1e-13 * f0.norm());  // Σ f_z = ∂Π/∂(translation) = 0
  // The tangent annihilates the translation mode.
  ShellMatrix K0;
  axisym_shell(X, x, 0.06, *m, f0, &K0);
  ShellVector t = ShellVector::Zero();
  t(1) = t(5) = 1.0;
  EXPECT_LT((K0 * t).norm(), 1e-13 * K0.norm());
}

TEST(AxisymShell, OutputPointsSumToTheElementEnergy) {
  std::mt19937 rng(14);
  const auto m = material_from_yaml(kRatAorta);
  ShellNodes X, x;
  random_state(rng, X, x);
  ShellVector f;
  std::vector<ShellPoint> pts;
  const double e = axisym_shell(X, x, 0.06, *m, f, nullptr, {4, 5}, &pts);
  ASSERT_EQ(pts.size(), 4u);
  double sum = 0;
  for (const ShellPoint& p : pts) {
    sum += p.W * p.weight;
    EXPECT_NEAR(p.lambda(2), 1.0 / (p.lambda(0) * p.lambda(1)), 1e-14);
    EXPECT_EQ(p.sigma.cols(), 5);
    EXPECT_NEAR(p.zeta.front(), -p.zeta.back(), 1e-15);
  }
  EXPECT_NEAR(sum, e, 1e-13 * std::abs(e));
}

TEST(AxisymShell, NonPositiveStretchesThrowDomainError) {
  const auto m = material_from_yaml("{type: neo_hookean, mu: 0.3}");
  ShellNodes X;
  X << 1.0, 1.0, 0.0, 1.0, 0.0, 0.0, 1.0, 1.0;  // straight tube segment along z at r = 1
  ShellVector f;
  ShellNodes x = X;
  x.row(0).array() = -0.5;  // through the axis
  EXPECT_THROW(axisym_shell(X, x, 0.05, *m, f, nullptr), std::domain_error);
  x = X;
  x.block<2, 1>(0, 1) = x.block<2, 1>(0, 0);
  x.block<2, 2>(2, 0).setZero();  // the element collapsed to a point
  EXPECT_THROW(axisym_shell(X, x, 0.05, *m, f, nullptr), std::domain_error);
  // Slopes turned by ±2.5 rad: the meridian kinks into a loop of curvature radius ≪ H.
  x = X;
  x.block<2, 1>(2, 0) = rotation(2.5) * X.block<2, 1>(2, 0);
  x.block<2, 1>(2, 1) = rotation(-2.5) * X.block<2, 1>(2, 1);
  EXPECT_THROW(axisym_shell(X, x, 0.5, *m, f, nullptr), std::domain_error);
  // Reference thicker than twice its radius of curvature.
  ShellNodes Xc;
  Xc << 1.0, 1.0, 0.0, 0.1, std::cos(1.2), -std::cos(1.2), std::sin(1.2), std::sin(1.2);
  EXPECT_THROW(axisym_shell(Xc, Xc, 0.5, *m, f, nullptr), std::domain_error);
}

TEST(AxisymShell, BadReferenceDataThrowsInvalidArgument) {
  const auto m = material_from_yaml("{type: neo_hookean, mu: 0.3}");
  ShellNodes X;
  X << 1.0, 1.0, 0.0, 1.0, 0.0, 0.0, 1.0, 1.0;
  ShellVector f;
  EXPECT_THROW(axisym_shell(X, X, 0.0, *m, f, nullptr), std::invalid_argument);
  EXPECT_THROW(axisym_shell(X, X, 0.1, *m, f, nullptr, {0, 5}), std::invalid_argument);
  EXPECT_THROW(axisym_shell(X, X, 0.1, *m, f, nullptr, {3, 17}), std::invalid_argument);
  ShellNodes Xs = X;
  Xs(3, 0) = 2.0;  // a non-unit reference slope
  EXPECT_THROW(axisym_shell(Xs, Xs, 0.1, *m, f, nullptr), std::invalid_argument);
  Xs = X;
  Xs.block<2, 2>(2, 0) *= -1.0;  // slopes against the node order
  EXPECT_THROW(axisym_shell(Xs, Xs, 0.1, *m, f, nullptr), std::invalid_argument);
}
