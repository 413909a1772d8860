// Spherical balloons as 3-D membranes (examples/balloon-sphere-3d.yaml: an
// octant of 4-node membranes with symmetry planes) inflated by volume control
// through the pressure maximum to λ > 2, against theory manual (8.3):
//   neo-Hookean    p = 2μ(H/R)(λ⁻¹ − λ⁻⁷),
//   Mooney–Rivlin  p = 4(H/R)(λ⁻¹ − λ⁻⁷)(b1 + b2λ²),
// with λ = (V/V₀)^⅓ from the enclosed volume of the faceted octant; and the
// error's rate under mesh refinement.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "../support/capture.hpp"

using namespace tunica;
using namespace tunica::test;

namespace {

const std::string kDeck = std::string(TUNICA_SOURCE_DIR) + "/examples/balloon-sphere-3d.yaml";

struct Path {
  double max_error = 0;        ///< largest relative pressure error over the path
  double lambda_at_peak = 0;   ///< λ of the largest FE pressure
  double last_lambda = 0;
  bool rose_then_fell = false;
  int cutbacks = 0, max_iterations = 0;
};

Path run(const std::string& text, const std::function<double(double)>& p_of_lambda) {
  const Model m = read_deck_text(text, kDeck);
  Capture cap;
  Analysis a(m);
  a.run(cap);
  const int p = Capture::column(m, "pressure_kPa"), v = Capture::column(m, "volume_mm3");
  Path path;
  path.cutbacks = cap.cutbacks;
  const double V0 = cap.rows.front().values[v];
  double pmax = 0;
  for (const Row& row : cap.rows) {
    if (row.info.step == 0) continue;
    const double lambda = std::cbrt(row.values[v] / V0);
    const double exact = p_of_lambda(lambda) * 1e3;  // MPa → kPa
    path.max_error = std::max(path.max_error, std::abs(row.values[p] - exact) / exact);
    if (row.values[p] > pmax) {
      pmax = row.values[p];
      path.lambda_at_peak = lambda;
    }
    path.last_lambda = lambda;
    if (row.values[p] < 0.97 * pmax) path.rose_then_fell = true;  // past the peak by 3 %
  }
  for (const auto& it : cap.iterations) path.max_iterations = std::max(path.max_iterations, it.rec.iteration);
  return path;
}

double neo_hookean(double l) { return 2 * 1.0 * 0.01 * (1 / l - std::pow(l, -7)); }

}  // namespace

TEST(Sphere3d, NeoHookeanBalloonFollowsTheClosedFormThroughItsPressureMaximum) {
  const Path p = run(read_text(kDeck), neo_hookean);
  std::printf("neo-Hookean octant n = 8: max relative pressure error %.3e, peak at λ = %.4f (exact %.4f), last λ = %.4f, "
              "iterations ≤ %d\n", p.max_error, p.lambda_at_peak, std::pow(7.0, 1.0 / 6.0), p.last_lambda, p.max_iterations);
  EXPECT_EQ(p.cutbacks, 0);
  EXPECT_TRUE(p.rose_then_fell);
  EXPECT_GE(p.last_lambda, 2.0);
  EXPECT_NEAR(p.lambda_at_peak, std::pow(7.0, 1.0 / 6.0), 0.05);
  EXPECT_LT(p.max_error, 5e-3);
  EXPECT_LE(p.max_iterations, 6);
}

TEST(Sphere3d, TriangleOctantFollowsTheClosedFormToo) {
  const Path p = run(replace(read_text(kDeck), "n: 8}", "n: 8, shape: triangle}"), neo_hookean);
  std::printf("neo-Hookean triangle octant n = 8: max relative pressure error %.3e, peak at λ = %.4f, last λ = %.4f\n",
              p.max_error, p.lambda_at_peak, p.last_lambda);
  EXPECT_EQ(p.cutbacks, 0);
  EXPECT_TRUE(p.rose_then_fell);
  EXPECT_GE(p.last_lambda, 2.0);
  EXPECT_LT(p.max_error, 1e-2);
}

TEST(Sphere3d, MooneyRivlinBalloonFollowsTheClosedFormOnBothSidesOfThePeak) {
  const double b1 = 0.5 / 1.1, b2 = 0.05 / 1.1;
  const std::string deck = replace(read_text(kDeck), "{type: neo_hookean, mu: 1 MPa}",
                                   "{type: mooney_rivlin, b1: " + std::to_string(b1) + " MPa, b2: " +
                                       std::to_string(b2) + " MPa}");
  const auto mr = [&](double l) { return 4 * 0.01 * (1 / l - std::pow(l, -7)) * (b1 + b2 * l * l); };
  const Path p = run(deck, mr);
  std::printf("Mooney-Rivlin octant n = 8: max relative pressure error %.3e, peak at λ = %.4f, last λ = %.4f\n",
              p.max_error, p.lambda_at_peak, p.last_lambda);
  double lpeak = 1, best = 0;  // the closed form's peak, by scanning
  for (double l = 1.0; l < 2.0; l += 1e-5)
    if (mr(l) > best) best = mr(l), lpeak = l;
  EXPECT_EQ(p.cutbacks, 0);
  EXPECT_TRUE(p.rose_then_fell);
  EXPECT_GE(p.last_lambda, 2.0);
  EXPECT_NEAR(p.lambda_at_peak, lpeak, 0.05);
  EXPECT_LT(p.max_error, 5e-3);
}

TEST(Sphere3d, ErrorFallsAtSecondOrderUnderMeshRefinement) {
  double e[3];
  const int n[3] = {4, 8, 16};
  for (int k = 0; k < 3; ++k)
    e[k] = run(replace(read_text(kDeck), "n: 8}", "n: " + std::to_string(n[k]) + "}"), neo_hookean).max_error;
  const double r1 = std::log2(e[0] / e[1]), r2 = std::log2(e[1] / e[2]);
  std::printf("octant max relative pressure error: n = 4 %.3e, 8 %.3e, 16 %.3e; rates %.3f, %.3f\n", e[0], e[1], e[2], r1,
              r2);
  EXPECT_GT(r1, 1.7);
  EXPECT_GT(r2, 1.7);
}
