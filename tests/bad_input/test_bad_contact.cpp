// Bad input in the `rigid_surfaces` and `contact` sections: each error names the
// file, the line and the key, exits with 2 and prints one line. The base deck is the
// rat-aorta example with a rigid sleeve, a rigid polyline and a contact pair added.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "../support/capture.hpp"
#include "../support/cli.hpp"
#include "../support/deck_files.hpp"

using namespace tunica::test;
namespace fs = std::filesystem;

namespace {

const std::string kContactSections =
    "rigid_surfaces:\n"
    "  sleeve: {type: cylinder, radius: 1.2 mm, side: inside}\n"
    "  tip: {type: polyline, points: [[2 mm, 0], [0.5 mm, 0]]}\n"
    "contact:\n"
    "  wall_sleeve: {slave: wall, rigid: sleeve, penalty: 1e3 N/mm^3, offset: 0.01 mm}\n"
    "  wall_tip: {slave: wall.start, rigid: tip, penalty: 1e3}\n";

std::string base_deck(const std::string& example = "rat-aorta-inflation.yaml") {
  return read_text(std::string(TUNICA_SOURCE_DIR) + "/examples/" + example) + kContactSections;
}

const std::string kScratch = "tunica-bad-contact";

std::string write_deck(const std::string& name, const std::string& text) {
  return write_deck_file(kScratch, name, text);
}

void expect_error(const std::string& name, const std::string& from, const std::string& to, const std::string& key,
                  const std::string& what) {
  expect_check_error(kScratch, name, replace(base_deck(), from, to), to, key, what);
}

}  // namespace

TEST(BadContact, TheBaseDeckIsValid) {
  const Outcome o = run_cli("check " + write_deck("valid", base_deck()));
  EXPECT_EQ(o.exit_code, 0) << o.output;
}

TEST(BadContact, UnknownRigidSurface) {
  expect_error("unknown-rigid", "rigid: sleeve,", "rigid: sleve,", "contact.wall_sleeve.rigid",
               "undefined rigid surface 'sleve'");
}

TEST(BadContact, RigidKeyWithoutAValue) {  // `rigid:` present but empty: refused, not taken for absent
  expect_error("rigid-without-value", "rigid: sleeve,", "rigid: ,", "contact.wall_sleeve.rigid",
               "has no value");
}

TEST(BadContact, UnknownSlave) {
  expect_error("unknown-slave", "slave: wall,", "slave: wal,", "contact.wall_sleeve.slave",
               "undefined part or node set 'wal'");
}

TEST(BadContact, NegativePenalty) {
  expect_error("negative-penalty", "penalty: 1e3 N/mm^3", "penalty: -1e3 N/mm^3", "contact.wall_sleeve.penalty",
               "value -1e3 N/mm^3 (= -1000 N/mm³) is out of range (must be > 0 N/mm³)");
}

TEST(BadContact, PenaltyOfTheWrongDimension) {
  expect_error("penalty-unit", "penalty: 1e3 N/mm^3", "penalty: 1e3 kPa", "contact.wall_sleeve.penalty",
               "unit 'kPa' is not a pressure per length");
}

TEST(BadContact, NegativeOffset) {
  expect_error("negative-offset", "offset: 0.01 mm", "offset: -0.01 mm", "contact.wall_sleeve.offset",
               "value -0.01 mm is out of range (must be >= 0 mm)");
}

TEST(BadContact, PolylineWithOnePoint) {
  expect_error("one-point", "points: [[2 mm, 0], [0.5 mm, 0]]", "points: [[2 mm, 0]]", "rigid_surfaces.tip.points",
               "a polyline needs at least 2 points, got 1");
}

TEST(BadContact, CylinderWithoutRadius) {
  expect_error("no-radius", "{type: cylinder, radius: 1.2 mm, side: inside}", "{type: cylinder, side: inside}",
               "rigid_surfaces.sleeve.radius", "missing required key 'radius'");
}

TEST(BadContact, UnknownCylinderSide) {
  expect_error("bad-side", "side: inside}", "side: within}", "rigid_surfaces.sleeve.side", "within");
}

TEST(BadContact, UnknownSurfaceType) {
  expect_error("bad-type", "{type: cylinder,", "{type: cone,", "rigid_surfaces.sleeve.type",
               "unknown rigid surface type 'cone'");
}

TEST(BadContact, ContactNeedsAnAxisymmetricModel) {
  const std::string text = base_deck("rat-aorta-3d.yaml");
  expect_check_error(kScratch, "three-d", text, "  sleeve: {type: cylinder", "rigid_surfaces",
                     "need an axisymmetric model");
}

TEST(BadContact, HistoryOfAnUnknownContactPair) {
  const std::string text = replace(base_deck(), "  history:\n", "  history:\n    - {quantity: contact_force, contact: nope}\n");
  expect_check_error(kScratch, "history-contact", text, "contact: nope}", "output.history[0].contact",
                     "undefined contact pair 'nope'");
}

TEST(BadContact, HistoryNamingTheRigidSurfaceNamesThePairThatUsesIt) {
  const std::string text =
      replace(base_deck(), "  history:\n", "  history:\n    - {quantity: contact_force, contact: sleeve}\n");
  expect_check_error(kScratch, "history-contact-rigid", text, "contact: sleeve}", "output.history[0].contact",
                     "'sleeve' is a rigid surface, not a contact pair; the pair that uses it is `contact: wall_sleeve`");
}

// A rigid surface given the wrong way round: the slave starts behind it, and the penalty would push
// it through in the first increment. Refused at the pair's `rigid`, with the depth and the fix.
TEST(BadContact, SlaveBehindARigidCylinder) {
  // The wall (r = 0.763 mm) inside the sleeve (r = 1.2 mm), which `side: outside` puts behind it.
  const std::string text = replace(base_deck(), "side: inside}", "side: outside}");
  const Outcome o = expect_check_error(kScratch, "cylinder-wrong-side", text, "wall_sleeve: {slave: wall, rigid: sleeve",
                                       "contact.wall_sleeve.rigid",
                                       "contact pair 'wall_sleeve': 2 of the 2 slave nodes of 'wall' that face the "
                                       "rigid surface 'sleeve' lie behind it at the reference state, the deepest by "
                                       "0.437 mm");
  EXPECT_NE(o.output.find("`side: outside` keeps the slave at r ≥ 1.2 mm: if it belongs inside the cylinder, write `side: "
                 "inside` in rigid_surfaces.sleeve (line " +
                                 std::to_string(line_of(text, "  sleeve: {type: cylinder")) + ")"),
            std::string::npos)
      << o.output;
}

TEST(BadContact, SlaveBehindARigidPolylineListedTheWrongWay) {
  // A sleeve as a polyline running towards +z faces +r: the wall inside it is behind it.
  std::string text = replace(base_deck(), "tip: {type: polyline, points: [[2 mm, 0], [0.5 mm, 0]]}",
                             "tip: {type: polyline, points: [[1.2 mm, -1 mm], [1.2 mm, 2 mm]]}");
  text = replace(text, "wall_tip: {slave: wall.start, rigid: tip", "wall_tip: {slave: wall, rigid: tip");
  const Outcome o = expect_check_error(kScratch, "polyline-wrong-way", text, "wall_tip: {slave: wall, rigid: tip",
                                       "contact.wall_tip.rigid",
                                       "contact pair 'wall_tip': 2 of the 2 slave nodes of 'wall' that face the rigid "
                                       "surface 'tip' lie behind it at the reference state, the deepest by 0.437 mm");
  EXPECT_NE(o.output.find("list the points of rigid_surfaces.tip (line " + std::to_string(line_of(text, "  tip: {type: polyline")) +
                                 ") in the reverse order, `points: [[1.2 mm, 2 mm], [1.2 mm, -1 mm]]`"),
            std::string::npos)
      << o.output;
}

TEST(BadContact, SlaveJustBehindARigidSurfaceEverywhere) {
  // Behind by a hundredth of the element (1 mm) only, but every node that faces the surface is:
  // the wrong side, not round-off.
  const std::string text = replace(base_deck(), "points: [[2 mm, 0], [0.5 mm, 0]]", "points: [[2 mm, 0.01 mm], [0.5 mm, 0.01 mm]]");
  expect_check_error(kScratch, "polyline-just-behind", text, "wall_tip: {slave: wall.start, rigid: tip",
                     "contact.wall_tip.rigid",
                     "1 of the 1 slave nodes of 'wall.start' that face the rigid surface 'tip' lie behind it at the "
                     "reference state, the deepest by 0.01 mm");
}

TEST(BadContact, SlaveOnTheSurfaceOrAFewNodesJustBehindIsAccepted) {
  // The base deck's wall.start lies on the plane z = 0 (signed distance 0). A plane tilted so that
  // one of the wall's two nodes is a hundredth of an element behind and the other in front: a
  // minority just behind, which contact corrects, not the wrong side.
  std::string text = replace(base_deck(), "points: [[2 mm, 0], [0.5 mm, 0]]", "points: [[0.793 mm, -1 mm], [0.733 mm, 2 mm]]");
  text = replace(text, "wall_tip: {slave: wall.start, rigid: tip", "wall_tip: {slave: wall, rigid: tip");
  const Outcome o = run_cli("check " + write_deck("few-just-behind", text));
  EXPECT_EQ(o.exit_code, 0) << o.output;
}

TEST(BadContact, ASmoothingBeyondATenthOfTheElementLengthNamesTheValueToGive) {
  // The rat aorta's wall: 40 elements over its meridian; a smoothing of a metre, the unit typo.
  expect_error("smoothing-metres", "offset: 0.01 mm}", "offset: 0.01 mm, smoothing: 0.1 m}",
               "contact.wall_sleeve.smoothing", "is more than a tenth of the slave's mean element length");
  expect_error("smoothing-negative", "offset: 0.01 mm}", "offset: 0.01 mm, smoothing: -1e-4 mm}",
               "contact.wall_sleeve.smoothing", "smoothing");
}

TEST(BadContact, ASmallSmoothingIsValid) {
  const Outcome o = run_cli(
      "check " + write_deck("smoothing-ok", replace(base_deck(), "offset: 0.01 mm}", "offset: 0.01 mm, smoothing: 1e-4 mm}")));
  EXPECT_EQ(o.exit_code, 0) << o.output;
}
