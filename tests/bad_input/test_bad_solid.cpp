// Bad input for axisymmetric solid parts and `enter_step`: each error names the file, the line
// and the key, exits with 2 and prints one line. The base deck is the artery with a plaque of
// tests/support/solid_decks.hpp.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "../support/capture.hpp"
#include "../support/cli.hpp"
#include "../support/deck_files.hpp"
#include "../support/solid_decks.hpp"

using namespace tunica::test;
namespace fs = std::filesystem;

namespace {

const std::string kScratch = "tunica-bad-solid";

std::string write_deck(const std::string& name, const std::string& text) {
  return write_deck_file(kScratch, name, text);
}

/// Replaces `from` by `to` in the base deck; the error must be on the line holding `at` (default `to`).
void expect_error(const std::string& name, const std::string& from, const std::string& to, const std::string& key,
                  const std::string& what, const std::string& at = "") {
  expect_check_error(kScratch, name, replace(kArteryWithPlaque, from, to), at.empty() ? to : at, key, what);
}

}  // namespace

TEST(BadSolid, TheBaseDeckIsValid) {
  const Outcome o = run_cli("check " + write_deck("valid", kArteryWithPlaque));
  EXPECT_EQ(o.exit_code, 0) << o.output;
}

TEST(BadSolid, MembraneMaterialOnASolidPart) {
  expect_error("membrane-material", "    material: plaque\n", "    material: wall\n", "parts.plaque.material",
               "'wall' is a membrane material (type neo_hookean); an axisymmetric_solid part needs a solid material",
               "    material: wall\n    mesh:");
}

TEST(BadSolid, SolidMaterialOnAMembranePart) {
  expect_error("solid-material", "    material: wall\n", "    material: plaque\n", "parts.artery.material",
               "'plaque' is a solid material (type neo_hookean_solid); a axisymmetric_membrane part needs a membrane material");
}

TEST(BadSolid, UnknownEnterStep) {
  expect_error("unknown-step", "enter_step: squeeze", "enter_step: squash", "parts.plaque.enter_step",
               "unknown step 'squash' (the steps are: prestretch, squeeze)");
}

TEST(BadSolid, UnknownFormulation) {
  expect_error("formulation", "    element: axisymmetric_solid\n", "    element: axisymmetric_solid\n    formulation: mixed\n",
               "parts.plaque.formulation", "mixed", "formulation: mixed");
}

TEST(BadSolid, InnerRadiusNotBelowTheOuterOne) {
  expect_error("inner-outer", "      outer: 0.9\n", "      outer: 0.8\n", "parts.plaque.mesh",
               "the inner radius 0.85 is not below the outer radius 0.8 at z = 0.5", "      type: grid");
}

TEST(BadSolid, NonPositiveRadius) {
  expect_error("negative-radius", "inner: {radius_ends: 0.85, radius_centre: 0.6, shape: cosine}",
               "inner: [[0.5, 0.5], [-0.1, 1.5]]", "parts.plaque.mesh", "is not positive", "      type: grid");
}

TEST(BadSolid, CircularArcTooDeep) {
  expect_error("deep-arc", "inner: {radius_ends: 0.85, radius_centre: 0.6, shape: cosine}",
               "inner: {radius_ends: 0.85, radius_centre: 0.3, shape: circular}", "parts.plaque.mesh",
               "a circular profile needs", "      type: grid");
}

TEST(BadSolid, PressureOnASolidPart) {
  expect_error("pressure-on-solid", "lumen: {type: pressure, part: artery}", "lumen: {type: pressure, part: plaque}",
               "loads.lumen.part", "is a solid: pressure loads act on membrane parts");
}

TEST(BadSolid, BoundarySetBeforeThePartEnters) {
  expect_error("set-before-entry", "set: {stretch: 0.2, lumen: 0.005}", "set: {stretch: 0.2, lumen: 0.005, plaque_push: 0.01}",
               "steps[0].set.plaque_push", "acts on part 'plaque', which enters in step 2 'squeeze'");
}

TEST(BadSolid, MembraneQuantityOfASolidPart) {
  expect_error("membrane-quantity", "{quantity: sigma_zz, part: plaque, reduce: min, name: szz_min}",
               "{quantity: lambda_1, part: plaque, reduce: min, name: szz_min}", "output.history[0].quantity",
               "'lambda_1' is a membrane quantity; part 'plaque' is a solid");
}

TEST(BadSolid, StartOfASolidPart) {
  expect_error("solid-start", "boundary:\n", "node_sets:\n  tip: {part: plaque, nodes: start}\nboundary:\n",
               "node_sets.tip.nodes", "a solid part has no start or end", "  tip: {part: plaque, nodes: start}");
}
