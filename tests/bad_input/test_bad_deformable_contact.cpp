// Bad input in contact pairs with a deformable master (`master`): each error names
// the file, the line and the key, exits with 2 and prints one line. The base deck:
// a tube inflated inside another (deformable pair) and the outer tube in a rigid sleeve.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "../support/capture.hpp"
#include "../support/cli.hpp"
#include "../support/deck_files.hpp"

using namespace tunica::test;
namespace fs = std::filesystem;

namespace {

const std::string kBase = R"(title: two tubes
units: {length: mm, force: N}
materials:
  soft: {type: neo_hookean, mu: 0.1 MPa}
parts:
  balloon:
    element: axisymmetric_membrane
    material: soft
    thickness: 0.1 mm
    mesh: {type: line, from: [1, 0], to: [1, 1], elements: 4}
  artery:
    element: axisymmetric_membrane
    material: soft
    thickness: 0.1 mm
    mesh: {type: line, from: [1.2, 0], to: [1.2, 1], elements: 4}
node_sets:
  rim: {part: artery, nodes: [0, 1, 2]}
boundary:
  b0: {node_set: balloon.all, dofs: [z]}
  a0: {node_set: artery.all, dofs: [z]}
loads:
  lumen: {type: pressure, part: balloon}
rigid_surfaces:
  sleeve: {type: cylinder, radius: 2 mm, side: inside}
contact:
  press: {slave: balloon, master: artery, master_orientation: reversed, penalty: 1e3, offset: 0.1 mm}
  cage: {slave: artery, rigid: sleeve, penalty: 1e3}
steps:
  - {name: inflate, increments: 1, set: {lumen: 0.001}}
)";

const std::string kScratch = "tunica-bad-deformable-contact";

std::string write_deck(const std::string& name, const std::string& text) {
  return write_deck_file(kScratch, name, text);
}

/// Replaces `from` by `to` in the base deck; the error is on the line of `to`.
void expect_error(const std::string& name, const std::string& from, const std::string& to, const std::string& key,
                  const std::string& what) {
  expect_check_error(kScratch, name, replace(kBase, from, to), to, key, what);
}

/// The master is the node set `rim` with the node indices `nodes`.
std::string with_rim(const std::string& nodes) {
  return replace(replace(kBase, "rim: {part: artery, nodes: [0, 1, 2]}", "rim: {part: artery, nodes: " + nodes + "}"),
                 "master: artery,", "master: rim,");
}

}  // namespace

TEST(BadDeformableContact, TheBaseDeckIsValid) {
  const Outcome o = run_cli("check " + write_deck("valid", kBase));
  EXPECT_EQ(o.exit_code, 0) << o.output;
}

TEST(BadDeformableContact, BothRigidAndMaster) {
  expect_error("both", "master: artery,", "rigid: sleeve, master: artery,", "contact.press.master",
               "either `rigid: <surface>` or `master: <part or node set>`, not both");
}

TEST(BadDeformableContact, NeitherRigidNorMaster) {
  expect_error("neither", "press: {slave: balloon, master: artery, master_orientation: reversed,",
               "press: {slave: balloon,", "contact.press", "needs `rigid: <surface>`");
}

TEST(BadDeformableContact, UnknownMaster) {
  expect_error("unknown-master", "master: artery,", "master: arterie,", "contact.press.master",
               "undefined part or node set 'arterie'");
}

TEST(BadDeformableContact, MasterChainOfOneNode) {
  expect_error("one-node", "master: artery,", "master: artery.start,", "contact.press.master",
               "the master chain 'artery.start' has 1 node; it needs at least 2");
}

TEST(BadDeformableContact, SlaveChainOfOneNode) {
  expect_error("one-slave-node", "slave: balloon, master", "slave: balloon.end, master", "contact.press.slave",
               "the slave chain 'balloon.end' has 1 node; it needs at least 2");
}

TEST(BadDeformableContact, MasterIsTheSlave) {
  expect_error("self", "master: artery,", "master: balloon,", "contact.press.master",
               "the master is the slave 'balloon' (self-contact is not supported)");
}

TEST(BadDeformableContact, MasterSharesNodesWithTheSlave) {
  expect_error("shared", "slave: balloon, master: artery,", "slave: artery, master: rim,", "contact.press.master",
               "the master 'rim' and the slave 'artery' share a node (master node 0)");
}

// A master chain that repeats a node (a zero-length segment, or a chain that turns back on itself)
// is refused where its node set lists the node twice, before the contact pair is read (the
// pair's own check of its chain stays for chains built otherwise).
TEST(BadDeformableContact, ZeroLengthMasterSegment) {
  expect_check_error(kScratch, "zero-length", with_rim("[0, 1, 1, 2]"), "rim: {part: artery", "node_sets.rim.nodes[2]",
                     "node set 'rim' lists node 1 twice: first as nodes[1]");
}

TEST(BadDeformableContact, MasterNodeListedTwice) {
  expect_check_error(kScratch, "twice", with_rim("[0, 1, 0]"), "rim: {part: artery", "node_sets.rim.nodes[2]",
                     "node set 'rim' lists node 0 twice: first as nodes[0]");
}

TEST(BadDeformableContact, OrientationOfARigidSurface) {
  expect_error("rigid-orientation", "rigid: sleeve,", "rigid: sleeve, master_orientation: reversed,",
               "contact.cage.master_orientation", "only a deformable `master` has an orientation");
}

TEST(BadDeformableContact, UnknownOrientation) {
  expect_error("bad-orientation", "master_orientation: reversed,", "master_orientation: backwards,",
               "contact.press.master_orientation", "backwards");
}

TEST(BadDeformableContact, MasterSurfaceOfARigidSurface) {
  expect_error("rigid-master-surface", "rigid: sleeve,", "rigid: sleeve, master_surface: faceted,",
               "contact.cage.master_surface", "only a deformable `master` has a surface choice");
}

TEST(BadDeformableContact, UnknownMasterSurface) {
  expect_error("bad-master-surface", "master_orientation: reversed,",
               "master_orientation: reversed, master_surface: spline,", "contact.press.master_surface", "spline");
}

TEST(BadDeformableContact, SlaveBehindTheMaster) {
  // The artery meshed towards +z faces +r: as given, the balloon inside it is behind it.
  expect_error("behind", "master_orientation: reversed,", "master_orientation: as_given,",
               "contact.press.master_orientation",
               "slave node 0 of 'balloon' lies behind the master 'artery' (signed distance -0.2 mm at the reference state");
  expect_error("behind-default", "master: artery, master_orientation: reversed,", "master: artery,", "contact.press.master",
               "reverse `master_orientation`");
}

TEST(BadDeformableContact, TwoPassesOnARigidPair) {
  expect_error("rigid-two-passes", "rigid: sleeve,", "rigid: sleeve, passes: 2,", "contact.cage.passes",
               "a rigid pair has one pass: a rigid surface has no nodes to push back on the slave");
}

TEST(BadDeformableContact, ThreePasses) {
  expect_error("three-passes", "master_orientation: reversed,", "master_orientation: reversed, passes: 3,",
               "contact.press.passes", "passes");
}
