// Element mean curvature of faceted surfaces (model/surface_curvature.hpp): 1/R on a sphere
// octant of quads and of triangles (every element, boundary elements included: a sphere's
// normal curvature is 1/R in every direction; triangles more roughly), about 1/(2R) on a cylinder, 0 on a plane.
#include <gtest/gtest.h>

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "io/deck.hpp"
#include "model/surface_curvature.hpp"

using namespace tunica;

namespace {

Model part_model(const std::string& mesh) {
  return read_deck_text(fmt::format(R"(title: curvature
units: {{length: mm, force: N}}
materials:
  rubber: {{type: neo_hookean, mu: 1 MPa}}
parts:
  skin: {{element: membrane, material: rubber, thickness: 0.01 mm, mesh: {}}}
steps:
  - {{name: none, increments: 1, set: {{}}}}
output: {{vtk: false}}
)",
                                    mesh),
                        "curvature.yaml", ReadOptions{.allow_scripts = true});  // one test meshes a .geo
}

}  // namespace

TEST(SurfaceCurvature, SphereOctantOfQuadsAndTrianglesIsOneOverR) {
  // Quadrilaterals: every element within 10 %. Triangles (each cube-sphere quadrilateral split
  // on one diagonal, obtuse where the patches meet): the local split of the edges' curvature is
  // rougher, within 35 % (a tension estimate needs its size, not its digits); the mean is close.
  for (const auto& [shape, tolerance] : {std::pair<const char*, double>{"quad", 0.10}, {"triangle", 0.35}}) {
    const Model m = part_model(fmt::format("{{type: octant, radius: 2 mm, n: 12, shape: {}}}", shape));
    const auto H = element_mean_curvature(m, m.parts[0]);
    double mean = 0, worst = 0;
    int count = 0;
    for (const auto& block : H)
      for (double h : block) {
        EXPECT_NEAR(h * 2.0, 1.0, tolerance) << shape;
        worst = std::max(worst, std::abs(h * 2.0 - 1.0));
        mean += h;
        ++count;
      }
    EXPECT_GT(count, 400) << shape;
    EXPECT_NEAR(mean / count * 2.0, 1.0, 0.03) << shape;
    fmt::print("octant of {}s, R = 2 mm: mean H R - 1 = {:+.4f}, worst |H R - 1| = {:.4f}\n", shape,
               mean / count * 2.0 - 1.0, worst);
  }
}

TEST(SurfaceCurvature, CylinderIsAboutOneOverTwoR) {
  const Model m =
      part_model("{type: tube, radius: 0.5 mm, length: 3 mm, around: 48, along: 30, shape: staggered_triangle}");
  const auto H = element_mean_curvature(m, m.parts[0]);
  double mean = 0;
  int count = 0;
  for (const auto& block : H)
    for (double h : block) {
      EXPECT_NEAR(h * 2 * 0.5, 1.0, 0.5);  // two or three neighbours at uneven angles: a rough estimate
      mean += h;
      ++count;
    }
  EXPECT_NEAR(mean / count * 2 * 0.5, 1.0, 0.1);
}

TEST(SurfaceCurvature, PlaneIsFlat) {
  const std::filesystem::path geo = std::filesystem::temp_directory_path() /
                                    ("tunica-curvature-" + std::to_string(::getpid()) + ".geo");
  std::ofstream(geo) << "Point(1) = {0, 0, 0, 0.2}; Point(2) = {1, 0, 0, 0.2}; Point(3) = {1, 1, 0, 0.2};\n"
                        "Point(4) = {0, 1, 0, 0.2}; Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4};\n"
                        "Line(4) = {4, 1}; Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};\n"
                        "Physical Surface(\"sheet\") = {1};\n";
  const Model m = part_model(fmt::format("{{type: gmsh, file: {}, surface: sheet}}", geo.string()));
  std::filesystem::remove(geo);
  const auto H = element_mean_curvature(m, m.parts[0]);
  int count = 0;
  for (const auto& block : H)
    for (double h : block) {
      EXPECT_EQ(h, 0.0);
      ++count;
    }
  EXPECT_GT(count, 20);
}
