// Follower pressure and enclosed volume on the Hermite mid-surface of the
// axisymmetric shell (loads/axisym_shell_pressure.hpp):
//  - the load stiffness ∂f/∂u and the volume gradient ∂V/∂u against central
//    differences (relative error < 1e-8) at random curved, stretched, rotated and
//    bent elements;
//  - f is linear in p and flips with it;
//  - a sphere meshed pole to pole with exact slopes (8 elements): the Hermite volume
//    is exact to 1e-5 where the nodal chords' is short by more than 1e-2; the
//    resultant pressure force on the upper half is p π ρ² (its projected area)
//    exactly, as on the chords (−2πp ∫ r r_ξ dξ telescopes);
//  - on a rigid-body motion along z the pressure does no work on a closed sphere.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "../support/fd.hpp"
#include "loads/axisym_shell_pressure.hpp"

using namespace tunica;
using tunica::test::fd_gradient;
using tunica::test::fd_jacobian;
using tunica::test::relative_error;

namespace {

ShellNodes unflat(const Eigen::VectorXd& v) { return Eigen::Map<const ShellNodes>(v.data()); }
Eigen::VectorXd flat(const ShellNodes& x) { return Eigen::Map<const Eigen::VectorXd>(x.data(), 8); }

Eigen::Vector2d turned(const Eigen::Vector2d& v, double t) {
  return Eigen::Vector2d(std::cos(t) * v(0) - std::sin(t) * v(1), std::sin(t) * v(0) + std::cos(t) * v(1));
}

void random_state(std::mt19937& rng, ShellNodes& X, ShellNodes& x) {
  std::uniform_real_distribution<double> u(0, 1), s(-1, 1);
  const double dir = 6.283 * u(rng), len = 0.3 + 0.3 * u(rng);
  const Eigen::Vector2d X1(0.8 + u(rng), s(rng)), e(std::cos(dir), std::sin(dir));
  X.block<2, 1>(0, 0) = X1;
  X.block<2, 1>(0, 1) = X1 + len * e;
  X.block<2, 1>(2, 0) = turned(e, 0.4 * s(rng));
  X.block<2, 1>(2, 1) = turned(e, 0.4 * s(rng));
  for (int a = 0; a < 2; ++a) {
    x.block<2, 1>(0, a) = turned(X.block<2, 1>(0, a), 0.1 * s(rng)) + 0.1 * Eigen::Vector2d(s(rng), s(rng));
    x.block<2, 1>(2, a) = (0.8 + 0.5 * u(rng)) * turned(X.block<2, 1>(2, a), 0.5 * s(rng));
  }
}

/// Element e of n of a circle of radius ρ centred on the axis at z = 0, from the lower pole.
ShellNodes sphere_element(int e, int n, double rho) {
  ShellNodes X;
  for (int a = 0; a < 2; ++a) {
    const double phi = -std::numbers::pi / 2 + std::numbers::pi * (e + a) / n;
    X.col(a) << rho * std::cos(phi), rho * std::sin(phi), -std::sin(phi), std::cos(phi);
  }
  return X;
}

}  // namespace

TEST(ShellPressure, LoadStiffnessMatchesFiniteDifferences) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 20; ++trial) {
    ShellNodes X, x;
    random_state(rng, X, x);
    const double p = 0.7;
    ShellVector f;
    ShellMatrix K;
    axisym_shell_pressure(X, x, p, f, &K);
    const auto force = [&](const Eigen::VectorXd& v) {
      ShellVector g;
      axisym_shell_pressure(X, unflat(v), p, g, nullptr);
      return Eigen::VectorXd(g);
    };
    EXPECT_LT(relative_error(K, fd_jacobian(force, flat(x), 1e-6)), 1e-8) << "trial " << trial;
    ShellVector fm;
    axisym_shell_pressure(X, x, -2 * p, fm, nullptr);
    EXPECT_LT((fm + 2 * f).norm(), 1e-13 * f.norm());
  }
}

TEST(ShellPressure, VolumeGradientMatchesFiniteDifferences) {
  std::mt19937 rng(12);
  for (int trial = 0; trial < 20; ++trial) {
    ShellNodes X, x;
    random_state(rng, X, x);
    ShellVector g;
    axisym_shell_volume(X, x, &g);
    const auto volume = [&](const Eigen::VectorXd& v) { return axisym_shell_volume(X, unflat(v), nullptr); };
    EXPECT_LT(relative_error(g, fd_gradient(volume, flat(x), 1e-6)), 1e-8) << "trial " << trial;
  }
}

TEST(ShellPressure, SphereVolumeAndPressureResultantFollowTheHermiteMidSurface) {
  const double rho = 0.35, p = 2.0;
  const int n = 8;
  double V = 0, Fz = 0, Fz_chord = 0;
  for (int e = 0; e < n; ++e) {
    const ShellNodes X = sphere_element(e, n, rho);
    V += axisym_shell_volume(X, X, nullptr);
    ShellVector f;
    axisym_shell_pressure(X, X, p, f, nullptr);
    // The z force on the upper half: the z components of its position unknowns (h₀₀ + h₀₁ = 1,
    // so their sum is −2πp ∫ r r_ξ dξ = −πp [r²] per element).
    if (e >= n / 2) Fz += f(1) + f(5);
    if (e >= n / 2) {  // the nodal chord's z force, 2π p ∫ r (−Δr) dξ, for comparison
      const double r1 = X(0, 0), r2 = X(0, 1);
      Fz_chord += -2 * std::numbers::pi * p * (r2 - r1) * 0.5 * (r1 + r2);
    }
  }
  const double V_exact = 4.0 / 3.0 * std::numbers::pi * rho * rho * rho, F_exact = p * std::numbers::pi * rho * rho;
  EXPECT_NEAR(V / V_exact, 1.0, 1e-5);
  EXPECT_NEAR(Fz / F_exact, 1.0, 1e-12);
  EXPECT_NEAR(Fz_chord / F_exact, 1.0, 1e-12);  // on the chords too: a projected area
  // The volume of the chords (a polygon of revolution) is short by O(h²).
  double V_chord = 0;
  for (int e = 0; e < n; ++e) {
    const ShellNodes X = sphere_element(e, n, rho);
    const double r1 = X(0, 0), r2 = X(0, 1);
    V_chord += std::numbers::pi * (X(1, 1) - X(1, 0)) * (r1 * r1 + r1 * r2 + r2 * r2) / 3.0;
  }
  EXPECT_GT(std::abs(V_chord / V_exact - 1.0), 1e-2);
}

TEST(ShellPressure, NoWorkOnAnAxialTranslationOfAClosedSphere) {
  const int n = 7;
  double work = 0, scale = 0;
  for (int e = 0; e < n; ++e) {
    const ShellNodes X = sphere_element(e, n, 0.5);
    ShellNodes x = X;
    x.row(0) *= 1.2;  // an ellipsoid
    ShellVector f;
    axisym_shell_pressure(X, x, 1.0, f, nullptr);
    work += f(1) + f(5);
    scale += f.norm();
  }
  EXPECT_LT(std::abs(work), 1e-13 * scale);
}
