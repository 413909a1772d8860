// Newton's convergence order on the 3-D examples: with the consistent tangent
// (material + geometric + follower-pressure load stiffness, and the bordered
// volume constraint) the order estimate q = log(r_{k+1}/r_k) / log(r_k/r_{k−1})
// on the relative residual tends to 2 in every increment: the Fung tube under
// pressure control (quads) and the neo-Hookean octant under volume control,
// before and after its pressure maximum.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "../support/capture.hpp"

using namespace tunica;
using namespace tunica::test;

namespace {

/// Runs a deck and checks, per increment of `step`, the last order estimate above round-off.
void expect_quadratic(const std::string& deck, int step, int max_iterations) {
  const Model m = read_deck_text(read_text(deck), deck);
  Capture cap;
  Analysis a(m);
  a.run(cap);
  EXPECT_EQ(cap.cutbacks, 0);
  std::map<int, std::vector<IterationRecord>> inc;
  for (const auto& it : cap.iterations)
    if (it.info.step == step) inc[it.info.increment].push_back(it.rec);
  double qmin = 10, qmax = 0;
  int measured = 0;
  for (const auto& [k, recs] : inc) {
    EXPECT_LE(recs.back().iteration, max_iterations) << "increment " << k;
    double last_q = 0, floor = recs.front().residual;
    for (const auto& r : recs) floor = std::min(floor, r.residual);  // the round-off level reached
    for (std::size_t j = 1; j + 1 < recs.size(); ++j) {
      const double r0 = recs[j - 1].relative_residual, r1 = recs[j].relative_residual, r2 = recs[j + 1].relative_residual;
      // Skip iterates within 10³ of the round-off floor, and those before the asymptotic range.
      if (recs[j + 1].residual < 1e3 * floor || r2 < 1e-12 || r1 >= 1.0) continue;
      last_q = std::log(r2 / r1) / std::log(r1 / r0);
    }
    if (last_q == 0) continue;  // converged in too few iterations to measure
    ++measured;
    qmin = std::min(qmin, last_q);
    qmax = std::max(qmax, last_q);
    EXPECT_NEAR(last_q, 2.0, 0.3) << "increment " << k;
  }
  std::printf("%s: order estimate in [%.2f, %.2f] over %d of %zu increments\n", deck.c_str(), qmin, qmax, measured,
              inc.size());
  // Increments that converge in three iterations reach round-off before a pair can be measured.
  EXPECT_GE(measured, 5);
}

}  // namespace

TEST(NewtonRate3d, FungTubeConvergesQuadratically) {
  expect_quadratic(std::string(TUNICA_SOURCE_DIR) + "/examples/rat-aorta-3d.yaml", 2, 5);
}

TEST(NewtonRate3d, VolumeControlledBalloonConvergesQuadratically) {
  expect_quadratic(std::string(TUNICA_SOURCE_DIR) + "/examples/balloon-sphere-3d.yaml", 1, 6);
}
