// The paper's first example (theory manual §12.1, paper §4.1): the rat-aorta deck
// against the thin-tube closed form, with 1 and 50 elements, and the Newton
// convergence the paper reports (Table 1).
#include <gtest/gtest.h>

#include <cmath>

#include "../support/capture.hpp"

using namespace tunica;
using namespace tunica::test;

namespace {

const std::string kDeck = std::string(TUNICA_SOURCE_DIR) + "/examples/rat-aorta-inflation.yaml";

// Independent closed form (theory manual (3.2), (8.1)), written out here rather than taken from the material classes.
constexpr double c = 61.163, a1 = 0.68238, a2 = 0.60558, a4 = 0.1067;  // kPa
constexpr double R = 0.763, H = 0.122, lz = 1.6;                          // mm
constexpr double mmHg_kPa = 0.133322387415;  // UDUNITS-2's mmHg

double S1(double E1, double E2) { return 2 * c * (a1 * E1 + a4 * E2) * std::exp(a1 * E1 * E1 + a2 * E2 * E2 + 2 * a4 * E1 * E2); }
double S2(double E1, double E2) { return 2 * c * (a4 * E1 + a2 * E2) * std::exp(a1 * E1 * E1 + a2 * E2 * E2 + 2 * a4 * E1 * E2); }

/// E_θ with S1(E_θ, E_z) = target, by bisection (S1 increases with E1).
double solve_E_theta(double target, double Ez) {
  double lo = -0.49, hi = 3.0;
  for (int k = 0; k < 200; ++k) {
    const double mid = 0.5 * (lo + hi);
    (S1(mid, Ez) < target ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

struct Result {
  Model model;
  Capture capture;
};

Result run(const std::string& text) {
  Result r{read_deck_text(text, kDeck), {}};
  Analysis a(r.model);
  a.run(r.capture);
  return r;
}

double rel(double a, double b) { return std::abs(a - b) / std::max(std::abs(b), 1e-12); }

void expect_closed_form(const Result& r, int elements) {
  const Model& m = r.model;
  const int p = Capture::column(m, "pressure_mmHg"), lt = Capture::column(m, "lambda_theta"),
            st = Capture::column(m, "S_theta_kPa"), sz = Capture::column(m, "S_z_kPa"),
            ez = Capture::column(m, "E_z"), h = Capture::column(m, "thickness_mm"),
            rad = Capture::column(m, "radius_mm"), F = Capture::column(m, "axial_force_N");
  int checked = 0;
  for (const Row& row : r.capture.rows) {
    if (row.info.step != 2) continue;
    const double pk = row.values[p] * mmHg_kPa;
    const double Ez = 0.5 * (lz * lz - 1);
    ASSERT_NEAR(row.values[ez], Ez, 1e-12);
    const double St = pk * R * lz / H;  // p r = σθ h  ⇔  Sθ = p R λz / H
    const double Et = solve_E_theta(St, Ez);
    const double lt_exact = std::sqrt(2 * Et + 1);
    EXPECT_LT(rel(row.values[lt], lt_exact), 1e-6) << elements << " elements, p = " << row.values[p];
    EXPECT_LT(std::abs(row.values[st] - St), 1e-6 * std::max(St, S2(Et, Ez))) << "p = " << row.values[p];
    EXPECT_LT(rel(row.values[sz], S2(Et, Ez)), 1e-6) << "p = " << row.values[p];
    EXPECT_LT(rel(row.values[h], H / (lt_exact * lz)), 1e-6);
    EXPECT_LT(rel(row.values[rad], R * lt_exact), 1e-6);
    // Axial force = 2π r h σz = 2π R H λz Sz (kPa·mm² = 1e-3 N).
    EXPECT_LT(rel(row.values[F], 2 * M_PI * R * H * lz * S2(Et, Ez) * 1e-3), 1e-6);
    ++checked;
  }
  EXPECT_EQ(checked, 20);
}

}  // namespace

TEST(RatAorta, PrestretchGivesTheZeroPressureHoopStretchOfTheory) {
  const Result r = run(read_text(kDeck));
  const int lt = Capture::column(r.model, "lambda_theta");
  const Row* last = nullptr;
  for (const Row& row : r.capture.rows)
    if (row.info.step == 1) last = &row;
  ASSERT_NE(last, nullptr);
  // S1 = 0  ⇔  E1 = −a4 E2 / a1 (theory manual (8.2): λθ(p = 0) = 0.8695).
  const double E1 = -a4 * 0.5 * (lz * lz - 1) / a1;
  EXPECT_NEAR(last->values[lt], std::sqrt(2 * E1 + 1), 1e-9);
  EXPECT_NEAR(last->values[lt], 0.8695, 5e-5);
}

TEST(RatAorta, OneElementMatchesTheClosedFormAtEveryIncrement) {
  const Result r = run(read_text(kDeck));
  expect_closed_form(r, 1);
  EXPECT_EQ(r.capture.cutbacks, 0);
}

TEST(RatAorta, FiftyElementsGiveTheSameState) {
  const Result r = run(replace(read_text(kDeck), "elements: 1}", "elements: 50}"));
  expect_closed_form(r, 50);
  // Every Gauss point of the 50 elements in the same state: min = max.
  const Model& m = r.model;
  EXPECT_EQ(m.parts[0].num_elements(), 50);
  Analysis a(m);
  Capture c;
  a.run(c);
  for (const auto& pt : a.system().points(a.displacement(), 0)) {
    EXPECT_NEAR(pt.lambda(0), a.system().points(a.displacement(), 0)[0].lambda(0), 1e-9);
    EXPECT_NEAR(pt.lambda(1), lz, 1e-9);
  }
}

TEST(RatAorta, NewtonConvergesQuadraticallyInAtMostFiveIterations) {
  const Result r = run(read_text(kDeck));
  // Group iterations by increment of the inflation step.
  std::map<int, std::vector<IterationRecord>> inc;
  for (const auto& it : r.capture.iterations)
    if (it.info.step == 2) inc[it.info.increment].push_back(it.rec);
  ASSERT_EQ(inc.size(), 20u);
  for (const auto& [k, recs] : inc) {
    const int iterations = recs.back().iteration;
    EXPECT_LE(iterations, 5) << "increment " << k;
    EXPECT_GE(iterations, 2) << "increment " << k;
    // Order of convergence q_k = log(r_{k+1}/r_k) / log(r_k/r_{k−1}) on iterates above round-off,
    // and the measure log r(k+1) / log r(k) on the relative residual. Both tend to 2: the
    // first iterate is pre-asymptotic (q ≈ 2–2.8), the last one above round-off is at 2.
    double last_q = 0, last_ratio = 0;
    for (std::size_t j = 1; j + 1 < recs.size(); ++j) {
      const double r0 = recs[j - 1].relative_residual, r1 = recs[j].relative_residual, r2 = recs[j + 1].relative_residual;
      if (r2 < 1e-13) break;  // round-off
      last_q = std::log(r2 / r1) / std::log(r1 / r0);
      last_ratio = std::log(r2) / std::log(r1);
      EXPECT_GT(last_q, 1.8) << "increment " << k << " iteration " << j;
      EXPECT_GT(last_ratio, 1.9) << "increment " << k << " iteration " << j;
    }
    EXPECT_NEAR(last_q, 2.0, 0.1) << "increment " << k;
    EXPECT_GT(last_ratio, 1.9) << "increment " << k;
    EXPECT_LT(last_ratio, 2.5) << "increment " << k;
    EXPECT_LT(recs.back().relative_residual, 1e-10);
  }
}
