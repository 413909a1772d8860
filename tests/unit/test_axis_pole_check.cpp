// An axisymmetric membrane's pole (a node on the axis) whose r nothing holds is warned about at its
// part, naming the node set to hold it on (model/axis_pole_check.hpp).
#include <gtest/gtest.h>

#include <algorithm>

#include "../support/capture.hpp"

using namespace tunica;
using namespace tunica::test;

namespace {

const std::string kSphere = std::string(TUNICA_SOURCE_DIR) + "/examples/balloon-sphere.yaml";

std::vector<std::string> pole_warnings(const Model& m) {
  std::vector<std::string> out;
  for (const std::string& w : m.warnings)
    if (w.find("lies on the axis") != std::string::npos) out.push_back(w);
  return out;
}

}  // namespace

TEST(AxisPoleCheck, AFreePoleIsWarnedAboutWithTheNodeSetToHold) {
  const std::string text = replace(read_text(kSphere), "  pole:    {node_set: balloon.end, dofs: [r]}\n", "");
  const Model m = read_deck_text(text, kSphere);
  const std::vector<std::string> w = pole_warnings(m);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("balloon-sphere.yaml:"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("part 'balloon'"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("`{node_set: balloon.end, dofs: [r]}`"), std::string::npos) << w[0];
}

TEST(AxisPoleCheck, AHeldPoleAndATubeAreNot) {
  EXPECT_TRUE(pole_warnings(read_deck_text(read_text(kSphere), kSphere)).empty());
  const std::string tube = std::string(TUNICA_SOURCE_DIR) + "/examples/rat-aorta-inflation.yaml";
  EXPECT_TRUE(pole_warnings(read_deck_text(read_text(tube), tube)).empty());
}

TEST(AxisPoleCheck, AFlatPartFromTheAxisSaysPointsAreRadiusFirst) {
  // A tube's points written [z, r]: a flat disk at z = 3 from the axis out to r = 10.
  const std::string deck = R"(units: {length: mm, force: N}
materials:
  m: {type: neo_hookean, mu: 30 kPa}
parts:
  wall: {element: axisymmetric_membrane, material: m, thickness: 0.5 mm, mesh: {type: line, from: [0 mm, 3 mm], to: [10 mm, 3 mm], elements: 10}}
boundary:
  base: {node_set: wall.start, dofs: [z]}
  pull: {node_set: wall.end, dofs: [z]}
loads:
  lumen: {type: pressure, part: wall}
steps:
  - {increments: 5, set: {lumen: 10 mmHg}}
)";
  const std::vector<std::string> w = pole_warnings(read_deck_text(deck, "disk.yaml"));
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("The part is a flat disk in the plane z = 3 mm (points are [r, z], the radius first): if a tube "
                      "along the axis was meant, write each point the other way round ([3 mm, 0 mm] to [3 mm, 10 mm])"),
            std::string::npos)
      << w[0];
  // The sphere's pole is on a curved meridian: no such note.
  const std::string text = replace(read_text(kSphere), "  pole:    {node_set: balloon.end, dofs: [r]}\n", "");
  EXPECT_EQ(pole_warnings(read_deck_text(text, kSphere))[0].find("flat disk"), std::string::npos);
}

TEST(WallThicknessCheck, AShellThickerThanItsRadiusIsWarnedAboutAsAMembraneIs) {
  const std::string deck = R"(units: {length: mm, force: N}
materials:
  art: {type: neo_hookean, mu: 100 kPa}
parts:
  wall: {element: axisymmetric_shell, material: art, thickness: 1.2 mm, mesh: {type: line, from: [1 mm, 0 mm], to: [1 mm, 4 mm], elements: 40}}
node_sets:
  ends: {part: wall, nodes: [0, 40]}
boundary:
  clamp: {node_set: ends, dofs: [r, z, slope_r]}
loads:
  p: {type: pressure, part: wall}
steps:
  - {increments: 5, set: {p: 1 kPa}}
)";
  const auto said = [](const Model& m) {
    for (const std::string& w : m.warnings)
      if (w.find("typical radius of curvature") != std::string::npos) return w;
    return std::string();
  };
  const std::string w = said(read_deck_text(deck, "shell.yaml"));
  EXPECT_NE(w.find("key 'parts.wall.thickness': part 'wall': the thickness 1.2 mm is 1.2 times the part's typical "
                   "radius of curvature, 1 mm (a tube's radius; half a sphere's): a shell (Kirchhoff–Love) model"),
            std::string::npos)
      << w;
  EXPECT_EQ(said(read_deck_text(replace(deck, "thickness: 1.2 mm", "thickness: 0.1 mm"), "shell.yaml")), "");
}
