// What a run that stops with contact in play says (solver/failure_hints.hpp,
// contact_convergence_hint; user guide §6):
// - a Mooney–Rivlin balloon (ends held at r = 1.2 mm) inflated by pressure against a Fung artery
//   that carries no tension yet (no prestretch): Newton stalls where they first touch at every
//   increment size, and the stop names the slack master and the fixes (its tension first, two
//   passes, a finer slave, a smaller penalty); the same model with the artery prestretched by 5 %
//   in a step before reaches the target;
// - the same pair under volume control: the correction, taken whole, drives the balloon's nodes
//   into the artery until the residual is not finite, and the stop says why and what to change.
#include <gtest/gtest.h>

#include <string>

#include "../support/capture.hpp"

using namespace tunica;
using namespace tunica::test;

namespace {

/// The balloon in the artery: `steps` is the deck's steps section.
std::string balloon_in_artery(const std::string& steps) {
  return R"(title: balloon in an artery without prestretch
units: {length: mm, force: N}
materials:
  artery: {type: fung, c: 61.163 kPa, a1: 0.68238, a2: 0.60558, a4: 0.1067}
  balloon: {type: mooney_rivlin, b1: 0.5 MPa, b2: 0.125 MPa}
parts:
  artery:
    element: axisymmetric_membrane
    material: artery
    thickness: 0.122 mm
    mesh: {type: line, from: [1.561 mm, -1 mm], to: [1.561 mm, 5 mm], elements: 60}
  balloon:
    element: axisymmetric_membrane
    material: balloon
    thickness: 0.2 mm
    mesh: {type: line, from: [1.2 mm, 0 mm], to: [1.2 mm, 4 mm], elements: 40}
node_sets:
  balloon_ends: {part: balloon, nodes: [0, 40]}
boundary:
  artery_start: {node_set: artery.start, dofs: [z]}
  artery_end: {node_set: artery.end, dofs: [z]}
  balloon_ends: {node_set: balloon_ends, dofs: [r, z]}
loads:
  inflation: {type: pressure, part: balloon}
contact:
  balloon_artery: {slave: balloon, master: artery, master_orientation: reversed, penalty: 1e3 N/mm^3, offset: 0.16 mm}
steps:
)" + steps + R"(
output:
  vtk: false
  history:
    - {quantity: pressure, load: inflation, unit: kPa}
    - {quantity: contact_force, contact: balloon_artery, unit: N}
)";
}

std::string stop_message(const std::string& deck) {
  const Model m = read_deck_text(deck, "balloon-artery.yaml");
  Capture c;
  Analysis a(m);
  try {
    a.run(c);
  } catch (const SolveError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(ContactHints, ASlackMasterThatStallsNewtonIsNamedWithItsFixes) {
  const std::string what = stop_message(balloon_in_artery("  - {name: inflation, increments: 20, set: {inflation: 200 kPa}}"));
  ASSERT_FALSE(what.empty()) << "the run converged";
  EXPECT_NE(what.find("Hint: the failed attempt had slave nodes in contact"), std::string::npos) << what;
  EXPECT_NE(what.find("part 'artery', carries almost no tension"), std::string::npos) << what;
  EXPECT_NE(what.find("axial prestretch"), std::string::npos) << what;
  EXPECT_NE(what.find("`passes: 2`"), std::string::npos) << what;
  EXPECT_NE(what.find("smaller `penalty`"), std::string::npos) << what;
}

TEST(ContactHints, TheSameModelWithTheArteryPrestretchedReachesTheTarget) {
  const Model m = read_deck_text(balloon_in_artery("  - {name: prestretch, increments: 4, set: {artery_end: 0.3 mm}}\n"
                                                   "  - {name: inflation, increments: 20, set: {inflation: 200 kPa}}"),
                                 "prestretched.yaml");
  Capture c;
  Analysis a(m);
  ASSERT_NO_THROW(a.run(c));
  EXPECT_NEAR(c.rows.back().values[0], 200.0, 1e-9);
  EXPECT_GT(c.rows.back().values[1], 0.0);  // in contact at the end
}

TEST(ContactHints, ANonFiniteResidualUnderVolumeControlWithContactSaysWhy) {
  const std::string what = stop_message(balloon_in_artery(
      "  - {name: start, increments: 2, set: {inflation: 20 kPa}}\n"
      "  - {name: inflation, increments: 20, volume_control: {load: inflation, volume: 45 mm^3}}"));
  ASSERT_FALSE(what.empty()) << "the run converged";
  ASSERT_NE(what.find("the residual is not finite"), std::string::npos) << what;
  EXPECT_NE(what.find("Hint: under volume control each correction is taken whole"), std::string::npos) << what;
  EXPECT_NE(what.find("'balloon_artery'"), std::string::npos) << what;
  EXPECT_NE(what.find("smaller `penalty`"), std::string::npos) << what;
  EXPECT_NE(what.find("more `increments`"), std::string::npos) << what;
}
