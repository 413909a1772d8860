// The structured (r, z) grid of axisymmetric solid parts (mesh/solid_grid.hpp): node numbering,
// counter-clockwise elements, the ordered surface chains, the profiles (constant, polyline,
// cosine and circular bumps) and the geometric checks; the stenosis of the paper's angioplasty
// example (theory manual §12.2) is buildable.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "mesh/solid_grid.hpp"

using namespace tunica;

namespace {

RadiusProfile constant(double r) {
  RadiusProfile p;
  p.radius = r;
  return p;
}

RadiusProfile bump(RadiusProfile::Type t, double ends, double centre) {
  RadiusProfile p;
  p.type = t;
  p.radius_ends = ends;
  p.radius_centre = centre;
  return p;
}

}  // namespace

TEST(SolidGrid, NumberingChainsAndCounterClockwiseElements) {
  SolidGridSpec s;
  s.z0 = -1;
  s.z1 = 2;
  s.inner = constant(1.0);
  s.outer = constant(1.5);
  s.elements_r = 3;
  s.elements_z = 5;
  const SolidGrid g = solid_grid(s);
  ASSERT_EQ(g.nodes.size(), 4u * 6u);
  ASSERT_EQ(g.quads.size(), 4u * 15u);
  for (std::size_t e = 0; e < g.quads.size() / 4; ++e) {
    double area2 = 0;  // shoelace: positive for counter-clockwise in (r, z)
    for (int a = 0; a < 4; ++a) {
      const auto& p = g.nodes[g.quads[4 * e + a]];
      const auto& q = g.nodes[g.quads[4 * e + (a + 1) % 4]];
      area2 += p(0) * q(1) - q(0) * p(1);
    }
    EXPECT_NEAR(area2, 2 * 0.5 / 3 * 3.0 / 5, 1e-12);
  }
  ASSERT_EQ(g.inner.size(), 6u);
  ASSERT_EQ(g.bottom.size(), 4u);
  for (std::size_t k = 0; k < g.inner.size(); ++k) {
    EXPECT_DOUBLE_EQ(g.nodes[g.inner[k]](0), 1.0);
    EXPECT_DOUBLE_EQ(g.nodes[g.outer[k]](0), 1.5);
    if (k > 0) {
      EXPECT_GT(g.nodes[g.inner[k]](1), g.nodes[g.inner[k - 1]](1));
    }
  }
  EXPECT_DOUBLE_EQ(g.nodes[g.inner.back()](1), 2.0);
  for (std::size_t k = 0; k < g.bottom.size(); ++k) {
    EXPECT_DOUBLE_EQ(g.nodes[g.bottom[k]](1), -1.0);
    EXPECT_DOUBLE_EQ(g.nodes[g.top[k]](1), 2.0);
    if (k > 0) {
      EXPECT_GT(g.nodes[g.top[k]](0), g.nodes[g.top[k - 1]](0));
    }
  }
}

TEST(SolidGrid, ProfilesPassThroughTheirDefiningPoints) {
  for (auto t : {RadiusProfile::Type::cosine, RadiusProfile::Type::circular}) {
    const RadiusProfile p = bump(t, 0.6235, 0.39);
    EXPECT_NEAR(profile_radius(p, 0.0, 0.0, 3.8), 0.6235, 1e-12);
    EXPECT_NEAR(profile_radius(p, 3.8, 0.0, 3.8), 0.6235, 1e-12);
    EXPECT_NEAR(profile_radius(p, 1.9, 0.0, 3.8), 0.39, 1e-12);
  }
  // The circular arc: every point at the same distance ρ = (a² + d²)/(2d) from its centre.
  const RadiusProfile c = bump(RadiusProfile::Type::circular, 1.0, 0.5);
  const double a = 1.0, d = 0.5, rho = (a * a + d * d) / (2 * d);
  for (double z : {0.0, 0.3, 0.77, 1.0, 1.6, 2.0})
    EXPECT_NEAR(std::hypot(profile_radius(c, z, 0, 2) - (0.5 + rho), z - 1.0), rho, 1e-12);
  RadiusProfile poly;
  poly.type = RadiusProfile::Type::polyline;
  poly.points = {{1.0, 0.0}, {2.0, 1.0}, {2.0, 3.0}};
  EXPECT_DOUBLE_EQ(profile_radius(poly, 0.25, 0, 3), 1.25);
  EXPECT_DOUBLE_EQ(profile_radius(poly, 2.0, 0, 3), 2.0);
  EXPECT_THROW(profile_radius(poly, 3.5, 0, 3.5), std::invalid_argument);
  EXPECT_THROW(profile_radius(bump(RadiusProfile::Type::circular, 2.0, 0.5), 0.5, 0, 2), std::invalid_argument);
}

TEST(SolidGrid, TheStenosisOfThePapersAngioplasty) {
  // 3.8 mm long, 0.01 mm thick at both ends, lumen radius 0.39 mm at the centre, inside an
  // artery whose inner wall is at r = 0.6335 mm; 5 × 100 = 500 elements as in the paper.
  SolidGridSpec s;
  s.z0 = 0;
  s.z1 = 3.8;
  s.outer = constant(0.6335);
  s.inner = bump(RadiusProfile::Type::cosine, 0.6235, 0.39);
  s.elements_r = 5;
  s.elements_z = 100;
  const SolidGrid g = solid_grid(s);
  EXPECT_EQ(g.quads.size() / 4, 500u);
  EXPECT_NEAR(g.nodes[g.inner[50]](0), 0.39, 1e-12);
  EXPECT_NEAR(g.nodes[g.outer[0]](0) - g.nodes[g.inner[0]](0), 0.01, 1e-12);
}

TEST(SolidGrid, BadGeometryIsRefusedWithAReason) {
  SolidGridSpec s;
  s.inner = constant(1.0);
  s.outer = constant(1.0);
  try {
    solid_grid(s);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("not below the outer radius"), std::string::npos) << e.what();
  }
  s.inner = constant(-0.1);
  s.outer = constant(1.0);
  try {
    solid_grid(s);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("not positive"), std::string::npos) << e.what();
  }
  s.inner = constant(0.5);
  s.z1 = s.z0;
  EXPECT_THROW(solid_grid(s), std::invalid_argument);
}
