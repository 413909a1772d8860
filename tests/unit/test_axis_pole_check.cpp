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
