// Thin spherical balloons (theory manual (8.3)) modelled as axisymmetric spheres below
// their pressure maximum: neo-Hookean p = 2μ(H/R)(λ⁻¹ − λ⁻⁷) and Mooney–Rivlin
// p = 4(H/R)(λ⁻¹ − λ⁻⁷)(b1 + b2λ²), with λ the equator stretch; and the error's
// rate under mesh refinement (the faceted meridian converges at O(h²): 7.1e-3,
// 1.8e-3, 4.4e-4 for 10, 20, 40 elements; 7e-5 with the example's 100).
#include <gtest/gtest.h>

#include <cmath>

#include "../support/capture.hpp"

using namespace tunica;
using namespace tunica::test;

namespace {

const std::string kDeck = std::string(TUNICA_SOURCE_DIR) + "/examples/balloon-sphere.yaml";

/// Largest relative error of the FE pressure against p(λ) over all increments.
double max_error(const std::string& deck, const std::function<double(double)>& p_of_lambda, int* cutbacks = nullptr) {
  const Model m = read_deck_text(deck, kDeck);
  Capture c;
  Analysis a(m);
  a.run(c);
  if (cutbacks) *cutbacks = c.cutbacks;
  const int p = Capture::column(m, "pressure_kPa"), r = Capture::column(m, "equator_radius_mm");
  double err = 0;
  for (const Row& row : c.rows) {
    if (row.info.step == 0) continue;
    const double lambda = row.values[r] / 1.0;  // R = 1 mm
    const double exact = p_of_lambda(lambda) * 1e3;  // MPa → kPa
    err = std::max(err, std::abs(row.values[p] - exact) / exact);
  }
  return err;
}

double neo_hookean(double l) { return 2 * 1.0 * 0.01 * (1 / l - std::pow(l, -7)); }

std::string with_elements(int n) { return replace(read_text(kDeck), "elements: 100}", "elements: " + std::to_string(n) + "}"); }

}  // namespace

TEST(Sphere, NeoHookeanBalloonMatchesTheClosedFormBelowItsPressureMaximum) {
  int cutbacks = -1;
  EXPECT_LT(max_error(read_text(kDeck), neo_hookean, &cutbacks), 1e-4);
  EXPECT_EQ(cutbacks, 0);
}

TEST(Sphere, MooneyRivlinBalloonMatchesTheClosedForm) {
  // b1 + b2 = μ/2 (same small-strain shear modulus), b2/b1 = 0.1; MR has no pressure
  // maximum below λ ≈ 1.9 for b2/b1 = 0.1, so load to 0.012 MPa.
  const double b1 = 0.5 / 1.1, b2 = 0.05 / 1.1;
  std::string deck = replace(read_text(kDeck), "{type: neo_hookean, mu: 1 MPa}",
                             "{type: mooney_rivlin, b1: " + std::to_string(b1) + " MPa, b2: " + std::to_string(b2) + " MPa}");
  deck = replace(deck, "{inflation: 0.0118 MPa}", "{inflation: 0.0125 MPa}");
  const auto mr = [&](double l) { return 4 * 0.01 * (1 / l - std::pow(l, -7)) * (b1 + b2 * l * l); };
  EXPECT_LT(max_error(deck, mr), 1e-4);
}

TEST(Sphere, ErrorFallsAtSecondOrderUnderMeshRefinement) {
  const double e10 = max_error(with_elements(10), neo_hookean);
  const double e20 = max_error(with_elements(20), neo_hookean);
  const double e40 = max_error(with_elements(40), neo_hookean);
  const double rate1 = std::log2(e10 / e20), rate2 = std::log2(e20 / e40);
  std::printf("sphere max relative error: 10 el %.3e, 20 el %.3e, 40 el %.3e; rates %.3f, %.3f\n", e10, e20, e40, rate1,
              rate2);
  EXPECT_NEAR(rate1, 2.0, 0.15);
  EXPECT_NEAR(rate2, 2.0, 0.15);
}
