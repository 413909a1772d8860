// A correction solved with an earlier iteration's factorization (solver/newton.cpp, theory
// manual (7.11), `reuse_factorization`): on the benchmark's Fung tube stretched and inflated
// from rest, `last` saves factorizations without adding an iteration, `basin` saves more for a
// few iterations more, and all three reach the same state; a reused correction comes only
// after a factorization of the same attempt, in the quadratic basin.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <string>

#include "../support/capture.hpp"
#include "../support/fung_tube.hpp"

using namespace tunica;
using namespace tunica::test;

namespace {

struct ReuseRun {
  Eigen::VectorXd u;
  int corrections = 0;     // iterations with a solve
  int factorizations = 0;  // of those, the ones that factorized
  bool converged = false;
  Capture capture;
};

ReuseRun run(const std::string& reuse, int increments, int prestretch_increments, const std::string& more = "") {
  const Model model = read_deck_text(
      fung_tube_deck(24, fmt::format("solver: {{reuse_factorization: {}{}}}\n", reuse, more), increments,
                     prestretch_increments),
      "tube-" + reuse + ".yaml");
  Analysis a(model);
  ReuseRun r;
  a.run(r.capture);
  r.u = a.displacement();
  r.converged = !r.capture.rows.empty() && r.capture.rows.back().info.fraction == 1.0 &&
                r.capture.rows.back().info.step == static_cast<int>(model.steps.size());
  for (const auto& it : r.capture.iterations)
    if (!it.rec.solver.empty()) {
      ++r.corrections;
      if (it.rec.solver.find(kReusedFactorization) == std::string::npos) ++r.factorizations;
    }
  return r;
}

}  // namespace

TEST(FactorizationReuse, LastSavesFactorizationsWithoutIterationsAndBasinSavesMore) {
  for (const auto& [increments, prestretch] : {std::pair{6, 4}, std::pair{1, 1}}) {
    const ReuseRun never = run("never", increments, prestretch);
    const ReuseRun last = run("last", increments, prestretch);
    const ReuseRun basin = run("basin", increments, prestretch);
    ASSERT_TRUE(never.converged && last.converged && basin.converged);
    EXPECT_EQ(never.factorizations, never.corrections) << "never reuses";
    EXPECT_LT(last.factorizations, never.factorizations);
    EXPECT_LE(last.corrections, never.corrections) << "last adds no iteration, (7.12)";
    EXPECT_LE(basin.factorizations, last.factorizations);
    // Each converged to ‖R‖ ≤ 1e-9 ‖R₀‖: the same state to well below the discretization error.
    EXPECT_LT((last.u - never.u).cwiseAbs().maxCoeff(), 1e-8) << "mm";
    EXPECT_LT((basin.u - never.u).cwiseAbs().maxCoeff(), 1e-8) << "mm";
    fmt::print("tube 24 x 24, {} + {} increments: never {} iterations / {} factorizations, last {} / {}, basin {} / {}\n",
               prestretch, increments, never.corrections, never.factorizations, last.corrections, last.factorizations,
               basin.corrections, basin.factorizations);
  }
}

TEST(FactorizationReuse, AReusedCorrectionFollowsAFactorizationOfTheSameAttemptInTheBasin) {
  const ReuseRun basin = run("basin", 6, 4);
  ASSERT_TRUE(basin.converged);
  int reused = 0;
  const auto& its = basin.capture.iterations;
  for (std::size_t i = 0; i < its.size(); ++i) {
    const IterationRecord& r = its[i].rec;
    if (r.solver.find(kReusedFactorization) == std::string::npos) continue;
    ++reused;
    EXPECT_EQ(r.factor_seconds, 0.0);
    EXPECT_LE(r.relative_residual, 1e-4);
    // An earlier iteration of the same increment and attempt factorized.
    bool factorized = false;
    for (std::size_t j = i; j-- > 0 && its[j].info.step == its[i].info.step && its[j].info.increment == its[i].info.increment &&
                            its[j].info.attempt == its[i].info.attempt;)
      factorized = factorized || (!its[j].rec.solver.empty() && its[j].rec.solver.find(kReusedFactorization) == std::string::npos);
    EXPECT_TRUE(factorized) << "step " << its[i].info.step << " increment " << its[i].info.increment;
    ASSERT_GE(i, 1u);
    EXPECT_LE(r.residual, 0.1 * its[i - 1].rec.residual) << "the last correction cut ‖R‖ tenfold";
  }
  EXPECT_GT(reused, 0);
}

TEST(FactorizationReuse, NoReusedCorrectionLeadsToTheLastIterationAllowed) {
  // A reused correction converges less surely than a Newton one (7.12): the last iterate the
  // limit allows always comes from a fresh factorization.
  constexpr int kLimit = 5;
  const ReuseRun basin = run("basin", 6, 4, fmt::format(", max_iterations: {}", kLimit));
  ASSERT_TRUE(basin.converged);
  int reused = 0, at_limit = 0;
  for (const auto& it : basin.capture.iterations) {
    if (it.rec.iteration + 1 == kLimit && !it.rec.solver.empty()) ++at_limit;
    if (it.rec.solver.find(kReusedFactorization) == std::string::npos) continue;
    ++reused;
    EXPECT_LT(it.rec.iteration + 1, kLimit) << "step " << it.info.step << " increment " << it.info.increment;
  }
  EXPECT_GT(reused, 0);
  EXPECT_GT(at_limit, 0) << "some increment needs the last iteration allowed, or the test shows nothing";
}
