// The stiffened first correction from a stress-free state (solver/tangent_hooks.hpp, theory manual
// §7.2, (7.6)–(7.8)): the same converged state as the plain tangent, in fewer iterations, and a tangent
// CHOLMOD can factorize.
//  - The thin neo-Hookean sphere octant inflated from rest to λ = 1.2 in one increment: the
//    plain first correction dimples the cube-sphere's valence-3 corner and Newton needs 6
//    iterations; stiffened, 5. In 2 and 10 increments at most 5 and 4 per increment.
//  - The benchmark's Fung tube stretched and inflated from rest: the plain stress-free tangent
//    is indefinite (`auto` falls back to UMFPACK for the first factorization), the stiffened
//    one is positive definite (CHOLMOD for every factorization); same iterations, same state.
// Every iteration factorizes here (reuse_factorization: never): the counts are those of the start
// strategies, not of a reused factorization (7.11).
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
  return sphere_octant_deck("sphere octant from rest", kN, fmt::format("solver: {{stress_free_start: {}, reuse_factorization: never}}\n", start),
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
  EXPECT_LT((stiffened.u - exact.u).cwiseAbs().maxCoeff(), 1e-8) << "mm (radius 1 mm, stretch 0.2)";
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
  EXPECT_LT((two.u - ten.u).cwiseAbs().maxCoeff(), 1e-8);
}

TEST(StressFreeStart, TubeStartTangentIsPositiveDefinite) {
  const auto deck = [](const char* start) {
    return fung_tube_deck(24, fmt::format("solver: {{stress_free_start: {}, reuse_factorization: never}}\n", start), 6);
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
  EXPECT_LT((stiffened.u - exact.u).cwiseAbs().maxCoeff(), 1e-8) << "mm";
}

TEST(StressFreeStart, PrescribedNormalMotionEntersThePredictorThroughTheStartStiffness) {
  // The pole of the sphere octant is lifted to its closed-form position (z = 1.2 mm) in the same
  // increment as the pressure: a prescribed displacement along the normal, so the predictor's
  // right-hand side gets −K₀_fp Δu_p, the gradient of ½ (u − u_n)ᵀ K₀ (u − u_n) at u_n + Δu_p,
  // which makes the pole's neighbours follow it out. The predictor alone (Newton stopped after
  // it) is compared with the plain one: the mean radial displacement of the pole's neighbours.
  const auto first_iterate = [](const char* start) {
    std::string d = sphere_octant_deck("sphere octant, pole lifted", kN,
                                       fmt::format("solver: {{stress_free_start: {}, reuse_factorization: never}}\n", start), 1);
    d = replace(d, "  sym_z: {node_set: balloon.z0, dofs: [z]}\n",
                "  sym_z: {node_set: balloon.z0, dofs: [z]}\n  lift: {node_set: balloon.pole, dofs: [z]}\n");
    d = replace(d, "set: {inflation: ", "set: {lift: 0.2 mm, inflation: ");
    const Model model = read_deck_text(d, "pole-lift.yaml");
    const System system(model);
    LoadState loads;
    loads.boundary.assign(model.boundaries.size(), 0.0);
    loads.pressure.assign(model.loads.size(), sphere_octant_pressure());
    loads.volume.assign(model.loads.size(), 0.0);
    for (std::size_t b = 0; b < model.boundaries.size(); ++b)
      if (model.boundaries[b].name == "lift") loads.boundary[b] = 0.2;
    const Eigen::VectorXd un = Eigen::VectorXd::Zero(model.num_dofs());
    Eigen::VectorXd u = un;
    system.apply_boundary(loads, u);
    SolverSettings settings = model.steps[0].solver;
    settings.max_iterations = 1;  // stop right after the predictor: u is its iterate
    auto solver = make_linear_solver("auto");
    const NewtonResult r = solve_increment(system, *solver, loads, u, settings, [](const IterationRecord&) {}, nullptr, &un);
    EXPECT_FALSE(r.converged);
    // Neighbours of the pole: the nodes within 1.5 element sizes of it (not the pole itself).
    const Eigen::Vector3d pole(0, 0, 1);
    double sum = 0;
    int count = 0;
    for (int n = 0; n < model.num_nodes(); ++n) {
      const double dist = (model.X[n] - pole).norm();
      if (dist > 1e-9 && dist < 1.5 * (3.14159265 / 4) / kN) {
        sum += (model.X[n] + u.segment<3>(3 * n)).norm() - 1.0;
        ++count;
      }
    }
    EXPECT_GT(count, 2);
    return sum / count;
  };
  const double stiffened = first_iterate("stiffened"), exact = first_iterate("exact");
  fmt::print("pole lifted by 0.2 mm with the pressure, first iterate: mean radial displacement of its neighbours "
             "{:.4f} mm stiffened, {:.4f} mm plain (converged: 0.2 mm)\n",
             stiffened, exact);
  EXPECT_GT(stiffened, exact);
  EXPECT_NEAR(stiffened, 0.2, 0.05);
}

TEST(StressFreeStart, AFailedStiffenedStartIsRetriedPlainAtTheSameSizeBeforeACutBack) {
  // The campaign's closed Fung tube (64 × 16 quads) inflated from rest to 120 mmHg in one
  // increment: the stiffened attempt does not converge in 12 iterations. The next attempt has
  // the same size and the plain start; only then is the increment cut back.
  const std::string deck = R"(title: closed Fung tube from rest in one increment
units: {length: mm, force: N}
materials:
  wall: {type: fung, c: 61.163 kPa, a1: 0.68238, a2: 0.60558, a4: 0.1067}
parts:
  vessel:
    element: membrane
    material: wall
    thickness: 0.122 mm
    mesh: {type: tube, radius: 0.763 mm, length: 5 mm, around: 64, along: 16, shape: quad}
    frame: {type: cylindrical, axis: [0, 0, 1]}
boundary:
  bottom: {node_set: vessel.bottom, dofs: [x, y, z]}
  top: {node_set: vessel.top, dofs: [x, y, z]}
loads:
  blood: {type: pressure, part: vessel}
steps:
  - {name: inflation, increments: 1, set: {blood: 120 mmHg}}
output: {vtk: false}
)";
  Capture c;
  const Model model = read_deck_text(deck, "fung-tube.yaml");
  Analysis a(model);
  a.run(c);
  ASSERT_EQ(c.rows.back().info.fraction, 1.0);
  ASSERT_GE(c.retries.size(), 1u);
  EXPECT_EQ(c.retries.front().first.attempt, 0);
  EXPECT_EQ(c.retries.front().first.fraction, 1.0);  // the full increment, not yet cut back
  EXPECT_NE(c.retries.front().second.find("stress_free_start: exact"), std::string::npos);
  // Attempt 1 is that retry: its iterations are at the full size.
  bool retried_full = false;
  for (const auto& it : c.iterations) retried_full |= it.info.attempt == 1 && it.info.fraction == 1.0;
  EXPECT_TRUE(retried_full);
  // From the first converged increment on the state is not stress free: no more retries.
  for (const auto& r : c.retries) EXPECT_EQ(r.first.increment, 1);
}

TEST(StressFreeStart, AnAttemptThatTookNoStiffenedStartIsNotRetriedAtTheSameSize) {
  // A 3-D stretch from rest without pressure takes the slack stiffness of (7.14), not the stiffened
  // start: a plain retry would repeat it. With one iteration allowed it fails, and is cut back
  // at once.
  const std::string deck = R"(units: {length: mm, force: N}
materials:
  wall: {type: neo_hookean, mu: 30 kPa}
parts:
  vessel:
    element: membrane
    material: wall
    thickness: 0.2 mm
    mesh: {type: tube, radius: 1 mm, length: 4 mm, around: 16, along: 4, shape: quad}
boundary:
  bottom: {node_set: vessel.bottom, dofs: [z]}
  top: {node_set: vessel.top, dofs: [z]}
  sx: {node_set: vessel.x0, dofs: [x]}
  sy: {node_set: vessel.y0, dofs: [y]}
loads:
  blood: {type: pressure, part: vessel}
steps:
  - {name: stretch, increments: 1, set: {top: 1 mm}, solver: {max_iterations: 1, max_cutbacks: 1}}
output: {vtk: false}
)";
  Capture c;
  const Model model = read_deck_text(deck, "slack-tube.yaml");
  Analysis a(model);
  EXPECT_THROW(a.run(c), SolveError);
  EXPECT_TRUE(c.retries.empty());
  EXPECT_EQ(c.cutbacks, 1);
}

TEST(StressFreeStart, InflationAfterAPrestretchAloneStartsAsFromRest) {
  // A closed 3-D tube of quadrilaterals stretched axially alone (4 increments) has no hoop tension
  // and ovalizes freely; the inflation step after it raises the pressure from zero. Its first
  // correction is stiffened as from rest: 120 mmHg in 6 increments with the defaults (the plain
  // first correction stagnated at a relative residual near 1 through 5 cut-backs).
  const std::string deck = R"(units: {length: mm, force: N}
materials:
  aorta: {type: fung, c: 61.163 kPa, a1: 0.68238, a2: 0.60558, a4: 0.1067}
parts:
  wall:
    element: membrane
    material: aorta
    thickness: 0.122 mm
    mesh: {type: tube, radius: 0.763 mm, length: 1 mm, around: 48, along: 24}
    frame: {type: cylindrical, axis: [0, 0, 1]}
boundary:
  sym_x:   {node_set: wall.x0, dofs: [x]}
  sym_y:   {node_set: wall.y0, dofs: [y]}
  base:    {node_set: wall.bottom, dofs: [z]}
  stretch: {node_set: wall.top, dofs: [z]}
loads:
  lumen: {type: pressure, part: wall, volume_axis: [0, 0, 1]}
steps:
  - {name: prestretch, increments: 4, set: {stretch: 0.6 mm}}
  - {name: inflation, increments: 6, set: {lumen: 120 mmHg}}
output:
  history:
    - {quantity: radius, part: wall, unit: mm}
)";
  const Model model = read_deck_text(deck, "prestretch-then-inflation.yaml");
  Analysis a(model);
  Capture c;
  a.run(c);
  // The inflation step: every increment at its first attempt, quadratically (at most 6 iterations).
  int retries = 0, most = 0, increments = 0;
  for (const auto& it : c.iterations)
    if (it.info.step == 2 && it.info.attempt > 0 && it.rec.iteration == 0) ++retries;
  for (const auto& row : c.rows)
    if (row.info.step == 2) {
      most = std::max(most, row.info.iterations);
      ++increments;
    }
  std::printf("prestretch alone, then 120 mmHg in 6 increments: %d increments, at most %d iterations, %d retries or "
              "cut-backs\n",
              increments, most, retries);
  EXPECT_EQ(c.rows.back().info.fraction, 1.0);
  EXPECT_EQ(c.rows.back().info.step, 2);
  EXPECT_EQ(increments, 6);
  EXPECT_EQ(retries, 0);
  EXPECT_LE(most, 6);
}
