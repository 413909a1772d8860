// Bad constants of the HGO and Ogden materials: a clear one-line message naming
// the file, the line and the key, exit 2 and no crash. Each test runs the real
// `tunica check` on the rat-aorta example deck with its material replaced.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "../support/capture.hpp"
#include "../support/cli.hpp"
#include "../support/deck_files.hpp"

using namespace tunica::test;
namespace fs = std::filesystem;

namespace {

const std::string kExample = std::string(TUNICA_SOURCE_DIR) + "/examples/rat-aorta-inflation.yaml";

/// The example deck with the material `aorta` given by `body` (lines indented by four spaces).
std::string deck_with_material(const std::string& body) {
  const std::string text = read_text(kExample);
  const auto begin = text.find("    type: fung");
  const auto end = text.find("\nparts:");
  if (begin == std::string::npos || end == std::string::npos) throw std::runtime_error("example deck changed");
  return text.substr(0, begin) + body + "\n" + text.substr(end);
}

const std::string kScratch = "tunica-bad-materials-" + std::to_string(getpid());

std::string write_deck(const std::string& name, const std::string& text) {
  return write_deck_file(kScratch, name, text);
}

/// Checks the deck with material `body`; expects exit 2 and "<file>:<line of line_text>:...key '<key>'...<what>".
void expect_error(const std::string& name, const std::string& body, const std::string& line_text,
                  const std::string& key, const std::string& what) {
  const Outcome o = expect_check_error(kScratch, name, deck_with_material(body), line_text, key, what);
  EXPECT_EQ(o.output.find("terminate called"), std::string::npos) << o.output;
}

const std::string kHgo =
    "    type: hgo\n    mu: 3 kPa\n    k1: 2.3632 kPa\n    k2: 0.8393\n    beta: 29 deg\n    kappa: 0.2\n";
const std::string kOgden =
    "    type: ogden\n    mu: [0.63 MPa, 0.0012 MPa, -0.01 MPa]\n    alpha: [1.3, 5.0, -2.0]\n";

}  // namespace

TEST(BadMaterials, ValidHgoAndOgdenDecks) {
  for (const auto& [name, body] : {std::pair{"hgo", kHgo}, std::pair{"ogden", kOgden},
                                   std::pair{"hgo-90deg", replace(kHgo, "29 deg", "90 deg")},
                                   std::pair{"ogden-kpa", replace(kOgden, "0.0012 MPa", "1.2 kPa")}}) {
    const Outcome o = run_cli("check " + write_deck(std::string("valid-") + name, deck_with_material(body)));
    EXPECT_EQ(o.exit_code, 0) << name << ": " << o.output;
    EXPECT_NE(o.output.find("valid deck"), std::string::npos) << o.output;
  }
}

TEST(BadMaterials, OgdenListLengthMismatch) {
  expect_error("ogden-length", replace(kOgden, "[1.3, 5.0, -2.0]", "[1.3, 5.0]"), "alpha: [1.3, 5.0]",
               "materials.aorta.alpha", "as many alpha as mu values: 3 mu, 2 alpha");
}

TEST(BadMaterials, OgdenTooManyTerms) {
  expect_error("ogden-nine", "    type: ogden\n    mu: [1, 1, 1, 1, 1, 1, 1, 1, 1]\n    alpha: [2, 2, 2, 2, 2, 2, 2, 2, 2]\n",
               "mu: [1, 1", "materials.aorta.mu", "Ogden needs 1 to 8 terms, got 9");
}

TEST(BadMaterials, OgdenEmptyList) {
  expect_error("ogden-empty", "    type: ogden\n    mu: []\n    alpha: []\n", "mu: []", "materials.aorta.mu",
               "Ogden needs 1 to 8 terms, got 0");
}

TEST(BadMaterials, OgdenZeroExponent) {
  expect_error("ogden-alpha-zero", replace(kOgden, "[1.3, 5.0, -2.0]", "[1.3, 0, -2.0]"), "alpha: [1.3, 0",
               "materials.aorta.alpha", "alpha #2 is 0");
}

TEST(BadMaterials, OgdenShearModulusNotPositive) {
  // ½ (0.1·2 − 0.3·1) = −0.05
  expect_error("ogden-shear", "    type: ogden\n    mu: [0.1 MPa, -0.3 MPa]\n    alpha: [2, 1]\n", "mu: [0.1 MPa",
               "materials.aorta.mu", "initial shear modulus ½ Σ mu_p alpha_p = -0.05 must be positive");
}

TEST(BadMaterials, OgdenScalarInsteadOfList) {
  expect_error("ogden-scalar", "    type: ogden\n    mu: 0.63 MPa\n    alpha: [1.3]\n", "mu: 0.63 MPa",
               "materials.aorta.mu", "expected a list of pressure");
}

TEST(BadMaterials, OgdenWrongUnitInList) {
  expect_error("ogden-unit", replace(kOgden, "0.0012 MPa", "0.0012 mm"), "mu: [0.63 MPa", "materials.aorta.mu[1]",
               "unit 'mm' is not a pressure");
}

TEST(BadMaterials, HgoK2NotPositive) {
  expect_error("hgo-k2", replace(kHgo, "k2: 0.8393", "k2: 0"), "k2: 0", "materials.aorta.k2",
               "value 0 is out of range (must be > 0)");
}

TEST(BadMaterials, HgoDispersionAboveOneThird) {
  expect_error("hgo-kappa", replace(kHgo, "kappa: 0.2", "kappa: 0.4"), "kappa: 0.4", "materials.aorta.kappa",
               "value 0.4 is out of range (must be >= 0, <= 0.333333): κ runs from 0 (the fibres perfectly aligned "
               "along ±β) to 1/3 (isotropic dispersion");
  // The bounds are explained, and another paper's convention named.
  expect_error("hgo-kappa-convention", replace(kHgo, "kappa: 0.2", "kappa: 0.45"), "kappa: 0.45", "materials.aorta.kappa",
               "Some papers use another convention (an in-plane dispersion up to 1/2");
}

TEST(BadMaterials, HgoNegativeK1) {
  expect_error("hgo-k1", replace(kHgo, "k1: 2.3632 kPa", "k1: -2.3632 kPa"), "k1: -2.3632 kPa", "materials.aorta.k1",
               "value -2.3632 kPa (= -0.0023632 N/mm²) is out of range (must be >= 0 N/mm²)");
}

TEST(BadMaterials, HgoFibreAngleWithoutUnitIsRadiansAndOutOfRange) {
  // `beta: 39.98` without `deg` is 39.98 rad: refused rather than silently used, with the fix.
  expect_error("hgo-beta", replace(kHgo, "beta: 29 deg", "beta: 39.98"), "beta: 39.98", "materials.aorta.beta",
               "value 39.98 is out of range (must be >= 0, <= 1.5708 rad): a plain number is radians; for degrees "
               "write `39.98 deg`");
}
