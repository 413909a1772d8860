// The round-off test of Newton's convergence, ‖R‖ ≤ roundoff_tolerance · F (user guide §6,
// theory manual (7.2)): F weighs each element's stiffness with the larger of its length and its
// distance from the origin, since positions are held to a relative precision and an element of
// length h at |x| has strains with round-off ε|x|/h. A fine axisymmetric balloon (2,000 elements
// on a 1 mm radius, h = 0.8 µm) has R₀ of its first small increments near 1e-4 N and a residual
// floor near 7e-13 N: the relative tolerance asks 1e-13 N, below the floor, and F counted with
// the length alone put the round-off test at 1.6e-15 N. It must converge with the defaults, to
// the thin sphere's closed form (the pressure is that of λ = 1.3).
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>

#include "../support/capture.hpp"
#include "io/deck.hpp"
#include "solver/analysis.hpp"

using namespace tunica;
using namespace tunica::test;

namespace {

/// Thin Mooney–Rivlin sphere, theory manual (8.3): p(λ) = 4 (H/R)(λ⁻¹ − λ⁻⁷)(b₁ + b₂λ²).
double mooney_rivlin_sphere_pressure(double b1, double b2, double R, double H, double lambda) {
  return 4.0 * H / R * (1.0 / lambda - std::pow(lambda, -7)) * (b1 + b2 * lambda * lambda);
}

}  // namespace

TEST(RoundoffYardstick, AFineAxisymmetricBalloonConvergesWithTheDefaultsInTenIncrements) {
  const double b1 = 0.4, b2 = 0.05, R = 1.0, H = 0.01, lambda = 1.3;  // MPa, mm
  const double p = mooney_rivlin_sphere_pressure(b1, b2, R, H, lambda);
  const std::string deck = fmt::format(R"(units: {{length: mm, force: N}}
materials:
  rubber: {{type: mooney_rivlin, b1: {} MPa, b2: {} MPa}}
parts:
  balloon:
    element: axisymmetric_membrane
    material: rubber
    thickness: {} mm
    mesh: {{type: arc, center: [0, 0], radius: {} mm, start_angle: 0 deg, end_angle: 90 deg, elements: 2000}}
boundary:
  equator: {{node_set: balloon.start, dofs: [z]}}
  pole: {{node_set: balloon.end, dofs: [r]}}
loads:
  inflation: {{type: pressure, part: balloon}}
steps:
  - {{name: inflate, increments: 10, set: {{inflation: {:.17g} MPa}}}}
output: {{vtk: false}}
)",
                                       b1, b2, H, R, p);
  const Model model = read_deck_text(deck, "balloon-2000.yaml");
  Analysis a(model);
  Capture capture;
  a.run(capture);
  ASSERT_FALSE(capture.rows.empty());
  EXPECT_EQ(capture.rows.back().info.fraction, 1.0) << "the inflation did not complete";
  // Every node at radius λR (the equator node r, the pole node z; all nodes of the meridian).
  const Eigen::VectorXd& u = a.displacement();
  double worst = 0;
  for (int n = 0; n < model.num_nodes(); ++n) {
    const Eigen::Vector2d x = model.X[n].head<2>() + u.segment<2>(2 * n);
    worst = std::max(worst, std::abs(x.norm() / (lambda * R) - 1.0));
  }
  EXPECT_LT(worst, 1e-5) << "largest relative error of the radius against the closed form";
}
