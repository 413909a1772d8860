// ParaView output of a model with an axisymmetric solid part (the artery with its plaque of
// tests/support/solid_decks.hpp, at the end of the run): the meridian holds the membrane's line
// cells and the solid's quadrilaterals; the revolved file holds quadrilaterals and hexahedra of
// positive volume in VTK's node order; the cylindrical Cauchy components of a solid cell are the
// mean of its Gauss points, and a straight tube's σ_zz is its meridional stress (σ_rr = 0).
#include <gtest/gtest.h>

#include <cmath>

#include "../support/capture.hpp"
#include "../support/solid_decks.hpp"
#include "../support/vtu.hpp"
#include "output/vtk_writer.hpp"

using namespace tunica;
using namespace tunica::test;

TEST(SolidOutput, MeridianAndRevolvedGridsWithCylindricalStresses) {
  const Model m = read_deck_text(kArteryWithPlaque, "artery-plaque.yaml");
  Analysis a(m);
  Capture cap;
  a.run(cap);
  const int membrane_cells = 10, solid_cells = 8, segments = 12;
  const int plaque = m.find_part("plaque");

  const std::string mer = meridian_vtu(a);
  EXPECT_NE(mer.find("NumberOfCells=\"" + std::to_string(membrane_cells + solid_cells) + "\""), std::string::npos);
  const auto types = decode_array<std::uint8_t>(mer, "types");
  ASSERT_EQ(types.size(), 18u);
  for (int c = 0; c < 18; ++c) EXPECT_EQ(types[c], c < membrane_cells ? 3 : 9) << c;
  const auto srr = decode_float64(mer, "sigma_rr_N_per_mm2"), szz = decode_float64(mer, "sigma_zz_N_per_mm2");
  const auto smer = decode_float64(mer, "sigma_meridional_N_per_mm2"), J = decode_float64(mer, "J");
  const auto pts = a.system().solid_points(a.displacement(), plaque);
  for (int e = 0; e < solid_cells; ++e) {
    double mean_rr = 0, mean_zz = 0;
    for (int g = 0; g < 4; ++g) {
      mean_rr += 0.25 * pts[4 * e + g].sigma(0);
      mean_zz += 0.25 * pts[4 * e + g].sigma(1);
    }
    EXPECT_NEAR(srr[membrane_cells + e], mean_rr, 1e-14);
    EXPECT_NEAR(szz[membrane_cells + e], mean_zz, 1e-14);
    EXPECT_TRUE(std::isnan(smer[membrane_cells + e]));
    EXPECT_GT(J[membrane_cells + e], 0.9);
  }
  for (int e = 0; e < membrane_cells; ++e) {
    EXPECT_NEAR(szz[e], smer[e], 1e-9 * std::abs(smer[e]));  // a straight tube stays straight
    EXPECT_NEAR(srr[e], 0.0, 1e-9 * std::abs(smer[e]));
    EXPECT_EQ(J[e], 1.0);
  }

  const std::string sur = surface_vtu(a, segments);
  const auto st = decode_array<std::uint8_t>(sur, "types");
  const auto conn = decode_array<std::int64_t>(sur, "connectivity");
  const auto xyz = decode_float64(sur, "Points");
  ASSERT_EQ(st.size(), static_cast<std::size_t>((membrane_cells + solid_cells) * segments));
  std::size_t at = 0;
  int hexes = 0;
  for (std::size_t c = 0; c < st.size(); ++c) {
    if (st[c] == 12) {
      // VTK hexahedron: the base (0, 1, 2, 3) has its right-hand normal towards the face (4, 5, 6, 7).
      Eigen::Vector3d p[8];
      for (int k = 0; k < 8; ++k) p[k] = Eigen::Map<const Eigen::Vector3d>(&xyz[3 * conn[at + k]]);
      const Eigen::Vector3d n = (p[1] - p[0]).cross(p[3] - p[0]);
      EXPECT_GT(n.dot(p[4] - p[0]), 0.0) << "cell " << c;
      ++hexes;
      at += 8;
    } else {
      EXPECT_EQ(st[c], 9);
      at += 4;
    }
  }
  EXPECT_EQ(hexes, solid_cells * segments);
  EXPECT_EQ(at, conn.size());
}
