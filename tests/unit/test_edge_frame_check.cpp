// A directional history quantity (lambda_1, S_2, ...) of a 3-D part without `frame`, whose direction
// 1 follows each element's first edge, is warned about when those edges turn between neighbours
// (model/edge_frame_check.hpp): a generated tube of triangles, not one of quadrilaterals (their
// first edges all run around it) nor a part with a frame.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include "io/deck.hpp"
#include "model/edge_frame_check.hpp"

using namespace tunica;

namespace {

std::string tube(const std::string& shape, const std::string& frame, const std::string& quantity) {
  return fmt::format(R"(units: {{length: mm, force: N}}
materials:
  rubber: {{type: neo_hookean, mu: 100 kPa}}
parts:
  wall:
    element: membrane
    material: rubber
    thickness: 0.1 mm
    mesh: {{type: tube, radius: 1 mm, length: 4 mm, around: 16, along: 4, shape: {}}}{}
boundary:
  b: {{node_set: wall.bottom, dofs: [z]}}
  x: {{node_set: wall.x0, dofs: [x]}}
  y: {{node_set: wall.y0, dofs: [y]}}
loads:
  p: {{type: pressure, part: wall}}
steps:
  - {{name: s, increments: 2, set: {{p: 5 kPa}}}}
output:
  history:
    - {{quantity: {}, part: wall}}
)",
                     shape, frame, quantity);
}

std::vector<std::string> frame_warnings(const Model& m) {
  std::vector<std::string> out;
  for (const std::string& w : m.warnings)
    if (w.find("which has no `frame`") != std::string::npos) out.push_back(w);
  return out;
}

}  // namespace

TEST(EdgeFrameCheck, ATubeOfTrianglesWithoutAFrameIsWarnedAboutAtTheHistoryEntry) {
  const Model m = read_deck_text(tube("triangle", "", "lambda_1"), "tube.yaml");
  EXPECT_GT(edge_frame_turned_fraction(m, 0), 0.3);
  const std::vector<std::string> w = frame_warnings(m);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("tube.yaml:20:"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("'lambda_1' is taken along the material directions of part 'wall'"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("`frame: {type: cylindrical, axis: [0, 0, 1]}`"), std::string::npos) << w[0];
}

TEST(EdgeFrameCheck, QuadrilateralsAFrameOrAFrameFreeQuantityAreNot) {
  const Model quads = read_deck_text(tube("quad", "", "lambda_1"), "tube.yaml");
  EXPECT_EQ(edge_frame_turned_fraction(quads, 0), 0.0);
  EXPECT_TRUE(frame_warnings(quads).empty());
  EXPECT_TRUE(frame_warnings(read_deck_text(tube("triangle", "\n    frame: {type: cylindrical, axis: [0, 0, 1]}",
                                                 "sigma_1"),
                                            "tube.yaml"))
                  .empty());
  EXPECT_TRUE(frame_warnings(read_deck_text(tube("triangle", "", "sigma_max"), "tube.yaml")).empty());
}
