// The line search (solver/newton.cpp): a Newton correction is kept when ‖R‖ fell or when
// it took the energy slope along it to half, |Δu·R(u + Δu)| ≤ ½ |Δu·R(u)|. The thin
// neo-Hookean sphere octant inflated from rest to λ = 1.2 in one increment is the case
// it is for: the first correction raises ‖R‖ (in-plane forces of the faceting modes,
// stiff but of little energy) while going most of the way along the softening
// pressure–stretch curve. Halving it, as a residual-only test did, cost an iteration.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>

#include "../support/capture.hpp"

using namespace tunica;
using namespace tunica::test;

namespace {

struct SphereRun {
  Capture capture;
  int corrections = 0;
  std::vector<IterationRecord> first_increment;
};

SphereRun run_sphere(bool line_search) {
  const double l = 1.2;
  const double p = 2.0 * 1.0 * 0.01 * (1.0 / l - std::pow(l, -7));  // THEORY §7, μ = 1 MPa, H/R = 0.01
  const std::string deck = fmt::format(R"(title: sphere octant from rest in one increment
units: {{length: mm, force: N}}
materials:
  rubber: {{type: neo_hookean, mu: 1 MPa}}
parts:
  balloon:
    element: membrane
    material: rubber
    thickness: 0.01 mm
    mesh: {{type: octant, radius: 1 mm, n: 16}}
boundary:
  sym_x: {{node_set: balloon.x0, dofs: [x]}}
  sym_y: {{node_set: balloon.y0, dofs: [y]}}
  sym_z: {{node_set: balloon.z0, dofs: [z]}}
loads:
  inflation: {{type: pressure, part: balloon}}
solver: {{line_search: {}}}
steps:
  - {{name: inflate, increments: 1, set: {{inflation: {:.17g}}}}}
output: {{vtk: false}}
)",
                                       line_search ? "true" : "false", p);
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
