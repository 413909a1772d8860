// A capsule balloon (Mooney–Rivlin, R 1 mm, H 0.05 mm) inflated to 0.5 MPa against a rigid sleeve
// of radius 1.3 mm with the user guide's penalty, 10⁵ N/mm³, in 10 increments and the default
// solver: the correction that first carries its nodes past the sleeve is taken whole (theory manual
// §7, entering contact), so no increment is cut back and none takes more than 8 iterations; the
// state it reaches obeys the penalty law, ε·penetration = p_c·λθλs, and the band in contact lies at the
// sleeve less the offset, plus that penetration.
#include <gtest/gtest.h>

#include <algorithm>

#include "../support/capture.hpp"

using namespace tunica;
using namespace tunica::test;

namespace {
const char* kDeck = R"(units: {length: mm, force: N}
materials:
  balloon: {type: mooney_rivlin, b1: 2.0 MPa, b2: 0.5 MPa}
parts:
  balloon:
    element: axisymmetric_membrane
    material: balloon
    thickness: 0.05 mm
    mesh:
      - {type: arc, center: [0 mm, 0 mm], radius: 1 mm, start_angle: -90 deg, end_angle: 0 deg, elements: 20}
      - {type: line, from: [1 mm, 0 mm], to: [1 mm, 4 mm], elements: 40}
      - {type: arc, center: [0 mm, 4 mm], radius: 1 mm, start_angle: 0 deg, end_angle: 90 deg, elements: 20}
boundary:
  south: {node_set: balloon.start, dofs: [r, z]}
  north: {node_set: balloon.end, dofs: [r]}
loads:
  inflation: {type: pressure, part: balloon}
rigid_surfaces:
  sleeve: {type: cylinder, radius: 1.3 mm, side: inside}
contact:
  balloon_sleeve: {slave: balloon, rigid: sleeve, penalty: 1e5 N/mm^3, offset: 0.025 mm}
steps:
  - {name: inflate, increments: 10, set: {inflation: 0.5 MPa}}
output:
  history:
    - {quantity: position_r, node_set: balloon.all, reduce: max, name: rmax, unit: mm}
    - {quantity: contact_pressure, contact: balloon_sleeve, unit: MPa, name: pc}
    - {quantity: contact_penetration, contact: balloon_sleeve, unit: mm, name: pen}
)";
}  // namespace

TEST(BalloonSleeve, FirstContactWithTheGuidesPenaltyConvergesWithoutCutBacks) {
  const Model m = read_deck_text(kDeck, "sleeve.yaml");
  Capture c;
  Analysis a(m);
  ASSERT_NO_THROW(a.run(c));
  EXPECT_EQ(c.cutbacks, 0);
  int most = 0;
  for (const auto& it : c.iterations) most = std::max(most, it.rec.iteration);
  EXPECT_LE(most, 8);
  const auto& end = c.rows.back().values;
  const double rmax = end[0], pc = end[1], pen = end[2];
  EXPECT_GT(pc, 0.1);   // pressed on the sleeve: most of the 0.5 MPa goes into it
  EXPECT_LT(pc, 0.5);   // and the hoop tension carries the rest
  // The penalty law per reference area, ε·pen; p_c is per current area, smaller by the area stretch
  // λθλs of the band (λθ = 1.275 here, λs between 1 and 2).
  EXPECT_GT(1e5 * pen, 1.27 * pc);
  EXPECT_LT(1e5 * pen, 2.6 * pc);
  EXPECT_NEAR(rmax, 1.3 - 0.025 + pen, 1e-9);   // on the sleeve less the offset
}

TEST(BalloonFloor, APoleOnAFlatSurfaceCarriesTheInflationPressure) {
  // A Mooney–Rivlin balloon (R 5 mm, H 0.1 mm) hung from its north pole and inflated to 9 kPa onto
  // a rigid floor 1 mm below its south pole: the flat patch on the floor carries p_c = p, its pole
  // node included (its consistent area, theory manual §9; the lumped 2π R L/2 is 0 on the axis,
  // and the pole went through the floor with p_c reported at 11.6 MPa).
  const Model m = read_deck_text(R"(units: {length: mm, force: N}
materials:
  latex: {type: mooney_rivlin, b1: 150 kPa, b2: 30 kPa}
parts:
  ball:
    element: axisymmetric_membrane
    material: latex
    thickness: 0.1 mm
    mesh: {type: arc, center: [0 mm, 0 mm], radius: 5 mm, start_angle: -90 deg, end_angle: 90 deg, elements: 60}
rigid_surfaces:
  floor: {type: polyline, points: [[20 mm, -6 mm], [0 mm, -6 mm]]}
contact:
  ball_floor: {slave: ball, rigid: floor, penalty: 1e3 N/mm^3, offset: 0.05 mm}
boundary:
  south: {node_set: ball.start, dofs: [r]}
  north: {node_set: ball.end, dofs: [r, z]}
loads:
  p: {type: pressure, part: ball}
steps:
  - {name: blow, increments: 20, set: {p: 9 kPa}}
output:
  history:
    - {quantity: contact_pressure, contact: ball_floor, unit: kPa}
    - {quantity: contact_penetration, contact: ball_floor, unit: mm}
    - {quantity: position_z, node_set: ball.start, unit: mm}
)",
                                 "floor.yaml");
  Capture c;
  Analysis a(m);
  ASSERT_NO_THROW(a.run(c));
  const auto& end = c.rows.back().values;
  EXPECT_NEAR(end[0], 9.0, 0.01);                 // the largest p_c, at the pole: p
  EXPECT_NEAR(end[1], 9e-3 / 1e3 * 1.4, 0.5e-5);  // ε·pen = p_c times the patch's area stretch (≈ 1.4)
  EXPECT_NEAR(end[2], -6 + 0.05 - end[1], 1e-7);  // the pole on the floor less the offset (to 1 % of pen)
}
