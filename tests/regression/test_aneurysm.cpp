// The fusiform-aneurysm example (examples/aneurysm.yaml: Gmsh geometry meshed on
// reading, HGO wall, cylindrical frame, clamped ends, 120 mmHg) converges in every
// increment, and its straight segments carry the pressure as a thin tube must:
// away from the clamped ends and from the bulge, the hoop Cauchy stress (direction 1
// of the cylindrical frame) at each Gauss point obeys Laplace's law σθ = p r / h
// with the local current radius r and thickness h, and the axial direction carries
// no more than the clamped ends allow.
#include <gtest/gtest.h>

#include <cmath>

#include "../support/capture.hpp"

using namespace tunica;
using namespace tunica::test;

TEST(Aneurysm, ConvergesAndItsStraightSegmentsObeyLaplacesLaw) {
  const std::string deck = std::string(TUNICA_SOURCE_DIR) + "/examples/aneurysm.yaml";
  ReadOptions scripts;
  scripts.allow_scripts = true;  // the example meshes examples/meshes/aneurysm.geo
  const Model m = read_deck(deck, scripts);
  Capture cap;
  Analysis a(m);
  a.run(cap);
  EXPECT_EQ(cap.cutbacks, 0);
  int most = 0;
  for (const auto& it : cap.iterations) most = std::max(most, it.rec.iteration);
  EXPECT_LE(most, 10);
  const double p = a.loads().pressure[0];
  EXPECT_NEAR(p, 120 * 133.322387415e-6, 1e-12);  // N/mm²
  const auto pts = a.system().points(a.displacement(), 0);
  double worst = 0, bulge_r = 0, bulge_z = 0;
  int n = 0;
  for (const auto& q : pts) {
    if (q.r > bulge_r) bulge_r = q.r, bulge_z = q.z;
    if (std::abs(q.X.z()) < 13 || std::abs(q.X.z()) > 16) continue;
    const double laplace = p * q.r / q.thickness;
    worst = std::max(worst, std::abs(q.sigma(0) / laplace - 1));
    ++n;
  }
  std::printf("aneurysm: %zu Gauss points; straight segments 13 < |Z| < 16 mm: %d points, max |σθ/(p r/h) − 1| = %.3e; "
              "largest radius %.3f mm at z = %.2f mm\n", pts.size(), n, worst, bulge_r, bulge_z);
  EXPECT_GT(n, 100);
  EXPECT_LT(worst, 0.01);
  EXPECT_LT(std::abs(bulge_z), 1.0);  // the bulge stays centred (the geometry is symmetric about z = 0)
}
