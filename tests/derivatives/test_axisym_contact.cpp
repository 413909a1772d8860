// Finite-difference checks of the penalty contact kernels (theory manual §9, contact/):
//  - node to segment (slave and master deformable): f = ∂Π/∂x and K = ∂f/∂x by
//    central differences at random states — segments of any orientation and
//    length, the slave projecting inside the segment, penetrations from 10⁻³ to
//    ½ of the segment length, with and without an offset; K symmetric;
//  - node to vertex (the corner region), both sides, with and without offset;
//  - the chain contact in the corner regions found by the search;
//  - slave against a rigid cylinder (outside, inside) and a translated rigid
//    polyline (segments and a concave corner).
// Each test prints its largest relative error.
#include <gtest/gtest.h>

#include <cstdio>
#include <numbers>
#include <random>

#include "../support/fd.hpp"
#include "contact/axisym_contact.hpp"
#include "contact/contact_search.hpp"
#include "contact/rigid_surface.hpp"

using namespace tunica;
using tunica::test::fd_gradient;
using tunica::test::fd_jacobian;
using tunica::test::relative_error;

namespace {

constexpr double kTol = 1e-7;  // relative error bound for all FD checks here
constexpr double kStep = 1e-6;

Eigen::Vector2d at(const Eigen::VectorXd& u, int node) { return u.segment<2>(2 * node); }

/// Random segment x1 → x2 of any orientation and a slave projecting at ξ ∈ [0.05, 0.95]
/// with gap g_N = −depth (the offset is added back to the geometric distance).
Eigen::VectorXd random_segment_state(std::mt19937& rng, double depth_fraction, double offset) {
  std::uniform_real_distribution<double> u(0, 1);
  const double theta = 2 * std::numbers::pi * u(rng), l = 0.2 + 1.3 * u(rng), xi = 0.05 + 0.9 * u(rng);
  const Eigen::Vector2d x1(0.5 + 2 * u(rng), 2 * u(rng) - 1);
  const Eigen::Vector2d t(std::cos(theta), std::sin(theta)), n(t(1), -t(0));
  const Eigen::Vector2d x2 = x1 + l * t;
  const Eigen::Vector2d xs = x1 + xi * l * t + (offset - depth_fraction * l) * n;
  Eigen::VectorXd v(6);
  v << xs, x1, x2;
  return v;
}

}  // namespace

TEST(AxisymContact, NodeToSegmentForceAndTangentMatchFiniteDifferences) {
  std::mt19937 rng(41);
  double worst_f = 0, worst_K = 0;
  int n = 0;
  for (double offset : {0.0, 0.03})
    for (double depth : {1e-3, 1e-2, 0.1, 0.5})
      for (int k = 0; k < 25; ++k) {
        const Eigen::VectorXd x = random_segment_state(rng, depth, offset);
        const ContactLaw law{.penalty = 1e3, .offset = offset};
        const double A = 0.07;
        ContactVector6 f;
        ContactMatrix6 K;
        const ContactPoint p = node_to_segment(at(x, 0), at(x, 1), at(x, 2), A, law, f, &K);
        ASSERT_TRUE(p.active);
        ASSERT_GT(p.xi, 0.0);
        ASSERT_LT(p.xi, 1.0);
        const auto energy = [&](const Eigen::VectorXd& v) {
          ContactVector6 g;
          return node_to_segment(at(v, 0), at(v, 1), at(v, 2), A, law, g, nullptr).energy;
        };
        const auto force = [&](const Eigen::VectorXd& v) -> Eigen::VectorXd {
          ContactVector6 g;
          node_to_segment(at(v, 0), at(v, 1), at(v, 2), A, law, g, nullptr);
          return g;
        };
        const double h = kStep * std::min(1.0, 0.1 / depth);
        const double ef = relative_error(f, fd_gradient(energy, x, h));
        const double eK = relative_error(K, fd_jacobian(force, x, h));
        EXPECT_LT(ef, kTol) << "depth " << depth << " offset " << offset;
        EXPECT_LT(eK, kTol) << "depth " << depth << " offset " << offset;
        EXPECT_LT((K - K.transpose()).norm(), 1e-12 * K.norm());
        EXPECT_NEAR(p.energy, 0.5 * law.penalty * p.gap * p.gap * A, 1e-14 * p.energy + 1e-300);
        worst_f = std::max(worst_f, ef);
        worst_K = std::max(worst_K, eK);
        ++n;
      }
  std::printf("node to segment (%d states): largest FD error force %.2e, tangent %.2e\n", n, worst_f, worst_K);
}

TEST(AxisymContact, NodeToSegmentIsZeroWhenOpenAndTheGeometricTermsMatter) {
  std::mt19937 rng(42);
  const ContactLaw law{.penalty = 1e3};
  // An open gap: nothing.
  Eigen::VectorXd x = random_segment_state(rng, -0.1, 0.0);
  ContactVector6 f;
  ContactMatrix6 K;
  ContactPoint p = node_to_segment(at(x, 0), at(x, 1), at(x, 2), 0.1, law, f, &K);
  EXPECT_FALSE(p.active);
  EXPECT_GT(p.gap, 0.0);
  EXPECT_EQ(p.energy, 0.0);
  EXPECT_EQ(f.norm(), 0.0);
  EXPECT_EQ(K.norm(), 0.0);
  // Penetrated: the tangent differs from the main term ε A N ⊗ N by the geometric terms, O(g/ℓ).
  x = random_segment_state(rng, 0.2, 0.0);
  p = node_to_segment(at(x, 0), at(x, 1), at(x, 2), 0.1, law, f, &K);
  ContactVector6 N;
  N << p.normal, -(1 - p.xi) * p.normal, -p.xi * p.normal;
  const double geo = (K - law.penalty * 0.1 * N * N.transpose()).norm() / K.norm();
  EXPECT_GT(geo, 0.05);
  std::printf("node to segment at g = -0.2 l: geometric part of the tangent %.2f of ||K||\n", geo);
  // Degenerate master segment.
  EXPECT_THROW(node_to_segment(at(x, 0), at(x, 1), at(x, 1), 0.1, law, f, &K), std::domain_error);
}

TEST(AxisymContact, NodeToVertexForceAndTangentMatchFiniteDifferences) {
  std::mt19937 rng(43);
  std::uniform_real_distribution<double> u(0, 1);
  double worst_f = 0, worst_K = 0;
  int n = 0;
  // (side, offset, distance range): concave corner (penetrated, any offset), and the
  // rounded convex corner with an offset larger than the distance.
  const struct {
    double side, offset, dmin, dmax;
  } cases[] = {{-1, 0.0, 1e-3, 0.5}, {-1, 0.05, 1e-3, 0.5}, {1, 0.2, 0.01, 0.15}};
  for (const auto& c : cases)
    for (int k = 0; k < 30; ++k) {
      const double phi = 2 * std::numbers::pi * u(rng), d = c.dmin * std::pow(c.dmax / c.dmin, u(rng));
      const Eigen::Vector2d xv(0.5 + u(rng), u(rng));
      Eigen::VectorXd x(4);
      x << xv + d * Eigen::Vector2d(std::cos(phi), std::sin(phi)), xv;
      const ContactLaw law{.penalty = 500, .offset = c.offset};
      const double A = 0.03;
      Eigen::Vector4d f;
      Eigen::Matrix4d K;
      const ContactPoint p = node_to_vertex(at(x, 0), at(x, 1), c.side, A, law, f, &K);
      ASSERT_TRUE(p.active);
      EXPECT_NEAR(p.gap, c.side * d - c.offset, 1e-14);
      const auto energy = [&](const Eigen::VectorXd& v) {
        Eigen::Vector4d g;
        return node_to_vertex(at(v, 0), at(v, 1), c.side, A, law, g, nullptr).energy;
      };
      const auto force = [&](const Eigen::VectorXd& v) -> Eigen::VectorXd {
        Eigen::Vector4d g;
        node_to_vertex(at(v, 0), at(v, 1), c.side, A, law, g, nullptr);
        return g;
      };
      const double h = kStep * std::min(1.0, d / 0.1);
      const double ef = relative_error(f, fd_gradient(energy, x, h));
      const double eK = relative_error(K, fd_jacobian(force, x, h));
      EXPECT_LT(ef, kTol) << "side " << c.side << " offset " << c.offset << " d " << d;
      EXPECT_LT(eK, kTol) << "side " << c.side << " offset " << c.offset << " d " << d;
      EXPECT_LT((K - K.transpose()).norm(), 1e-12 * K.norm());
      worst_f = std::max(worst_f, ef);
      worst_K = std::max(worst_K, eK);
      ++n;
    }
  std::printf("node to vertex (%d states): largest FD error force %.2e, tangent %.2e\n", n, worst_f, worst_K);
}

TEST(AxisymContact, ChainContactMatchesFiniteDifferencesInSegmentAndCornerRegions) {
  // A zig-zag master chain with concave and convex corners (normal on the right of +z travel).
  Eigen::Matrix2Xd chain(2, 5);
  chain << 1.0, 1.3, 1.0, 1.2, 0.9,  //
      0.0, 0.4, 0.8, 1.1, 1.5;
  std::mt19937 rng(44);
  std::uniform_real_distribution<double> u(0, 1);
  double worst_f = 0, worst_K = 0;
  int counts[3] = {0, 0, 0};
  const ContactLaw law{.penalty = 200, .offset = 0.0};
  for (int k = 0; k < 4000 && (counts[1] < 40 || counts[2] < 40); ++k) {
    const Eigen::Vector2d xs(0.8 + 0.6 * u(rng), -0.1 + 1.7 * u(rng));
    const ChainProjection where = project_on_chain(xs, chain);
    if (!where.active(law.offset) || where.distance < 1e-3) continue;
    const int kind = static_cast<int>(where.feature);
    if (counts[kind] >= 40) continue;
    // States with the nearest feature unchanged under the FD perturbations.
    Eigen::VectorXd x(6);
    x << xs, chain.col(where.segment), chain.col(where.segment + 1);
    const auto unflat = [&](const Eigen::VectorXd& v) {
      Eigen::Matrix2Xd c = chain;
      c.col(where.segment) = at(v, 1);
      c.col(where.segment + 1) = at(v, 2);
      return c;
    };
    bool stable = true;
    for (int i = 0; i < 6 && stable; ++i)
      for (double s : {-1e-5, 1e-5}) {
        Eigen::VectorXd v = x;
        v(i) += s;
        const ChainProjection w = project_on_chain(at(v, 0), unflat(v));
        stable = stable && w.feature == where.feature && w.segment == where.segment;
      }
    if (!stable) continue;
    const double A = 0.05;
    ContactVector6 f;
    ContactMatrix6 K;
    chain_contact(xs, chain, where, A, law, f, &K);
    // The search at each perturbed state picks the same feature, so differentiate search + kernel.
    const auto energy = [&](const Eigen::VectorXd& v) {
      ContactVector6 g;
      const Eigen::Matrix2Xd c = unflat(v);
      return chain_contact(at(v, 0), c, project_on_chain(at(v, 0), c), A, law, g, nullptr).energy;
    };
    const auto force = [&](const Eigen::VectorXd& v) -> Eigen::VectorXd {
      ContactVector6 g;
      const Eigen::Matrix2Xd c = unflat(v);
      chain_contact(at(v, 0), c, project_on_chain(at(v, 0), c), A, law, g, nullptr);
      return g;
    };
    const double ef = relative_error(f, fd_gradient(energy, x, kStep));
    const double eK = relative_error(K, fd_jacobian(force, x, kStep));
    EXPECT_LT(ef, kTol) << "feature " << kind;
    EXPECT_LT(eK, kTol) << "feature " << kind;
    worst_f = std::max(worst_f, ef);
    worst_K = std::max(worst_K, eK);
    ++counts[kind];
  }
  EXPECT_GE(counts[1], 40);
  EXPECT_GE(counts[2], 10);
  std::printf("chain contact (%d segment, %d corner states): largest FD error force %.2e, tangent %.2e\n", counts[1],
              counts[2], worst_f, worst_K);
}

TEST(RigidContact, CylinderForceAndTangentMatchFiniteDifferences) {
  std::mt19937 rng(45);
  std::uniform_real_distribution<double> u(0, 1);
  double worst_f = 0, worst_K = 0;
  for (CylinderSide side : {CylinderSide::outside, CylinderSide::inside})
    for (double offset : {0.0, 0.05})
      for (int k = 0; k < 20; ++k) {
        const RigidCylinder cyl{.radius = 0.3 + u(rng), .side = side};
        const double sigma = side == CylinderSide::outside ? 1 : -1;
        const double depth = 1e-3 * std::pow(100.0, u(rng));
        const Eigen::Vector2d xs(cyl.radius + sigma * (offset - depth), 3 * u(rng) - 1);
        const ContactLaw law{.penalty = 800, .offset = offset};
        const double A = 0.02;
        Eigen::Vector2d f;
        Eigen::Matrix2d K;
        const ContactPoint p = rigid_cylinder_contact(cyl, xs, A, law, f, &K);
        ASSERT_TRUE(p.active);
        EXPECT_NEAR(p.gap, -depth, 1e-14);
        const auto energy = [&](const Eigen::VectorXd& v) {
          Eigen::Vector2d g;
          return rigid_cylinder_contact(cyl, v, A, law, g, nullptr).energy;
        };
        const auto force = [&](const Eigen::VectorXd& v) -> Eigen::VectorXd {
          Eigen::Vector2d g;
          rigid_cylinder_contact(cyl, v, A, law, g, nullptr);
          return g;
        };
        const double h = kStep * std::min(1.0, depth / 0.1);
        const double ef = relative_error(f, fd_gradient(energy, xs, h));
        const double eK = relative_error(K, fd_jacobian(force, xs, h));
        EXPECT_LT(ef, kTol);
        EXPECT_LT(eK, kTol);
        worst_f = std::max(worst_f, ef);
        worst_K = std::max(worst_K, eK);
      }
  std::printf("rigid cylinder: largest FD error force %.2e, tangent %.2e\n", worst_f, worst_K);
}

TEST(RigidContact, TranslatedPolylineForceAndTangentMatchFiniteDifferences) {
  // A catheter-tip-like profile with a groove (a concave corner at (0.28, 0)),
  // translated; it runs from the axis at the bottom to the axis at the top, so the
  // normal (on the right of the direction of travel) points out of the body.
  RigidPolyline tool;
  tool.points.resize(2, 7);
  tool.points << 0.0, 0.3, 0.35, 0.28, 0.35, 0.3, 0.0,  //
      -1.0, -1.0, -0.2, 0.0, 0.2, 1.0, 1.0;
  tool.displacement = Eigen::Vector2d(0.02, -0.13);
  std::mt19937 rng(46);
  std::uniform_real_distribution<double> u(0, 1);
  double worst_f = 0, worst_K = 0;
  int counts[3] = {0, 0, 0};
  const ContactLaw law{.penalty = 300, .offset = 0.01};
  for (int k = 0; k < 20000 && (counts[1] < 60 || counts[2] < 20); ++k) {
    const Eigen::Vector2d xs(0.4 * u(rng), -1.3 + 2.6 * u(rng));
    ChainProjection where;
    Eigen::Vector2d f;
    Eigen::Matrix2d K;
    const ContactPoint p = rigid_polyline_contact(tool, xs, 0.04, law, f, &K, &where);
    if (!p.active || where.distance < 1e-3) continue;
    bool stable = true;
    for (int i = 0; i < 2; ++i)
      for (double s : {-1e-5, 1e-5}) {
        Eigen::Vector2d v = xs;
        v(i) += s;
        const ChainProjection w = project_on_chain(v, tool.current());
        stable = stable && w.feature == where.feature && w.segment == where.segment;
      }
    if (!stable) continue;
    const auto energy = [&](const Eigen::VectorXd& v) {
      Eigen::Vector2d g;
      return rigid_polyline_contact(tool, v, 0.04, law, g, nullptr).energy;
    };
    const auto force = [&](const Eigen::VectorXd& v) -> Eigen::VectorXd {
      Eigen::Vector2d g;
      rigid_polyline_contact(tool, v, 0.04, law, g, nullptr);
      return g;
    };
    const int kind = static_cast<int>(where.feature);
    if (counts[kind] >= 60) continue;
    const double h = kStep * std::min(1.0, where.distance / 0.1);  // small near a rounded corner (K ∝ 1/d)
    const double ef = relative_error(f, fd_gradient(energy, xs, h));
    const double eK = relative_error(K, fd_jacobian(force, xs, h));
    EXPECT_LT(ef, kTol);
    EXPECT_LT(eK, kTol);
    worst_f = std::max(worst_f, ef);
    worst_K = std::max(worst_K, eK);
    ++counts[kind];
  }
  EXPECT_GE(counts[1], 60);
  EXPECT_GE(counts[2], 20);
  std::printf("rigid polyline (%d segment, %d corner states): largest FD error force %.2e, tangent %.2e\n",
              counts[1], counts[2], worst_f, worst_K);
}
