// The line search (solver/newton.cpp): a Newton correction is kept when ‖R‖ fell or when
// it took the energy slope along it to half, |Δu·R(u + Δu)| ≤ ½ |Δu·R(u)|. The thin
// neo-Hookean sphere octant inflated from rest to λ = 1.2 in one increment is the case
// it is for: the first correction raises ‖R‖ (in-plane forces of the faceting modes,
// stiff but of little energy) while going most of the way along the softening
// pressure–stretch curve. Halving it, as a residual-only test would, costs an iteration.
// The case needs the plain tangent at the stress-free start (`stress_free_start: exact`):
// the default stiffened first correction does not raise ‖R‖ (test_stress_free_start.cpp).
#include <gtest/gtest.h>

#include <fmt/format.h>

#include "../support/capture.hpp"
#include "../support/sphere_octant.hpp"

using namespace tunica;
using namespace tunica::test;

namespace {

struct SphereRun {
  Capture capture;
  int corrections = 0;
  std::vector<IterationRecord> first_increment;
};

SphereRun run_sphere(bool line_search) {
  const std::string deck =
      sphere_octant_deck("sphere octant from rest in one increment", 16,
                         fmt::format("solver: {{line_search: {}, stress_free_start: exact}}\n", line_search ? "true" : "false"),
                         1);
  const Model model = read_deck_text(deck, "line-search-sphere.yaml");
  SphereRun r;
  Analysis a(model);
  a.run(r.capture);
  for (const auto& it : r.capture.iterations) {
    if (!it.rec.solver.empty()) ++r.corrections;
    if (it.info.increment == 1) r.first_increment.push_back(it.rec);
  }
  return r;
}

}  // namespace

TEST(LineSearch, KeepsACorrectionThatRaisesTheResidualButHalvesTheEnergySlope) {
  const SphereRun with = run_sphere(true);
  ASSERT_EQ(with.capture.rows.back().info.fraction, 1.0);
  ASSERT_GE(with.first_increment.size(), 3u);
  const IterationRecord& start = with.first_increment[0];
  const IterationRecord& first = with.first_increment[1];
  EXPECT_GT(first.residual, 2 * start.residual) << "the case must raise ‖R‖ in its first correction";
  EXPECT_EQ(first.backtracks, 0) << "a correction that leaves a quarter of the energy slope is kept";
  EXPECT_LT(first.relative_energy, 0.5);
  EXPECT_LE(with.corrections, 5);
  // The line search changes nothing here: the same iterates as with it switched off.
  const SphereRun without = run_sphere(false);
  ASSERT_EQ(without.first_increment.size(), with.first_increment.size());
  for (std::size_t k = 0; k < with.first_increment.size(); ++k)
    EXPECT_NEAR(with.first_increment[k].residual, without.first_increment[k].residual,
                1e-9 * with.first_increment[0].residual)
        << k;
}
