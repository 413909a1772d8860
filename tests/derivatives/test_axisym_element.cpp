// Finite-difference checks of the axisymmetric membrane element and the
// follower pressure (theory manual §5, §6, §8):
//  - the internal force (5.4) is the gradient of the stored energy Σ w Ŵ;
//  - the element tangent (5.4) (material + geometric) and the pressure load
//    stiffness (6.2) are the derivatives of the element residual R = f_int − f_p (6.3), with and
//    without a prestretch per Gauss point (13.23),
// at distorted states (hoop and meridional stretches 0.8–1.6, tilted, off-cylinder), for
// every registered material and each of its samples (tests/support/material_registry.hpp);
// the assembled tangent of a whole model against its assembled residual; and the pressure
// stiffness of a closed surface is symmetric (Schweizerhof & Ramm; theory manual §4).
#include <gtest/gtest.h>

#include <numbers>
#include <random>

#include "../support/fd.hpp"
#include "../support/material_registry.hpp"
#include "assembly/system.hpp"
#include "io/deck.hpp"
#include "loads/axisym_pressure.hpp"
#include "mesh/meridian.hpp"

using namespace tunica;
using tunica::test::fd_gradient;
using tunica::test::fd_jacobian;
using tunica::test::kFdTolerance;
using tunica::test::MaterialCase;
using tunica::test::relative_error;

namespace {

AxisymNodes nodes(const Eigen::VectorXd& v) {
  AxisymNodes x;
  x << v(0), v(2), v(1), v(3);
  return x;
}

Eigen::Vector4d flat(const AxisymNodes& x) { return Eigen::Vector4d(x(0, 0), x(1, 0), x(0, 1), x(1, 1)); }

/// Random reference element (any tilt, radius 0.8–1.8, length 0.3–0.7) and a current state with
/// hoop and meridional stretches in [0.8, 1.6], the meridian turned by up to ±0.5 rad and moved
/// along the axis, then nodes moved by up to ±0.02 (off-cylinder).
void random_state(std::mt19937& rng, AxisymNodes& X, AxisymNodes& x) {
  std::uniform_real_distribution<double> u(0, 1), s(-1, 1), stretch(0.8, 1.6);
  const double phi = 6.2832 * u(rng), L = 0.3 + 0.4 * u(rng);
  const Eigen::Vector2d X1(0.8 + u(rng), s(rng)), e(std::cos(phi), std::sin(phi));
  X.col(0) = X1;
  X.col(1) = X1 + L * e;
  const double hoop = stretch(rng), meridian = stretch(rng), turn = 0.5 * s(rng), dz = s(rng);
  const Eigen::Vector2d t(std::cos(turn) * e(0) - std::sin(turn) * e(1), std::sin(turn) * e(0) + std::cos(turn) * e(1));
  const Eigen::Vector2d mid(hoop * 0.5 * (X(0, 0) + X(0, 1)), 0.5 * (X(1, 0) + X(1, 1)) + dz);
  x.col(0) = mid - 0.5 * meridian * L * t;
  x.col(1) = mid + 0.5 * meridian * L * t;
  x += 0.02 * AxisymNodes::NullaryExpr([&] { return s(rng); });
}

/// No prestretch for even k; for odd k a prestretch (P_θ, P_s) in [0.7, 1.5] at each Gauss point (a
/// prestress step, theory manual (13.23)).
AxisymPrestretch prestretch_of(int k, std::mt19937& rng) {
  if (k % 2 == 0) return {Eigen::Vector2d::Ones(), Eigen::Vector2d::Ones()};
  std::uniform_real_distribution<double> stretch(0.7, 1.5);
  return {Eigen::Vector2d(stretch(rng), stretch(rng)), Eigen::Vector2d(stretch(rng), stretch(rng))};
}

/// The element over every registered material × sample; the frame is the element's (1 = hoop).
class AxisymMembraneFd : public ::testing::TestWithParam<MaterialCase> {
protected:
  void SetUp() override { m = tunica::test::make_membrane(GetParam()); }
  std::unique_ptr<MembraneMaterial> m;
};

INSTANTIATE_TEST_SUITE_P(Registry, AxisymMembraneFd, ::testing::ValuesIn(tunica::test::membrane_cases()),
                         tunica::test::case_name);

}  // namespace

TEST_P(AxisymMembraneFd, InternalForceIsTheGradientOfTheStoredEnergy) {
  std::mt19937 rng(3);
  double worst = 0;
  for (int k = 0; k < 8; ++k) {
    AxisymNodes X, x;
    random_state(rng, X, x);
    const std::array<double, 2> H{0.1, 0.1};
    const AxisymPrestretch P = prestretch_of(k, rng);
    Eigen::Vector4d f;
    axisym_membrane(X, x, H, P, *m, f, nullptr);
    const auto energy = [&](const Eigen::VectorXd& v) {
      Eigen::Vector4d g;
      std::array<MembranePoint, 2> pts;
      axisym_membrane(X, nodes(v), H, P, *m, g, nullptr, &pts);
      return pts[0].W * pts[0].weight + pts[1].W * pts[1].weight;
    };
    const double e = relative_error(f, fd_gradient(energy, flat(x), 1e-6));
    EXPECT_LT(e, kFdTolerance) << "state " << k;
    worst = std::max(worst, e);
  }
  tunica::test::record_error("worst_relative_error", worst);
}

TEST_P(AxisymMembraneFd, TangentWithPressureLoadStiffnessMatchesFiniteDifferences) {
  // The pressure kernel does not depend on the material; it is added so that the residual of a
  // loaded membrane, R = f_int − f_p, is checked whole.
  std::mt19937 rng(4);
  double worst = 0;
  for (double p : {0.0, 0.07, -0.035}) {  // × the material's modulus: 0.02 and −0.01 MPa at μ = 0.3 MPa
    for (int k = 0; k < 8; ++k) {
      AxisymNodes X, x;
      random_state(rng, X, x);
      const std::array<double, 2> H{0.1, 0.1};
      const AxisymPrestretch P = prestretch_of(k, rng);
      const double ps = p * tunica::test::sample_scale(*m);  // a pressure of the material's order
      const auto residual = [&](const Eigen::VectorXd& v) -> Eigen::VectorXd {
        Eigen::Vector4d f, fp;
        axisym_membrane(X, nodes(v), H, P, *m, f, nullptr);
        axisym_pressure(nodes(v), ps, fp, nullptr);
        return f - fp;
      };
      Eigen::Vector4d f, fp;
      Eigen::Matrix4d K, dfp;
      axisym_membrane(X, x, H, P, *m, f, &K);
      axisym_pressure(x, ps, fp, &dfp);
      const double e = relative_error(K - dfp, fd_jacobian(residual, flat(x), 1e-6));
      EXPECT_LT(e, kFdTolerance) << "state " << k << ", p = " << ps;
      worst = std::max(worst, e);
    }
  }
  tunica::test::record_error("worst_relative_error", worst);
}

TEST(AxisymElement, PressureLoadStiffnessIsNonsymmetricPerSegmentButSymmetricOnAClosedSurface) {
  // A closed sphere meridian from pole to pole; the pole nodes stay on the axis (r fixed).
  const int n = 12;
  const Meridian mer = arc_meridian({0, 0}, 1.3, -std::numbers::pi / 2, std::numbers::pi / 2, n);
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(2 * (n + 1), 2 * (n + 1));
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-0.05, 0.05);
  Meridian x = mer;
  for (int i = 1; i < n; ++i) x[i] += Eigen::Vector2d(u(rng), u(rng));  // a non-spherical closed surface
  double asym_segment = 0;
  for (int e = 0; e < n; ++e) {
    AxisymNodes xe;
    xe.col(0) = x[e];
    xe.col(1) = x[e + 1];
    Eigen::Vector4d f;
    Eigen::Matrix4d d;
    axisym_pressure(xe, 0.7, f, &d);
    asym_segment = std::max(asym_segment, (d - d.transpose()).norm() / d.norm());
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) K(2 * e + a, 2 * e + b) += d(a, b);
  }
  EXPECT_GT(asym_segment, 0.1);
  // Remove the r DOFs of the poles (prescribed r = 0).
  std::vector<int> keep;
  for (int i = 0; i < 2 * (n + 1); ++i)
    if (i != 0 && i != 2 * n) keep.push_back(i);
  Eigen::MatrixXd Kf(keep.size(), keep.size());
  for (std::size_t i = 0; i < keep.size(); ++i)
    for (std::size_t j = 0; j < keep.size(); ++j) Kf(i, j) = K(keep[i], keep[j]);
  EXPECT_LT((Kf - Kf.transpose()).norm() / Kf.norm(), 1e-14);
}

TEST(AxisymElement, PressureForceOnAClosedSurfaceIsPressureTimesVolumeGradient) {
  // Pappus: V = Σ_e π Δz (r1² + r1 r2 + r2²)/3; the virtual work of p is p δV.
  const int n = 9;
  Meridian x = arc_meridian({0, 0.2}, 0.8, -std::numbers::pi / 2, std::numbers::pi / 2, n);
  x[4] += Eigen::Vector2d(0.03, -0.02);
  const auto volume = [&](const Eigen::VectorXd& v) {
    double V = 0;
    for (int e = 0; e < n; ++e) {
      const double r1 = v(2 * e), r2 = v(2 * e + 2), dz = v(2 * e + 3) - v(2 * e + 1);
      V += std::numbers::pi * dz * (r1 * r1 + r1 * r2 + r2 * r2) / 3.0;
    }
    return V;
  };
  Eigen::VectorXd pos(2 * (n + 1)), F = Eigen::VectorXd::Zero(2 * (n + 1));
  for (int i = 0; i <= n; ++i) pos.segment<2>(2 * i) = x[i];
  for (int e = 0; e < n; ++e) {
    AxisymNodes xe;
    xe.col(0) = x[e];
    xe.col(1) = x[e + 1];
    Eigen::Vector4d f;
    axisym_pressure(xe, 1.0, f, nullptr);
    F.segment<4>(2 * e) += f;
  }
  Eigen::VectorXd G = fd_gradient(volume, pos, 1e-6);
  // Poles: r is held on the axis, so compare all but the poles' r components.
  F(0) = G(0) = F(2 * n) = G(2 * n) = 0;
  EXPECT_LT(relative_error(F, G), 1e-8);
}

TEST(AxisymElement, AssembledTangentOfAModelMatchesFiniteDifferencesOfItsResidual) {
  const Model m = read_deck_text(R"(
units: {length: mm, force: N}
materials: {wall: {type: fung, c: 61.163 kPa, a1: 0.68238, a2: 0.60558, a4: 0.1067}}
parts:
  tube: {element: axisymmetric_membrane, material: wall, thickness: 0.122 mm,
         mesh: {type: arc, center: [0.2, 0.5], radius: 0.6, start_angle: -60 deg, end_angle: 70 deg, elements: 7}}
boundary: {base: {node_set: tube.start, dofs: [z]}}
loads: {p: {type: pressure, part: tube}}
steps: [{increments: 1, set: {p: 100 mmHg}}]
)",
                                 "inline");
  const System sys(m);
  LoadState loads{{0.0}, {0.0133322}, {0.0}};
  std::mt19937 rng(6);
  std::uniform_real_distribution<double> u(-0.05, 0.08);
  Eigen::VectorXd u0(m.num_dofs());
  for (int i = 0; i < u0.size(); ++i) u0(i) = u(rng);
  sys.apply_boundary(loads, u0);
  Eigen::VectorXd R;
  SparseMatrix K;
  sys.assemble_full(u0, loads, R, K);
  std::vector<int> free;
  for (int i = 0; i < m.num_dofs(); ++i)
    if (sys.equation(i) >= 0) free.push_back(i);
  const auto residual = [&](const Eigen::VectorXd& uf) -> Eigen::VectorXd {
    Eigen::VectorXd full = u0, Rf;
    for (std::size_t i = 0; i < free.size(); ++i) full(free[i]) = uf(i);
    sys.assemble(full, loads, Rf, nullptr);
    Eigen::VectorXd out(free.size());
    for (std::size_t i = 0; i < free.size(); ++i) out(i) = Rf(free[i]);
    return out;
  };
  Eigen::VectorXd uf(free.size());
  for (std::size_t i = 0; i < free.size(); ++i) uf(i) = u0(free[i]);
  EXPECT_LT(relative_error(Eigen::MatrixXd(K), fd_jacobian(residual, uf, 1e-6)), 1e-6);
}

