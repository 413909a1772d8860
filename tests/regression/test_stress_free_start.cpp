// The stiffened first correction from a stress-free state (solver/newton.hpp, theory manual
// §7.2): the same converged state as the plain tangent, in fewer iterations, and a tangent
// CHOLMOD can factorize.
//  - The thin neo-Hookean sphere octant inflated from rest to λ = 1.2 in one increment: the
//    plain first correction dimples the cube-sphere's valence-3 corner and Newton needs 6
//    iterations; stiffened, 5. In 2 and 10 increments at most 5 and 4 per increment.
//  - The benchmark's Fung tube stretched and inflated from rest: the plain stress-free tangent
//    is indefinite (`auto` falls back to UMFPACK for the first factorization), the stiffened
//    one is positive definite (CHOLMOD for every factorization); same iterations, same state.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <algorithm>

#include "../support/capture.hpp"
#include "../support/fung_tube.hpp"
#include "../support/sphere_octant.hpp"

using namespace tunica;
using namespace tunica::test;

namespace {

struct StartRun {
  Eigen::VectorXd u;
  int corrections = 0;   // Newton iterations with a solve
  int most = 0;          // most iterations of an increment
  int cutbacks = 0;
  std::vector<std::string> solvers;  // per correction
  double fraction = 0;
};

StartRun run(const std::string& deck, const std::string& name) {
  const Model model = read_deck_text(deck, name);
  Analysis a(model);
  Capture c;
  a.run(c);
  StartRun r;
  r.u = a.displacement();
  r.cutbacks = c.cutbacks;
  r.fraction = c.rows.back().info.fraction;
  for (const auto& it : c.iterations)
    if (!it.rec.solver.empty()) {
      ++r.corrections;
      r.solvers.push_back(it.rec.solver);
    }
  for (const auto& row : c.rows) r.most = std::max(r.most, row.info.iterations);
  return r;
}

constexpr int kN = 24;  // 1,728 quads: the plain start needs 6 iterations from n ≈ 20 up (n = 16: 5)

std::string sphere(int increments, const char* start) {
  return sphere_octant_deck("sphere octant from rest", kN, fmt::format("solver: {{stress_free_start: {}}}\n", start),
                            increments);
}

}  // namespace

TEST(StressFreeStart, SphereFromRestConvergesInFiveIterationsToTheSameState) {
  const StartRun stiffened = run(sphere(1, "stiffened"), "sphere-stiffened.yaml");
  const StartRun exact = run(sphere(1, "exact"), "sphere-exact.yaml");
  ASSERT_EQ(stiffened.fraction, 1.0);
  ASSERT_EQ(exact.fraction, 1.0);
  EXPECT_EQ(stiffened.cutbacks, 0);
  EXPECT_LE(stiffened.corrections, 5);
  EXPECT_GE(exact.corrections, 6) << "the case no longer needs the stiffening";
  // Both converged to 1e-9 in ‖R‖: the same state to well below the discretization error.
  EXPECT_LT((stiffened.u - exact.u).cwiseAbs().maxCoeff(), 1e-9) << "mm (radius 1 mm, stretch 0.2)";
  for (const auto& s : stiffened.solvers) EXPECT_EQ(s, "cholmod");
  fmt::print("sphere n = {} from rest, one increment: {} iterations stiffened, {} exact; max |Δu| {:.2e} mm\n", kN,
             stiffened.corrections, exact.corrections, (stiffened.u - exact.u).cwiseAbs().maxCoeff());
}

TEST(StressFreeStart, SphereInTwoAndTenIncrementsTakesAtMostFiveAndFourPerIncrement) {
  const StartRun two = run(sphere(2, "stiffened"), "sphere-2.yaml");
  const StartRun ten = run(sphere(10, "stiffened"), "sphere-10.yaml");
  EXPECT_EQ(two.fraction, 1.0);
  EXPECT_EQ(ten.fraction, 1.0);
  EXPECT_LE(two.most, 5);
  EXPECT_LE(ten.most, 4);
  EXPECT_LT((two.u - ten.u).cwiseAbs().maxCoeff(), 1e-9);
}

TEST(StressFreeStart, TubeStartTangentIsPositiveDefinite) {
  const auto deck = [](const char* start) {
    return fung_tube_deck(24, fmt::format("solver: {{stress_free_start: {}}}\n", start), 6);
  };
  const StartRun stiffened = run(deck("stiffened"), "tube-stiffened.yaml");
  const StartRun exact = run(deck("exact"), "tube-exact.yaml");
  ASSERT_EQ(stiffened.fraction, 1.0);
  ASSERT_EQ(exact.fraction, 1.0);
  ASSERT_FALSE(exact.solvers.empty());
  EXPECT_EQ(exact.solvers.front(), "umfpack") << "the plain stress-free tangent is no longer indefinite";
  for (const auto& s : stiffened.solvers) EXPECT_EQ(s, "cholmod");
  EXPECT_LE(stiffened.corrections, exact.corrections);
  EXPECT_LE(stiffened.most, 4);
  EXPECT_LT((stiffened.u - exact.u).cwiseAbs().maxCoeff(), 1e-9) << "mm";
}
