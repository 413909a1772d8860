// Bad input for axisymmetric shell parts (io/deck_shell_parts.hpp) and their slope DOFs:
// each error names the file, the line and the key, exits with 2 and prints one line. The
// base deck is tests/support/shell_decks.hpp.
#include <gtest/gtest.h>

#include "../support/capture.hpp"
#include "../support/cli.hpp"
#include "../support/deck_files.hpp"
#include "../support/shell_decks.hpp"

using namespace tunica::test;

namespace {

const std::string kScratch = "tunica-bad-shell";

std::string write_deck(const std::string& name, const std::string& text) {
  return write_deck_file(kScratch, name, text);
}

/// Replaces `from` by `to` in the base deck; the error must be on the line holding `at` (default `to`).
void expect_error(const std::string& name, const std::string& from, const std::string& to, const std::string& key,
                  const std::string& what, const std::string& at = "") {
  expect_check_error(kScratch, name, replace(kShellArteryBalloon, from, to), at.empty() ? to : at, key, what);
}

}  // namespace

TEST(BadShell, TheBaseDeckIsValid) {
  const Outcome o = run_cli("check " + write_deck("valid", kShellArteryBalloon));
  EXPECT_EQ(o.exit_code, 0) << o.output;
}

TEST(BadShell, UnknownKeyOnAShellPart) {
  expect_error("unknown-key", "    thickness_points: 3\n", "    layers: 3\n", "parts.balloon.layers",
               "unknown key 'layers'");
}

TEST(BadShell, TooFewThicknessPoints) {
  expect_error("one-layer", "    thickness_points: 3\n", "    thickness_points: 1\n", "parts.balloon.thickness_points",
               "thickness_points");
}

TEST(BadShell, TooManyMeridianPoints) {
  expect_error("meridian-points", "    thickness_points: 3\n", "    meridian_points: 17\n",
               "parts.balloon.meridian_points", "meridian_points");
}

TEST(BadShell, ThicknessBeyondTheRadiusOfCurvature) {
  expect_error("too-thick", "    thickness: 0.08\n", "    thickness: 1.7\n", "parts.balloon.thickness",
               "shell part 'balloon', element 1: the thickness 1.7 does not fit the curvature of the reference "
               "meridian");
}

TEST(BadShell, SlopeDofOnAMembrane) {
  expect_error("membrane-slope", "cuff_base: {node_set: cuff.start, dofs: [z]}",
               "cuff_base: {node_set: cuff.start, dofs: [z, slope_r]}", "boundary.cuff_base.dofs[1]",
               "node set 'cuff.start' has nodes without slopes (only nodes of axisymmetric_shell parts have slope_r "
               "and slope_z)");
}

TEST(BadShell, UnknownDofNamesTheSlopes) {
  expect_error("bad-dof", "dofs: [r, z, slope_z]", "dofs: [r, z, rotation]", "boundary.poles.dofs[2]",
               "unknown DOF 'rotation' (axisymmetric DOFs are r and z, and slope_r and slope_z on shells)");
}

TEST(BadShell, NonZeroValueOnABoundaryMixingSlopesAndPositions) {
  expect_error("mixed-value", "{name: inflate, increments: 8, set: {inflation: 0.16}}",
               "{name: inflate, increments: 8, set: {inflation: 0.16, poles: 0.01}}", "steps[1].set.poles",
               "boundary 'poles' holds slopes and positions: it can only be 0");
}

TEST(BadShell, ShellQuantityOfAMembranePart) {
  expect_error("moment-of-membrane", "{quantity: M_2, part: artery, reduce: max, name: M_s_max, unit: N}",
               "{quantity: M_2, part: cuff, reduce: max, name: M_s_max, unit: N}", "output.history[3].quantity",
               "'M_2' is a quantity of axisymmetric_shell parts; part 'cuff' is an axisymmetric_membrane part");
}

TEST(BadShell, SlopeQuantityOfAMembraneNodeSet) {
  expect_error("slope-of-membrane", "{quantity: M_2, part: artery, reduce: max, name: M_s_max, unit: N}",
               "{quantity: reaction_slope_r, node_set: cuff.start, name: M_cuff}", "output.history[3].node_set",
               "'reaction_slope_r' is a quantity of axisymmetric_shell nodes; node");
}
