// The tangent predictor (solver/tangent_predictor.hpp): when prescribed displacements move,
// the first iteration linearizes their increment at the last converged state.
// A tube stretched by its end ring with 24 elements along: without the predictor
// the ring of elements next to the moved end takes the whole increment in the
// first iteration and Newton needs many iterations (or cut-backs); with it every
// increment converges in a few. Both reach the same state.
#include <gtest/gtest.h>

#include <algorithm>

#include "../support/capture.hpp"

using namespace tunica;
using namespace tunica::test;

namespace {

struct TubeRun {
  Capture capture;
  int iterations = 0;      ///< corrections over the whole run (converged attempts and failed ones)
  int max_per_increment = 0;
};

TubeRun run_tube(const std::string& predictor) {
  const std::string path = std::string(TUNICA_SOURCE_DIR) + "/examples/rat-aorta-3d.yaml";
  std::string text = read_text(path);
  text = replace(text, "along: 2}", "along: 24}");
  text = replace(text, "solver: {residual_tolerance: 1e-10}", "solver: {residual_tolerance: 1e-10, predictor: " + predictor + "}");
  text = replace(text, "increments: 6", "increments: 3");
  text = replace(text, "increments: 19", "increments: 8");
  const Model model = read_deck_text(text, path);
  TubeRun r;
  Analysis a(model);
  a.run(r.capture);
  for (const auto& it : r.capture.iterations)
    if (!it.rec.solver.empty()) ++r.iterations;
  for (const auto& row : r.capture.rows) r.max_per_increment = std::max(r.max_per_increment, row.info.iterations);
  return r;
}

}  // namespace

TEST(TangentPredictor, StretchedTubeConvergesInFewIterationsToTheSameState) {
  const TubeRun with = run_tube("tangent");
  const TubeRun without = run_tube("none");
  ASSERT_EQ(with.capture.rows.back().info.fraction, 1.0);
  ASSERT_EQ(without.capture.rows.back().info.fraction, 1.0);
  EXPECT_EQ(with.capture.cutbacks, 0);
  EXPECT_LE(with.max_per_increment, 5);
  EXPECT_LT(2 * with.iterations, without.iterations + without.capture.cutbacks)
      << "with the predictor " << with.iterations << " iterations; without " << without.iterations << " and "
      << without.capture.cutbacks << " cut-backs";
  const auto& a = with.capture.rows.back().values;
  const auto& b = without.capture.rows.back().values;
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) EXPECT_NEAR(a[k], b[k], 1e-8 * std::max(1.0, std::abs(b[k]))) << k;
}
