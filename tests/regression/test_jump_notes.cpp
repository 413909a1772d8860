// A converged increment that jumps onto a far branch of the pressure–volume curve, and a membrane
// stretched or crushed beyond what a membrane reaches, are noted once (output/jump_notes.hpp).
#include <gtest/gtest.h>

#include <unistd.h>

#include "../support/cli.hpp"
#include "../support/deck_files.hpp"
#include "../support/step_trace_along.hpp"
#include "io/deck.hpp"
#include "output/jump_notes.hpp"

using namespace tunica;
using namespace tunica::test;

namespace {

const std::string kScratch = "tunica-jump-notes-" + std::to_string(getpid());

// A Mooney–Rivlin balloon (b2 > 0 stiffens at large stretch) blown past its pressure maximum
// (about 10.6 kPa) under pressure control: increment 8 lands on the far, stiff branch.
const std::string kBalloon = R"(units: {length: mm, force: N}
materials:
  latex: {type: mooney_rivlin, b1: 150 kPa, b2: 30 kPa}
parts:
  ball: {element: axisymmetric_membrane, material: latex, thickness: 0.1 mm, mesh: {type: arc, center: [0 mm, 0 mm], radius: 5 mm, start_angle: -90 deg, end_angle: 90 deg, elements: 30}}
boundary:
  south: {node_set: ball.start, dofs: [r, z]}
  north: {node_set: ball.end, dofs: [r]}
loads:
  p: {type: pressure, part: ball}
steps:
  - {name: blow, increments: 10, set: {p: 15 kPa}}
)";

}  // namespace

TEST(JumpNotes, AJumpOntoAFarBranchIsNotedAndASmoothRiseIsNot) {
  const Model m = read_deck_text(kBalloon, "ball.yaml");
  // Pressures in N/mm² (1 kPa = 1e-3), volumes in mm³, as the balloon's run gives them.
  const std::string jump = volume_jump_note(m, 0, 0, along({{0.009, 967}, {0.0105, 1603}, {0.012, 24798}}), "at x");
  EXPECT_NE(jump.find("at x, the enclosed volume of load 'p' grew 15.5-fold in one increment (1603 to 2.48e+04 mm³) "
                      "while the pressure went from 10.5 to 12 kPa"),
            std::string::npos)
      << jump;
  EXPECT_NE(jump.find("`volume_control: {load: p, volume: ...}`"), std::string::npos) << jump;
  // A steady rise, a large first increment (no increment before it to compare), a volume-controlled step.
  EXPECT_EQ(volume_jump_note(m, 0, 0, along({{0.0075, 796}, {0.009, 967}, {0.0105, 1603}}), "at x"), "");
  EXPECT_EQ(volume_jump_note(m, 0, 0, along({{0, 524}, {0.012, 24798}}), "at x"), "");
  Model vc = m;
  vc.steps[0].volume_control.load = 0;
  EXPECT_EQ(volume_jump_note(vc, 0, 0, along({{0.009, 967}, {0.0105, 1603}, {0.012, 24798}}), "at x"), "");
}

TEST(JumpNotes, TheRunNotesTheSnapThroughOnceAndACrushedTubeAsCrushed) {
  const Outcome o = run_cli("run " + write_deck_file(kScratch, "ball.yaml", kBalloon) + " -o " +
                            testing::TempDir() + kScratch + "-ball");
  EXPECT_EQ(o.exit_code, 0) << o.output;
  const std::size_t at = o.output.find("tunica: note: at step 1 'blow', increment 8, the enclosed volume of load 'p' grew");
  EXPECT_NE(at, std::string::npos) << o.output;
  EXPECT_EQ(o.output.find("grew", at + 80), std::string::npos) << "once: " << o.output;
  // An end pushed 9.9 mm toward the other of a 10 mm tube: converged, crushed 59-fold.
  const std::string tube = R"(units: {length: mm, force: N}
materials:
  carotid: {type: hgo, mu: 30 kPa, k1: 20 kPa, k2: 8, beta: 35 deg}
parts:
  wall: {element: axisymmetric_membrane, material: carotid, thickness: 0.5 mm, mesh: {type: line, from: [3 mm, 0 mm], to: [3 mm, 10 mm], elements: 10}}
boundary:
  base: {node_set: wall.start, dofs: [z]}
  pull: {node_set: wall.end, dofs: [z]}
loads:
  lumen: {type: pressure, part: wall}
steps:
  - {name: prestretch, increments: 5, set: {pull: -9.9 mm}}
)";
  const Outcome c = run_cli("run " + write_deck_file(kScratch, "tube.yaml", tube) + " -o " + testing::TempDir() +
                            kScratch + "-tube");
  EXPECT_NE(c.output.find("part 'wall' is crushed at r = "), std::string::npos) << c.output;
  EXPECT_NE(c.output.find("which no membrane reaches"), std::string::npos) << c.output;
  // The paper's rat aorta at 200 mmHg is neither.
  const Outcome ok = run_cli("run " + std::string(TUNICA_SOURCE_DIR) + "/examples/rat-aorta-inflation.yaml -o " +
                             testing::TempDir() + kScratch + "-aorta");
  EXPECT_EQ(ok.exit_code, 0) << ok.output;
  EXPECT_EQ(ok.output.find("grew"), std::string::npos) << ok.output;
  EXPECT_EQ(ok.output.find("crushed"), std::string::npos) << ok.output;
  EXPECT_EQ(ok.output.find("stretched"), std::string::npos) << ok.output;
}

TEST(JumpNotes, AStretchNoteSaysAlongWhichDirection) {
  const Model m = read_deck_text(kBalloon, "ball.yaml");
  // Axisymmetric points: λ1 = r/R (hoop), λ2 along the meridian.
  MembranePoint p;
  p.lambda = Eigen::Vector3d(0.4, 9.0, 1 / 3.6);
  p.x = Eigen::Vector3d(0.008, 1, 0);
  p.X = Eigen::Vector3d(0.02, 1, 0);
  const std::string meridian = extreme_stretch_note(m, 0, {p}, "at x");
  EXPECT_NE(meridian.find("part 'ball' is stretched 9-fold along the meridian at r = 0.008 mm"), std::string::npos)
      << meridian;
  p.lambda = Eigen::Vector3d(9.0, 1.2, 1 / 10.8);
  const std::string hoop = extreme_stretch_note(m, 0, {p}, "at x");
  EXPECT_NE(hoop.find("stretched 9-fold around the circumference (hoop)"), std::string::npos) << hoop;
}
