// The smoothed penalty law (theory manual (9.2), ContactLaw::smoothing δ) and the contact kernels
// with it, against finite differences:
//  - the law: p = dΠ/d(−g_N), p′ = dp/d(−g_N), both continuous at g_N = ±δ/2; equal to the plain
//    law ε⟨−g_N⟩ beyond a penetration of δ/2 (pressure and stiffness; the energy by the constant
//    εδ²/24); zero from g_N = δ/2 on;
//  - node to segment, node to vertex, the smooth master and the rigid cylinder with δ > 0, at gaps
//    inside the blend (−δ/2 < g_N < δ/2, where a node outside the surface already feels it) and
//    beyond: f = ∂Π/∂x and K = ∂f/∂x by central differences, K symmetric.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

#include "../support/fd.hpp"
#include "contact/axisym_contact.hpp"
#include "contact/rigid_surface.hpp"
#include "contact/smooth_chain.hpp"

using namespace tunica;
using tunica::test::fd_gradient;
using tunica::test::fd_jacobian;
using tunica::test::relative_error;

namespace {

constexpr double kDelta = 0.02;  // δ [length] of the kernels' tests
/// Gaps of the kernels' tests as fractions of δ: in the blend (both signs) and beyond it.
constexpr double kGapFractions[] = {0.4, 0.1, -0.1, -0.3, -0.49, -0.7, -3.0};

Eigen::Vector2d at(const Eigen::VectorXd& u, int node) { return u.segment<2>(2 * node); }

}  // namespace

TEST(ContactSmoothing, TheLawIsC1AndThePlainLawBeyondTheBlend) {
  const ContactLaw law{.penalty = 1e3, .offset = 0.0, .smoothing = 0.01};
  const ContactLaw plain{.penalty = 1e3};
  const double h = 1e-8, d = law.smoothing;
  for (double g : {0.6 * d, 0.45 * d, 0.2 * d, 0.0, -0.2 * d, -0.49 * d, -0.51 * d, -2 * d}) {
    // dΠ/d(−g) = p, dp/d(−g) = p′.
    EXPECT_NEAR((law.energy(g - h) - law.energy(g + h)) / (2 * h), law.pressure(g), 1e-6 * law.penalty * d) << g;
    EXPECT_NEAR((law.pressure(g - h) - law.pressure(g + h)) / (2 * h), law.stiffness(g), 1e-6 * law.penalty) << g;
    EXPECT_EQ(law.touching(g), g < 0.5 * d) << g;
  }
  // Continuity at both ends of the blend.
  for (double edge : {0.5 * d, -0.5 * d}) {
    EXPECT_NEAR(law.pressure(edge - 1e-12), law.pressure(edge + 1e-12), 1e-8) << edge;
    EXPECT_NEAR(law.stiffness(edge - 1e-12), law.stiffness(edge + 1e-12), 1e-6) << edge;
    EXPECT_NEAR(law.energy(edge - 1e-12), law.energy(edge + 1e-12), 1e-10) << edge;
  }
  // At the touch g_N = 0: p = εδ/8, p′ = ε/2; beyond the blend the plain law.
  EXPECT_NEAR(law.pressure(0), law.penalty * d / 8, 1e-12);
  EXPECT_NEAR(law.stiffness(0), law.penalty / 2, 1e-12);
  for (double g : {-0.5 * d, -d, -10 * d}) {
    EXPECT_NEAR(law.pressure(g), plain.pressure(g), 1e-12 * plain.pressure(g)) << g;
    EXPECT_EQ(law.stiffness(g), plain.stiffness(g)) << g;
    EXPECT_NEAR(law.energy(g), plain.energy(g) + law.penalty * d * d / 24, 1e-12 * law.energy(g)) << g;
  }
  EXPECT_EQ(law.pressure(0.5 * d), 0.0);
  EXPECT_EQ(law.stiffness(0.5 * d), 0.0);
  // δ = 0 is the plain law exactly.
  for (double g : {1e-3, 0.0, -1e-9, -0.3}) {
    EXPECT_EQ(plain.pressure(g), g < 0 ? -plain.penalty * g : 0.0) << g;
    EXPECT_EQ(plain.energy(g), g < 0 ? 0.5 * plain.penalty * g * g : 0.0) << g;
    EXPECT_EQ(plain.touching(g), g < 0) << g;
  }
}

TEST(ContactSmoothing, NodeToSegmentAndNodeToVertexMatchFiniteDifferencesInTheBlend) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0, 1);
  double worst_f = 0, worst_K = 0;
  for (double offset : {0.0, 0.03})
    for (double q : kGapFractions)
      for (int k = 0; k < 6; ++k) {
        const ContactLaw law{.penalty = 1e3, .offset = offset, .smoothing = kDelta};
        const double gap = q * kDelta, A = 0.07;
        // Segment: random orientation and length, the slave projecting inside it.
        const double theta = 2 * std::numbers::pi * u(rng), l = 0.2 + u(rng), xi = 0.1 + 0.8 * u(rng);
        const Eigen::Vector2d x1(0.5 + u(rng), u(rng)), t(std::cos(theta), std::sin(theta)), n(t(1), -t(0));
        Eigen::VectorXd x(6);
        x << x1 + xi * l * t + (offset + gap) * n, x1, x1 + l * t;
        ContactVector6 f;
        ContactMatrix6 K;
        const ContactPoint p = node_to_segment(at(x, 0), at(x, 1), at(x, 2), A, law, f, &K);
        ASSERT_TRUE(p.active) << q;
        EXPECT_NEAR(p.gap, gap, 1e-12);
        EXPECT_NEAR(p.pressure, law.pressure(gap), 1e-9 * law.penalty * kDelta);
        const auto energy = [&](const Eigen::VectorXd& v) {
          ContactVector6 g;
          return node_to_segment(at(v, 0), at(v, 1), at(v, 2), A, law, g, nullptr).energy;
        };
        const auto force = [&](const Eigen::VectorXd& v) -> Eigen::VectorXd {
          ContactVector6 g;
          node_to_segment(at(v, 0), at(v, 1), at(v, 2), A, law, g, nullptr);
          return g;
        };
        const double ef = relative_error(f, fd_gradient(energy, x, 1e-7));
        const double eK = relative_error(K, fd_jacobian(force, x, 1e-7));
        EXPECT_LT(ef, 1e-6) << "segment, gap/δ " << q;
        EXPECT_LT(eK, 1e-6) << "segment, gap/δ " << q;
        EXPECT_LT((K - K.transpose()).norm(), 1e-12 * K.norm());
        worst_f = std::max(worst_f, ef);
        worst_K = std::max(worst_K, eK);

        // Vertex: the slave at distance offset + gap (σ = +1) from the master node.
        const double phi = 2 * std::numbers::pi * u(rng);
        Eigen::VectorXd y(4);
        y << x1 + (offset + gap) * Eigen::Vector2d(std::cos(phi), std::sin(phi)), x1;
        if (offset + gap <= 1e-3) continue;  // the vertex form needs the slave off the vertex
        Eigen::Vector4d fv;
        Eigen::Matrix4d Kv;
        const ContactPoint pv = node_to_vertex(at(y, 0), at(y, 1), 1.0, A, law, fv, &Kv);
        ASSERT_TRUE(pv.active) << q;
        const auto venergy = [&](const Eigen::VectorXd& v) {
          Eigen::Vector4d g;
          return node_to_vertex(at(v, 0), at(v, 1), 1.0, A, law, g, nullptr).energy;
        };
        const auto vforce = [&](const Eigen::VectorXd& v) -> Eigen::VectorXd {
          Eigen::Vector4d g;
          node_to_vertex(at(v, 0), at(v, 1), 1.0, A, law, g, nullptr);
          return g;
        };
        const double evf = relative_error(fv, fd_gradient(venergy, y, 1e-7));
        const double evK = relative_error(Kv, fd_jacobian(vforce, y, 1e-7));
        EXPECT_LT(evf, 1e-6) << "vertex, gap/δ " << q;
        EXPECT_LT(evK, 1e-6) << "vertex, gap/δ " << q;
        worst_f = std::max(worst_f, evf);
        worst_K = std::max(worst_K, evK);
      }
  std::printf("smoothed node to segment / vertex: largest FD error force %.2e, tangent %.2e\n", worst_f, worst_K);
}

TEST(ContactSmoothing, TheSmoothMasterAndTheRigidCylinderMatchFiniteDifferencesInTheBlend) {
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> u(0, 1);
  double worst_f = 0, worst_K = 0;
  // A smooth master of 4 nodes on a gentle arc; the slave near the middle segment.
  const int m = 4;
  Eigen::Matrix2Xd chain(2, m);
  for (int j = 0; j < m; ++j) chain.col(j) = Eigen::Vector2d(1.5 + 0.02 * (j - 1.5) * (j - 1.5), 0.3 * j);
  for (double q : kGapFractions)
    for (int k = 0; k < 4; ++k) {
      const ContactLaw law{.penalty = 1e3, .offset = 0.01, .smoothing = kDelta};
      const double gap = q * kDelta, xi = 0.2 + 0.6 * u(rng), area = 0.05;
      const Eigen::Vector2d foot = smooth_point(chain, 1, xi);
      const Eigen::Vector2d tangent = smooth_point(chain, 1, xi + 1e-6) - smooth_point(chain, 1, xi - 1e-6);
      const Eigen::Vector2d normal = Eigen::Vector2d(tangent(1), -tangent(0)).normalized();
      Eigen::VectorXd v(2 + 2 * m);
      v << foot + (law.offset + gap) * normal, Eigen::Map<const Eigen::VectorXd>(chain.data(), 2 * m);
      const auto eval = [&](const Eigen::VectorXd& y, ContactVector10& f, ContactMatrix10* K) {
        const Eigen::Map<const Eigen::Matrix2Xd> c(y.data() + 2, 2, m);
        const SmoothProjection p = project_on_smooth_chain(y.head<2>(), c, project_on_chain(y.head<2>(), c), 0.0);
        EXPECT_TRUE(p.found);
        return smooth_contact(y.head<2>(), c, p.segment, p.xi, area, law, f, K);
      };
      ContactVector10 f;
      ContactMatrix10 K;
      const ContactPoint p = eval(v, f, &K);
      ASSERT_TRUE(p.active) << q;
      EXPECT_NEAR(p.gap, gap, 1e-9);
      // f and K over (slave, window of the segment: ghost, 0, 1, 2, 3 → slots 0–3 = nodes 0–3).
      const auto energy = [&](const Eigen::VectorXd& y) {
        ContactVector10 g;
        return eval(y, g, nullptr).energy;
      };
      const auto force = [&](const Eigen::VectorXd& y) -> Eigen::VectorXd {
        ContactVector10 g;
        eval(y, g, nullptr);
        return g;
      };
      const double ef = relative_error(Eigen::VectorXd(f), fd_gradient(energy, v, 1e-7));
      const double eK = relative_error(Eigen::MatrixXd(K), fd_jacobian(force, v, 1e-7));
      EXPECT_LT(ef, 1e-6) << "smooth, gap/δ " << q;
      EXPECT_LT(eK, 1e-5) << "smooth, gap/δ " << q;
      worst_f = std::max(worst_f, ef);
      worst_K = std::max(worst_K, eK);
    }
  for (CylinderSide side : {CylinderSide::outside, CylinderSide::inside})
    for (double q : kGapFractions) {
      const ContactLaw law{.penalty = 500, .offset = 0.02, .smoothing = kDelta};
      const RigidCylinder cyl{.radius = 1.0, .side = side};
      const double sigma = side == CylinderSide::outside ? 1.0 : -1.0, A = 0.3;
      Eigen::VectorXd x(2);
      x << 1.0 + sigma * (law.offset + q * kDelta), 0.4;
      Eigen::Vector2d f;
      Eigen::Matrix2d K;
      const ContactPoint p = rigid_cylinder_contact(cyl, x, A, law, f, &K);
      ASSERT_TRUE(p.active);
      const auto energy = [&](const Eigen::VectorXd& y) {
        Eigen::Vector2d g;
        return rigid_cylinder_contact(cyl, y, A, law, g, nullptr).energy;
      };
      const auto force = [&](const Eigen::VectorXd& y) -> Eigen::VectorXd {
        Eigen::Vector2d g;
        rigid_cylinder_contact(cyl, y, A, law, g, nullptr);
        return g;
      };
      EXPECT_LT(relative_error(Eigen::VectorXd(f), fd_gradient(energy, x, 1e-7)), 1e-6) << q;
      EXPECT_LT(relative_error(Eigen::MatrixXd(K), fd_jacobian(force, x, 1e-7)), 1e-6) << q;
    }
  std::printf("smoothed smooth master: largest FD error force %.2e, tangent %.2e\n", worst_f, worst_K);
}
