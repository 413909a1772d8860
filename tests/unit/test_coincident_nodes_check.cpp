// Two parts whose nodes meet without being shared are warned about at the second part
// (model/coincident_nodes_check.hpp): a capsule of three axisymmetric parts.
#include <gtest/gtest.h>

#include "../support/capture.hpp"

using namespace tunica;
using namespace tunica::test;

namespace {

std::string capsule(const std::string& body_from) {
  return R"(units: {length: mm, force: N}
materials:
  rubber: {type: neo_hookean, mu: 1 MPa}
parts:
  lower:
    element: axisymmetric_membrane
    material: rubber
    thickness: 0.05 mm
    mesh: {type: arc, center: [0, 0], radius: 1 mm, start_angle: -90 deg, end_angle: 0 deg, elements: 10}
  body:
    element: axisymmetric_membrane
    material: rubber
    thickness: 0.05 mm
    mesh: {type: line, from: )" + body_from + R"(, to: [1 mm, 2 mm], elements: 8}
boundary:
  pole: {node_set: lower.start, dofs: [r, z]}
  top:  {node_set: body.end, dofs: [z]}
loads:
  p: {type: pressure, part: lower}
steps:
  - {name: inflate, increments: 2, set: {p: 0.01 MPa}}
)";
}

std::vector<std::string> joint_warnings(const Model& m) {
  std::vector<std::string> out;
  for (const std::string& w : m.warnings)
    if (w.find("not joined") != std::string::npos) out.push_back(w);
  return out;
}

}  // namespace

TEST(CoincidentNodesCheck, PartsThatMeetAtAnUnsharedNodeAreWarnedAbout) {
  const Model m = read_deck_text(capsule("[1 mm, 0 mm]"), "capsule.yaml");
  const std::vector<std::string> w = joint_warnings(m);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("capsule.yaml:"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("parts 'lower' and 'body' have 1 pair(s)"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("at r = 1, z = 0"), std::string::npos) << w[0];
}

TEST(CoincidentNodesCheck, PartsApartAreNot) {
  EXPECT_TRUE(joint_warnings(read_deck_text(capsule("[1.2 mm, 0 mm]"), "capsule.yaml")).empty());
}
