// A boundary value that moves its nodes past the model's far side, or across the axis, is warned
// about at the value, and names itself in the hint of the failure it causes
// (model/boundary_motion_check.hpp).
#include <gtest/gtest.h>

#include <filesystem>

#include "../support/capture.hpp"
#include "model/boundary_motion_check.hpp"
#include "solver/failure_hints.hpp"

using namespace tunica;
using namespace tunica::test;

namespace {

// A tube 10 mm long whose end is pulled along z (a prestretch): `-12 mm` would move that end 2 mm
// below the base, through the wall.
const std::string kTube = R"(units: {length: mm, force: N}
materials:
  carotid: {type: hgo, mu: 30 kPa, k1: 20 kPa, k2: 8, beta: 35 deg}
parts:
  wall:
    element: axisymmetric_membrane
    material: carotid
    thickness: 0.5 mm
    mesh: {type: line, from: [3 mm, 0 mm], to: [3 mm, 10 mm], elements: 10}
boundary:
  base: {node_set: wall.start, dofs: [z]}
  pull: {node_set: wall.end, dofs: [z]}
loads:
  lumen: {type: pressure, part: wall}
steps:
  - {name: prestretch, increments: 5, set: {pull: -12 mm}}
  - {name: inflate, increments: 20, set: {lumen: 120 mmHg}}
)";

std::vector<std::string> motion_warnings(const Model& m) {
  std::vector<std::string> out;
  for (const std::string& w : m.warnings)
    if (w.find("past the whole model") != std::string::npos || w.find("across the axis") != std::string::npos ||
        w.find("stretched at least") != std::string::npos ||
        w.find("every DOF the boundary names") != std::string::npos)
      out.push_back(w);
  return out;
}

}  // namespace

TEST(BoundaryMotionCheck, AnEndMovedPastTheOtherEndIsWarnedAboutAtTheValue) {
  const Model m = read_deck_text(kTube, "tube.yaml");
  const std::vector<std::string> w = motion_warnings(m);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("tube.yaml:16:"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("key 'steps[0].set.pull'"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("boundary 'pull' moves z of node set 'wall.end' (at z = 10 mm) by -12 mm in step 'prestretch', "
                      "to z = -2 mm: past the whole model, whose nodes span z = 0 to 10 mm, while boundary 'base' "
                      "holds z"),
            std::string::npos)
      << w[0];
}

TEST(BoundaryMotionCheck, AStretchAShorteningAndAFreeTranslationAreNot) {
  // A stretch away from the base, a shortening short of it, the base pulled away from the end, and
  // a tube whose other end nothing holds in z (it translates).
  for (const auto& [from, to] : std::vector<std::pair<std::string, std::string>>{
           {"pull: -12 mm", "pull: 5 mm"},
           {"pull: -12 mm", "pull: -8 mm"},
           {"set: {pull: -12 mm}", "set: {base: -5 mm}"},
           {"  base: {node_set: wall.start, dofs: [z]}\n", "  base: {node_set: wall.start, dofs: [r]}\n"}}) {
    const Model m = read_deck_text(replace(kTube, from, to), "tube.yaml");
    EXPECT_TRUE(motion_warnings(m).empty()) << to << ": " << (motion_warnings(m).empty() ? "" : motion_warnings(m)[0]);
  }
  // The base pulled up past the end is the same mistake from the other side.
  const Model up = read_deck_text(replace(kTube, "set: {pull: -12 mm}", "set: {base: 10.5 mm}"), "tube.yaml");
  ASSERT_EQ(motion_warnings(up).size(), 1u);
  EXPECT_NE(motion_warnings(up)[0].find("to z = 10.5 mm: past the whole model"), std::string::npos)
      << motion_warnings(up)[0];
}

TEST(BoundaryMotionCheck, AnEndPulledByMoreThanTheModelIsWarnedAboutAsAPosition) {
  // `pull: 13 mm` on a 10 mm tube: the end at z = 13 mm was meant, a 3 mm prestretch.
  const Model m = read_deck_text(replace(kTube, "pull: -12 mm", "pull: 13 mm"), "tube.yaml");
  const std::vector<std::string> w = motion_warnings(m);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("key 'steps[0].set.pull'"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("boundary 'pull' moves z of node set 'wall.end' by 13 mm in step 'prestretch', away from "
                      "boundary 'base', which holds z on the other side: more than the model's whole extent in z (10 "
                      "mm), so the wall between is stretched at least 2.3-fold along z"),
            std::string::npos)
      << w[0];
  EXPECT_NE(w[0].find("if the set (at z = 10 mm) is to end at z = 13 mm, the value is 3 mm"), std::string::npos)
      << w[0];
  // Half the tube's length (λz 1.5) is not.
  EXPECT_TRUE(motion_warnings(read_deck_text(replace(kTube, "pull: -12 mm", "pull: 5 mm"), "tube.yaml")).empty());
}

TEST(BoundaryMotionCheck, ARadialMotionAcrossTheAxisIsWarnedAbout) {
  const std::string deck = replace(replace(kTube, "pull: {node_set: wall.end, dofs: [z]}",
                                           "pull: {node_set: wall.end, dofs: [z]}\n  squeeze: {node_set: wall.end, dofs: [r]}"),
                                   "set: {pull: -12 mm}", "set: {pull: 1 mm, squeeze: -3.5 mm}");
  const std::vector<std::string> w = motion_warnings(read_deck_text(deck, "tube.yaml"));
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("boundary 'squeeze' moves r of node set 'wall.end' by -3.5 mm in step 'prestretch'"),
            std::string::npos)
      << w[0];
  EXPECT_NE(w[0].find("at r = -0.5 mm, across the axis"), std::string::npos) << w[0];
  EXPECT_TRUE(motion_warnings(read_deck_text(replace(deck, "-3.5 mm", "-2.5 mm"), "tube.yaml")).empty());
}

TEST(BoundaryMotionCheck, NoExampleIsWarnedAbout) {
  for (const auto& e : std::filesystem::directory_iterator(std::string(TUNICA_SOURCE_DIR) + "/examples")) {
    if (e.path().extension() != ".yaml") continue;
    const Model m = read_deck(e.path().string(), ReadOptions{.allow_scripts = true});  // the examples mesh their .geo
    EXPECT_TRUE(motion_warnings(m).empty()) << e.path();
  }
}

TEST(BoundaryMotionCheck, TheEversionOfAStepWithNoPressureNamesTheBoundaryNotALimitPoint) {
  const Model m = read_deck_text(kTube, "tube.yaml");
  StepTrace start;
  LoadState rest;
  rest.pressure = {0.0};
  rest.volume = {1.0};
  start.restart_at(rest);
  const std::string h = eversion_hint(m, 0, m.steps[0], 0, start);
  EXPECT_NE(h.find("boundary 'pull' moves z of node set 'wall.end'"), std::string::npos) << h;
  EXPECT_EQ(h.find("limit point"), std::string::npos) << h;
  // A shortening within the tube that everts it: the step's motion, still no limit point.
  const Model shorter = read_deck_text(replace(kTube, "pull: -12 mm", "pull: -9 mm"), "tube.yaml");
  const std::string s = eversion_hint(shorter, 0, shorter.steps[0], 0, start);
  EXPECT_NE(s.find("step 'prestretch' changes no pressure, so its boundary motion ('pull') turned the surface of load "
                   "'lumen' inside out"),
            std::string::npos)
      << s;
  EXPECT_EQ(s.find("limit point"), std::string::npos) << s;
  // The inflation step raises the pressure: the limit point stays the likely cause.
  const std::string p = eversion_hint(shorter, 0, shorter.steps[1], 1, start);
  EXPECT_NE(p.find("limit point"), std::string::npos) << p;
}

TEST(BoundaryMotionCheck, OneValueForTwoDofsIsSaidToMoveAlongEach) {
  const std::string deck =
      replace(kTube, "pull: {node_set: wall.end, dofs: [z]}", "pull: {node_set: wall.end, dofs: [r, z]}");
  const std::vector<std::string> w = motion_warnings(read_deck_text(replace(deck, "pull: -12 mm", "pull: 1 mm"), "t.yaml"));
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("boundary 'pull' names r and z and step 'prestretch' sets it to 1 mm: a boundary value moves every "
                      "DOF the boundary names by it, so node set 'wall.end' moves by 1 mm along each of r and z"),
            std::string::npos)
      << w[0];
  EXPECT_NE(w[0].find("`pull_hold: {node_set: wall.end, dofs: [r]}`"), std::string::npos) << w[0];
  // A clamp (no value, or 0) is no such motion.
  EXPECT_TRUE(motion_warnings(read_deck_text(replace(deck, "set: {pull: -12 mm}", "set: {pull: 0 mm}"), "t.yaml")).empty());
}
