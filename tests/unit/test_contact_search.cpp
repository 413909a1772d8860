// The contact search and the contact force balance (theory manual §9, §9.1, contact/):
//  - large sliding: a slave carried along a curved master chain, in single steps
//    and in jumps across many segments, is always given its own segment and ξ;
//  - corners: the fan of a convex corner is a vertex feature outside (inactive),
//    of a concave corner a vertex feature inside (active); beyond the chain's ends
//    there is no contact; ties go to the lowest segment; the search radius;
//  - the energy is continuous along a penetrated path that slides across corners;
//  - a node pressed into a flat rigid surface (polyline, cylinder) and into a
//    flat deformable segment carries the force p_c A_s, and the master's
//    reactions balance it (force and moment);
//  - a translated rigid polyline acts as the slave moved the opposite way;
//  - tributary areas.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "contact/axisym_contact.hpp"
#include "contact/contact_search.hpp"
#include "contact/rigid_surface.hpp"

using namespace tunica;

namespace {

/// Half circle of radius ρ about (r0, 0) from the bottom to the top, m nodes: a chain
/// running in +z on its outer (right) side, so its normal points away from the centre.
Eigen::Matrix2Xd arc(int m, double rho = 0.5, double r0 = 0.2) {
  Eigen::Matrix2Xd c(2, m);
  for (int i = 0; i < m; ++i) {
    const double phi = -std::numbers::pi / 2 + std::numbers::pi * i / (m - 1);
    c.col(i) = Eigen::Vector2d(r0 + rho * std::cos(phi), rho * std::sin(phi));
  }
  return c;
}

}  // namespace

TEST(ContactSearch, FindsTheRightSegmentUnderLargeSliding) {
  const int m = 41;
  const Eigen::Matrix2Xd chain = arc(m);
  // Positions on segment k at ξ, pushed in by δ (inside the arc), and visited in a
  // scrambled order so that consecutive positions are far apart along the chain.
  int checked = 0;
  for (double delta : {1e-4, 5e-3})
    for (int step = 0; step < 400; ++step) {
      const int k = (step * 17) % (m - 1);
      const double xi = 0.02 + 0.96 * ((step * 7) % 50) / 49.0;
      const Eigen::Vector2d a = chain.col(k), b = chain.col(k + 1);
      const Eigen::Vector2d n = segment_normal(a, b);
      const Eigen::Vector2d xs = a + xi * (b - a) - delta * n;
      const ChainProjection p = project_on_chain(xs, chain);
      ASSERT_EQ(p.feature, ChainFeature::segment) << "step " << step;
      ASSERT_EQ(p.segment, k) << "step " << step;
      EXPECT_NEAR(p.xi, xi, 1e-12);
      EXPECT_NEAR(p.gap(), -delta, 1e-12);
      EXPECT_TRUE(p.active());
      ++checked;
    }
  // A whole slave surface at once (a sliding balloon): search_chain is project_on_chain per node.
  Eigen::Matrix2Xd slaves = 0.97 * arc(23, 0.5, 0.0);
  slaves.row(0).array() += 0.2;
  const std::vector<ChainProjection> all = search_chain(slaves, chain);
  ASSERT_EQ(all.size(), 23u);
  for (int i = 0; i < 23; ++i) {
    const ChainProjection p = project_on_chain(slaves.col(i), chain);
    EXPECT_EQ(all[i].segment, p.segment);
    EXPECT_EQ(all[i].signed_distance, p.signed_distance);
    if (i > 0 && i < 22 && i != 11) {  // (node 11 is on the border of two segments' sectors)
      EXPECT_TRUE(all[i].active());
      // The nearest segment to a node at polar angle φ on the concentric inner arc.
      const double phi = -std::numbers::pi / 2 + std::numbers::pi * i / 22;
      const int expected = static_cast<int>(std::floor((phi + std::numbers::pi / 2) / (std::numbers::pi / (m - 1))));
      EXPECT_EQ(all[i].segment, std::min(expected, m - 2)) << "node " << i;
    }
  }
  std::printf("large sliding: %d positions on %d segments found\n", checked, m - 1);
}

TEST(ContactSearch, CornersEndsTiesAndSearchRadius) {
  // A ridge: (1, 0) → (1.5, 0.5) → (1, 1), normals pointing to larger r; the corner at
  // (1.5, 0.5) is convex towards the slave side.
  Eigen::Matrix2Xd ridge(2, 3);
  ridge << 1.0, 1.5, 1.0, 0.0, 0.5, 1.0;
  ChainProjection p = project_on_chain(Eigen::Vector2d(1.8, 0.52), ridge);
  EXPECT_EQ(p.feature, ChainFeature::vertex);
  EXPECT_EQ(p.vertex, 1);
  EXPECT_EQ(p.segment, 0);
  EXPECT_GT(p.signed_distance, 0.0);
  EXPECT_NEAR(p.distance, std::hypot(0.3, 0.02), 1e-15);
  EXPECT_FALSE(p.active());
  EXPECT_TRUE(p.active(0.4));  // an offset rounds the corner
  // Just inside the convex corner: in both slabs, the nearer segment wins.
  p = project_on_chain(Eigen::Vector2d(1.45, 0.53), ridge);
  EXPECT_EQ(p.feature, ChainFeature::segment);
  EXPECT_EQ(p.segment, 1);
  EXPECT_TRUE(p.active());

  // A valley: the same corner seen from the other side (reverse the chain, so the
  // normals point to smaller r): concave; its fan is on the penetrated side.
  const Eigen::Matrix2Xd valley = ridge.rowwise().reverse();
  p = project_on_chain(Eigen::Vector2d(1.8, 0.52), valley);
  EXPECT_EQ(p.feature, ChainFeature::vertex);
  EXPECT_EQ(p.vertex, 1);
  EXPECT_LT(p.signed_distance, 0.0);
  EXPECT_TRUE(p.active());
  // On the free side of the valley: both slabs overlap, the nearer segment wins.
  p = project_on_chain(Eigen::Vector2d(1.2, 0.45), valley);
  EXPECT_EQ(p.feature, ChainFeature::segment);
  EXPECT_EQ(p.segment, 1);  // valley segment 1 runs (1.5, 0.5) → (1, 0)
  EXPECT_FALSE(p.active());

  // Beyond the ends: no side, no contact, even "behind" the chain's line.
  EXPECT_EQ(project_on_chain(Eigen::Vector2d(0.9, -0.3), ridge).feature, ChainFeature::none);
  EXPECT_EQ(project_on_chain(Eigen::Vector2d(0.5, 1.2), ridge).feature, ChainFeature::none);
  EXPECT_FALSE(project_on_chain(Eigen::Vector2d(0.5, 1.2), ridge).active());

  // Ties: on the bisector of the valley's overlap both segments are equally near;
  // the lower index is chosen, and the answer does not depend on earlier calls.
  Eigen::Matrix2Xd vee(2, 3);
  vee << 1.0, 0.0, 1.0, -1.0, 0.0, 1.0;  // normals point to larger r: concave at (0, 0)
  for (int rep = 0; rep < 3; ++rep) {
    p = project_on_chain(Eigen::Vector2d(0.5, 0.0), vee);
    EXPECT_EQ(p.feature, ChainFeature::segment);
    EXPECT_EQ(p.segment, 0);
    p = project_on_chain(Eigen::Vector2d(-0.3, 0.0), vee);  // in the concave fan
    EXPECT_EQ(p.feature, ChainFeature::vertex);
    EXPECT_EQ(p.segment, 0);
    EXPECT_DOUBLE_EQ(p.signed_distance, -0.3);
  }

  // Search radius: nothing nearer than it.
  EXPECT_EQ(project_on_chain(Eigen::Vector2d(3.0, 0.5), ridge, 1.0).feature, ChainFeature::none);
  EXPECT_EQ(project_on_chain(Eigen::Vector2d(2.0, 0.5), ridge, 1.0).feature, ChainFeature::vertex);

  // Bad chains.
  EXPECT_THROW(project_on_chain(Eigen::Vector2d(0, 0), Eigen::Matrix2Xd(2, 1)), std::invalid_argument);
  Eigen::Matrix2Xd collapsed(2, 3);
  collapsed << 1, 1, 2, 0, 0, 1;
  EXPECT_THROW(project_on_chain(Eigen::Vector2d(1.2, 0.0), collapsed), std::domain_error);
}

TEST(ContactSearch, EnergyIsContinuousWhileSlidingAcrossCorners) {
  // A penetrated slave slides along the whole zig-zag chain on a continuous path
  // (the chain offset by −depth along the nodal normals n̄_i, interpolated linearly),
  // through the fans of concave corners and the overlapping slabs inside convex
  // ones; the energy (search + kernel) must not jump.
  Eigen::Matrix2Xd chain(2, 5);
  chain << 1.0, 1.3, 1.0, 1.2, 0.9,  //
      0.0, 0.4, 0.8, 1.1, 1.5;
  const int m = 5;
  Eigen::Matrix2Xd nbar(2, m);
  for (int i = 0; i < m; ++i) {
    Eigen::Vector2d s = Eigen::Vector2d::Zero();
    if (i > 0) s += segment_normal(chain.col(i - 1), chain.col(i));
    if (i < m - 1) s += segment_normal(chain.col(i), chain.col(i + 1));
    nbar.col(i) = s.normalized();
  }
  const ContactLaw law{.penalty = 100};
  const double A = 0.1, depth = 0.02;
  double prev = -1, largest_jump = 0, emin = 1e300;
  int vertex_steps = 0;
  const int steps = 100000;
  for (int i = 0; i <= steps; ++i) {
    const double s = 0.05 + 3.9 * i / steps;
    const int k = std::min(m - 2, static_cast<int>(s));
    const double xi = s - k;
    const Eigen::Vector2d xs = chain.col(k) + xi * (chain.col(k + 1) - chain.col(k)) -
                               depth * ((1 - xi) * nbar.col(k) + xi * nbar.col(k + 1));
    const ChainProjection where = project_on_chain(xs, chain);
    ContactVector6 f;
    const ContactPoint p = chain_contact(xs, chain, where, A, law, f, nullptr);
    if (where.feature == ChainFeature::vertex) ++vertex_steps;
    if (prev >= 0) largest_jump = std::max(largest_jump, std::abs(p.energy - prev));
    prev = p.energy;
    emin = std::min(emin, p.energy);
  }
  const double e_flat = 0.5 * law.penalty * depth * depth * A;
  EXPECT_GT(vertex_steps, 0);
  EXPECT_GT(emin, 0.0);
  EXPECT_LT(largest_jump, 1e-2 * e_flat);
  std::printf("sliding across corners: %d of %d steps in corner fans, largest energy step %.2e of the flat energy\n",
              vertex_steps, steps, largest_jump / e_flat);
}

TEST(ContactForce, NodePressedIntoAFlatSurfaceCarriesPressureTimesArea) {
  const ContactLaw law{.penalty = 2.5e3};
  const double R = 0.8, L = 0.05, A = 2 * std::numbers::pi * R * L;  // slave's tributary area
  const double depth = 4e-4, pc = law.penalty * depth;
  // Rigid polyline: the plane z = 0.3 seen from above (runs in −r so that n = +z).
  RigidPolyline plane;
  plane.points.resize(2, 2);
  plane.points << 2.0, 0.0, 0.3, 0.3;
  Eigen::Vector2d f;
  Eigen::Matrix2d K;
  ContactPoint p = rigid_polyline_contact(plane, Eigen::Vector2d(R, 0.3 - depth), A, law, f, &K);
  EXPECT_TRUE(p.active);
  EXPECT_NEAR(p.pressure, pc, 1e-12 * pc);
  EXPECT_NEAR(p.normal(1), 1.0, 1e-15);
  EXPECT_NEAR((-f - pc * A * p.normal).norm(), 0.0, 1e-12 * pc * A);  // force on the slave = p_c A_s n
  EXPECT_NEAR((K - law.penalty * A * p.normal * p.normal.transpose()).norm(), 0.0, 1e-9 * law.penalty * A);
  EXPECT_NEAR(p.energy, 0.5 * pc * depth * A, 1e-12 * p.energy);

  // Rigid cylinder r = 1 with the slave inside, pressed outwards by depth.
  p = rigid_cylinder_contact(RigidCylinder{.radius = 1.0, .side = CylinderSide::inside},
                             Eigen::Vector2d(1.0 + depth, 0.7), A, law, f, &K);
  EXPECT_NEAR(p.pressure, pc, 1e-9 * pc);
  EXPECT_NEAR(f(0), pc * A, 1e-9 * pc * A);  // internal force +r: the wall pushes the slave to −r
  EXPECT_EQ(f(1), 0.0);

  // Deformable flat segment: the slave gets p_c A_s n, the master nodes the reactions,
  // split by the lever rule (1 − ξ, ξ); forces and moments about any point balance.
  const Eigen::Vector2d x1(1.5, 0.3), x2(0.5, 0.3), xs(1.2, 0.3 - depth);
  ContactVector6 f6;
  ContactMatrix6 K6;
  p = node_to_segment(xs, x1, x2, A, law, f6, &K6);
  EXPECT_NEAR(p.xi, 0.3, 1e-12);
  EXPECT_NEAR((-f6.head<2>() - pc * A * Eigen::Vector2d(0, 1)).norm(), 0.0, 1e-9 * pc * A);
  EXPECT_NEAR(f6(3), -(1 - 0.3) * f6(1), 1e-12 * pc * A);
  EXPECT_NEAR(f6(5), -0.3 * f6(1), 1e-12 * pc * A);
  const Eigen::Vector2d F = f6.segment<2>(0) + f6.segment<2>(2) + f6.segment<2>(4);
  const auto moment = [](const Eigen::Vector2d& x, const Eigen::Vector2d& g) { return x(0) * g(1) - x(1) * g(0); };
  EXPECT_LT(F.norm(), 1e-12 * pc * A);
  EXPECT_LT(std::abs(moment(xs, f6.segment<2>(0)) + moment(x1, f6.segment<2>(2)) + moment(x2, f6.segment<2>(4))),
            1e-12 * pc * A);
  // The tangent of a contact pair is invariant under rigid translation (rows and columns sum to zero per direction).
  for (int d = 0; d < 2; ++d) {
    Eigen::Matrix<double, 6, 1> shift = Eigen::Matrix<double, 6, 1>::Zero();
    shift(d) = shift(d + 2) = shift(d + 4) = 1;
    EXPECT_LT((K6 * shift).norm(), 1e-9 * K6.norm());
  }
}

TEST(ContactForce, TranslatedRigidPolylineEqualsTheSlaveMovedTheOtherWay) {
  RigidPolyline tool;
  tool.points.resize(2, 4);
  tool.points << 0.0, 0.3, 0.32, 0.0, -1.0, -1.0, 1.0, 1.0;  // catheter profile, outside on the right
  const ContactLaw law{.penalty = 50, .offset = 0.005};
  const Eigen::Vector2d xs(0.31, 0.2), d(0.012, 0.4);
  Eigen::Vector2d f0, f1;
  Eigen::Matrix2d K0, K1;
  const ContactPoint p0 = rigid_polyline_contact(tool, xs - d, 0.1, law, f0, &K0);
  tool.displacement = d;
  const ContactPoint p1 = rigid_polyline_contact(tool, xs, 0.1, law, f1, &K1);
  EXPECT_TRUE(p1.active);
  EXPECT_NEAR(p0.gap, p1.gap, 1e-14);
  EXPECT_LT((f0 - f1).norm(), 1e-12 * f1.norm());
  EXPECT_LT((K0 - K1).norm(), 1e-12 * K1.norm());
}

TEST(ContactForce, TributaryAreas) {
  Eigen::Matrix2Xd X(2, 3);
  X << 1.0, 1.0, 2.0, 0.0, 0.5, 0.5;
  const Eigen::VectorXd A = slave_tributary_areas(X);
  const double two_pi = 2 * std::numbers::pi;
  EXPECT_NEAR(A(0), two_pi * 1.0 * 0.25, 1e-14);
  EXPECT_NEAR(A(1), two_pi * 1.0 * 0.75, 1e-14);
  EXPECT_NEAR(A(2), two_pi * 2.0 * 0.5, 1e-14);
}

TEST(ContactSearch, EndToleranceKeepsNodesAtTheChainsEndsOnTheEndSegments) {
  // A master running +z (normal +r) from z = 0 to z = 1; slave nodes in the planes of its ends,
  // beyond them by round-off (ξ ≈ −1e-13, 1 + 1e-13) or by more than the tolerance.
  Eigen::Matrix2Xd chain(2, 3);
  chain << 1.2, 1.2 + 1e-13, 1.2, 0.0, 0.5, 1.0;
  const double tol = 1e-9;
  const Eigen::Vector2d below(1.1, -1e-13), above(1.1, 1.0 + 1e-13), far(1.1, -1e-6);
  for (const auto& x : {below, above}) {
    EXPECT_EQ(project_on_chain(x, chain).feature, ChainFeature::none);  // τ = 0: beyond the end
    const ChainProjection p = project_on_chain(x, chain, std::numeric_limits<double>::infinity(), tol);
    EXPECT_EQ(p.feature, ChainFeature::segment);
    EXPECT_NEAR(p.signed_distance, -0.1, 1e-12);  // on the inner side of the line
    EXPECT_EQ(p.segment, x(1) < 0.5 ? 0 : 1);
  }
  EXPECT_EQ(project_on_chain(far, chain, std::numeric_limits<double>::infinity(), tol).feature, ChainFeature::none);
}
