// The hints a stopped run's message gives (solver/failure_hints.hpp), one per failure: raise
// max_iterations when Newton was still converging; volume_control when the pressure–volume curve
// has flattened to a maximum at the pressure the failed increment tried (a limit point), even if
// Newton was still converging; that the pressure still rises when the curve has flattened short of
// its maximum; for a singular tangent, the free body if one is, else a load beyond what the
// structure carries; nothing otherwise.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <string>

#include "../support/step_trace_along.hpp"
#include "io/deck.hpp"
#include "solver/failure_hints.hpp"

using namespace tunica;
using tunica::test::along;

namespace {

std::string replace_first(std::string text, const std::string& from, const std::string& to) {
  return text.replace(text.find(from), from.size(), to);
}

Model one_load_model() {
  Model m;
  PressureLoad l;
  l.name = "blood";
  m.loads.push_back(l);
  return m;
}

Step raising(double target) {
  Step s;
  s.targets["blood"] = target;
  s.solver.max_iterations = 12;
  return s;
}

/// The loads of a failed increment that tried pressure p.
LoadState trying(double p) {
  LoadState s;
  s.pressure = {p};
  return s;
}

/// A failed attempt whose absolute residual fell to `relative` of R₀ = the force scale 1.
NewtonResult failed(const std::string& why, double relative) {
  NewtonResult r;
  r.failure = why;
  r.last_relative_residual = relative;
  r.last_residual = relative;
  r.last_force_scale = 1;
  r.residual_falling = true;
  return r;
}

}  // namespace

TEST(FailureHints, StillConvergingAtTheLimitSuggestsMoreIterations) {
  const Model m = one_load_model();
  const auto linear = along({{0, 1}, {1, 2}, {2, 3}});
  const std::string h = failure_hints(m, raising(10), failed("no convergence in 12 iterations", 9e-7), linear, trying(2.5));
  EXPECT_NE(h.find("raise `max_iterations` in `solver` (now 12)"), std::string::npos) << h;
  EXPECT_EQ(h.find("volume_control"), std::string::npos) << h;
  // Far from converged, or another failure: no such hint.
  EXPECT_EQ(failure_hints(m, raising(10), failed("no convergence in 12 iterations", 0.3), linear, trying(2.5)), "");
  EXPECT_EQ(failure_hints(m, raising(10), failed("diverging", 1e-6), linear, trying(2.5)), "");
}

TEST(FailureHints, AStalledEnergyTestNamesTheEnergyToleranceNotMoreIterations) {
  const Model m = one_load_model();
  const auto linear = along({{0, 1}, {1, 2}, {2, 3}});
  NewtonResult stalled = failed("no convergence in 12 iterations", 4e-10);
  stalled.energy_stall = 8.66e-12;
  const std::string h = failure_hints(m, raising(10), stalled, linear, trying(2.5));
  EXPECT_NE(h.find("the residual criterion held and the energy criterion stalled at 8.66e-12"), std::string::npos) << h;
  EXPECT_NE(h.find("`energy_tolerance: 1e-10` in `solver` (now 1e-12)"), std::string::npos) << h;
  EXPECT_EQ(h.find("max_iterations"), std::string::npos) << h;
}

TEST(FailureHints, ATinyRelativeResidualOfADivergedAttemptDoesNotSuggestMoreIterations) {
  // What a volume-controlled tube from rest did before its stiffened start (user guide §6): the
  // first correction flung the wall out, R₀ = 6e14 N, and 40 iterations later ‖R‖ = 0.02 N is
  // 3.4e-17 of R₀ but not small against the 0.5 N of forces that cancel in it.
  const Model m = one_load_model();
  const auto linear = along({{0, 1}, {1, 2}, {2, 3}});
  NewtonResult blown = failed("no convergence in 40 iterations", 3.4e-17);
  blown.last_residual = 0.02;
  blown.last_force_scale = 0.5;
  EXPECT_EQ(failure_hints(m, raising(10), blown, linear, trying(2.5)).find("max_iterations"), std::string::npos);
  // Small against the forces but no longer falling: not converging either.
  NewtonResult flat = failed("no convergence in 12 iterations", 9e-7);
  flat.residual_falling = false;
  EXPECT_EQ(failure_hints(m, raising(10), flat, linear, trying(2.5)).find("max_iterations"), std::string::npos);
}

TEST(FailureHints, AFlatteningPressureVolumeCurveNamesVolumeControl) {
  const Model m = one_load_model();
  // dp/dV: 1 at the start, 0.1 at the end of the converged increments.
  const auto flattening = along({{0, 0}, {1, 1}, {1.5, 2}, {1.6, 3}});
  const std::string h = failure_hints(m, raising(3), failed("diverging", 1), flattening, trying(1.7));
  EXPECT_NE(h.find("load 'blood' has flattened"), std::string::npos) << h;
  EXPECT_NE(h.find("dp/dV down to 10 %"), std::string::npos) << h;
  EXPECT_NE(h.find("`volume_control: {load: blood, volume: <enclosed volume>}`"), std::string::npos) << h;
  // Not flattening, not raising this load, already under volume control, too few increments: none.
  EXPECT_EQ(failure_hints(m, raising(3), failed("diverging", 1), along({{0, 0}, {1, 1}, {2, 1.8}, {3, 2.6}}), trying(2.7)), "");
  EXPECT_EQ(failure_hints(m, raising(0), failed("diverging", 1), flattening, trying(1.7)), "");
  Step controlled = raising(3);
  controlled.volume_control.load = 0;
  EXPECT_EQ(failure_hints(m, controlled, failed("diverging", 1), flattening, trying(1.7)), "");
  EXPECT_EQ(failure_hints(m, raising(3), failed("diverging", 1), along({{0, 0}, {1, 1}}), trying(1.1)), "");
}

TEST(FailureHints, AFlatteningCurveShortOfItsMaximumIsNotCalledALimitPoint) {
  const Model m = one_load_model();
  // dp/dV: 1 at the start, then 0.1, 0.08, 0.06 per unit volume: flattened to 6 %, but falling
  // by 0.02 per unit volume, its trend reaches 0 at V = 6.5, a maximum near p = 1.3025.
  const auto slowing = along({{0, 0}, {1, 1}, {1.1, 2}, {1.18, 3}, {1.24, 4}});
  const std::string h = failure_hints(m, raising(3), failed("diverging", 1), slowing, trying(1.25));
  EXPECT_NE(h.find("load 'blood' has flattened"), std::string::npos) << h;
  EXPECT_NE(h.find("dp/dV down to 6 %"), std::string::npos) << h;
  EXPECT_NE(h.find("but the pressure still rises"), std::string::npos) << h;
  const auto kpa = [&](double p) { return m.units.from_internal(p, "kPa", Dimension::pressure); };
  const std::size_t near = h.find("its trend puts a maximum near ");
  ASSERT_NE(near, std::string::npos) << h;
  EXPECT_NEAR(std::stod(h.substr(near + 30)), kpa(1.3025), 1e-3 * kpa(1.3025)) << h;
  EXPECT_NE(h.find(fmt::format("kPa, above the {:.4g} kPa the failed increment tried", kpa(1.25))), std::string::npos) << h;
  EXPECT_EQ(h.find("likely at a maximum of the curve"), std::string::npos) << h;
  EXPECT_EQ(h.find("volume_control: {load"), std::string::npos) << h;
  // Trying beyond the predicted maximum: the limit point and volume control.
  const std::string beyond = failure_hints(m, raising(3), failed("diverging", 1), slowing, trying(1.31));
  EXPECT_NE(beyond.find("likely at a maximum of the curve"), std::string::npos) << beyond;
  EXPECT_NE(beyond.find("`volume_control: {load: blood, volume: <enclosed volume>}`"), std::string::npos) << beyond;
  // A flattened curve whose dp/dV no longer falls: no maximum in sight.
  const std::string steady =
      failure_hints(m, raising(3), failed("diverging", 1), along({{0, 0}, {1, 1}, {1.1, 2}, {1.2, 3}}), trying(1.25));
  EXPECT_NE(steady.find("its trend shows no maximum"), std::string::npos) << steady;
  // Past the maximum (dp/dV negative): the limit point whatever was tried.
  const std::string past =
      failure_hints(m, raising(3), failed("diverging", 1), along({{0, 0}, {1, 1}, {1.1, 2}, {1.05, 3}}), trying(1.06));
  EXPECT_NE(past.find("likely at a maximum of the curve"), std::string::npos) << past;
}

TEST(FailureHints, AtTheLargestPressureASlowNewtonGetsOneHintNotTwo) {
  // A tube at its asymptote μH/R: the curve flattened to nothing, the pressure tried at its end,
  // and Newton creeping (relative residual 2e-4, falling) when the iterations ran out. There is
  // no state to converge to: the limit, not more iterations.
  const Model m = one_load_model();
  const auto flat = along({{0, 0}, {1, 1}, {1.5, 2}, {1.6, 3}, {1.601, 4}});
  const std::string h = failure_hints(m, raising(1.61), failed("no convergence in 12 iterations", 2e-4), flat, trying(1.605));
  EXPECT_EQ(h.find("Hint:"), h.rfind("Hint:")) << "one hint: " << h;
  EXPECT_NE(h.find("likely at a maximum of the curve near the last converged state (a limit point), or at an "
                   "asymptote that it approaches: pressure control cannot pass it"),
            std::string::npos)
      << h;
  EXPECT_NE(h.find("(raising `max_iterations` would not help)"), std::string::npos) << h;
  EXPECT_EQ(h.find("raise `max_iterations`"), std::string::npos) << h;
  EXPECT_NE(h.find("Lower the load below about"), std::string::npos) << h;
  // Past the maximum (dp/dV negative): said as passed.
  const std::string past = failure_hints(m, raising(3), failed("no convergence in 12 iterations", 2e-4),
                                         along({{0, 0}, {1, 1}, {1.1, 2}, {1.05, 3}}), trying(1.06));
  EXPECT_NE(past.find("a maximum of the curve near the last converged state (a limit point, already passed: dp/dV has "
                            "turned negative)"), std::string::npos) << past;
  // Short of the predicted maximum, still converging: more iterations, alone.
  const std::string slow = failure_hints(m, raising(3), failed("no convergence in 12 iterations", 2e-4),
                                         along({{0, 0}, {1, 1}, {1.1, 2}, {1.18, 3}, {1.24, 4}}), trying(1.25));
  EXPECT_NE(slow.find("raise `max_iterations` in `solver` (now 12)"), std::string::npos) << slow;
  EXPECT_EQ(slow.find("Hint:"), slow.rfind("Hint:")) << "one hint: " << slow;
}

namespace {

NewtonResult singular() {
  NewtonResult r = failed("the tangent matrix is singular", 0.95);
  r.singular = true;
  r.residual_falling = false;
  return r;
}

const std::string kHeldTube = R"(units: {length: mm, force: N}
materials:
  rubber: {type: neo_hookean, mu: 100 kPa}
parts:
  wall:
    element: axisymmetric_membrane
    material: rubber
    thickness: 0.1 mm
    mesh: {type: line, from: [2 mm, 0 mm], to: [2 mm, 4 mm], elements: 8}
boundary:
  base: {node_set: wall.start, dofs: [z]}
  top:  {node_set: wall.end, dofs: [z]}
loads:
  blood: {type: pressure, part: wall}
steps:
  - {name: inflate, increments: 10, set: {blood: 4 MPa}}
)";

}  // namespace

TEST(FailureHints, BeyondAMaximumAStiffeningMaterialMaySnapThroughAndANeoHookeanOneCannot) {
  // The trial's Mooney–Rivlin sac under pressure control: a shallow maximum of p(V) at 6.674 kPa,
  // past which the pressure rises again (16 kPa, the target, at λ = 10.2). The hint must not say
  // that no state carries the pressure tried, nor send the user below the maximum unconditionally.
  const auto flat = along({{0, 0}, {1, 1}, {1.5, 2}, {1.6, 3}, {1.601, 4}});
  const std::string mr_deck = replace_first(kHeldTube, "{type: neo_hookean, mu: 100 kPa}",
                                            "{type: mooney_rivlin, b1: 150 kPa, b2: 30 kPa}");
  const Model mr = read_deck_text(mr_deck, "mr.yaml");
  LoadState tried = trying(1.605);
  tried.step = 0;
  const std::string h = failure_hints(mr, raising(16), failed("diverging", 1), flat, tried);
  EXPECT_EQ(h.find("Hint:"), h.rfind("Hint:")) << "one hint: " << h;
  EXPECT_NE(h.find("near the last converged state (a limit point), or at an asymptote that it approaches: "
                   "pressure control cannot pass it"), std::string::npos) << h;
  EXPECT_NE(h.find("may snap through to a larger volume where the pressure rises again"), std::string::npos) << h;
  EXPECT_NE(h.find("part 'wall' is mooney_rivlin"), std::string::npos) << h;
  EXPECT_NE(h.find("the step's target, 1.6e+04 kPa"), std::string::npos) << h;
  EXPECT_NE(h.find("only if the target is meant to lie below the maximum"), std::string::npos) << h;
  EXPECT_NE(h.find("`volume_control: {load: blood, volume: <enclosed volume>}`"), std::string::npos) << h;
  EXPECT_EQ(h.find("no state carries"), std::string::npos) << h;
  // A neo-Hookean membrane has no state beyond its maximum: lower the load.
  const Model nh = read_deck_text(kHeldTube, "nh.yaml");
  const std::string n = failure_hints(nh, raising(16), failed("diverging", 1), flat, tried);
  EXPECT_NE(n.find("(neo_hookean) does not stiffen"), std::string::npos) << n;
  EXPECT_NE(n.find("likely no state carries the 1605 kPa the failed increment tried. Lower the load below about 1601 kPa"),
            std::string::npos)
      << n;
  EXPECT_EQ(n.find("snap through"), std::string::npos) << n;
}

TEST(FailureHints, ASingularTangentOfAHeldModelIsALoadBeyondWhatItCarries) {
  // The trial's `lumen: 4` meant as kPa: 4 N/mm², 800 times the tube's asymptote μH/R = 5 kPa.
  // The model is held, so the hint speaks of the load, not of rigid-body motion.
  const Model m = read_deck_text(kHeldTube, "held.yaml");
  LoadState tried = trying(0.0125);
  tried.step = 0;
  const std::string h = failure_hints(m, m.steps[0], singular(), along({{0, 0}}), tried);
  EXPECT_EQ(h.find("Hint:"), h.rfind("Hint:")) << "one hint: " << h;
  EXPECT_NE(h.find("the model is held against rigid-body motion (`tunica check` finds no body free to move)"),
            std::string::npos)
      << h;
  EXPECT_NE(h.find("likely a load beyond what the structure carries"), std::string::npos) << h;
  EXPECT_NE(h.find("Load 'blood' tried 12.5 kPa = 93.76 mmHg (the step's target: 4000 kPa = 3e+04 mmHg)"),
            std::string::npos)
      << h;
  EXPECT_NE(h.find("No increment of this step converged"), std::string::npos) << h;
  EXPECT_NE(h.find("`volume_control: {load: blood, volume: <enclosed volume>}`"), std::string::npos) << h;
  EXPECT_EQ(h.find("is the model held"), std::string::npos) << h;
}

TEST(FailureHints, ASingularTangentOfAFreeModelNamesTheBodyAndItsHold) {
  // Neither end held in z: the tube slides along the axis whatever the load.
  const Model m = read_deck_text(replace_first(replace_first(kHeldTube, "dofs: [z]}", "dofs: [r]}"), "dofs: [z]}",
                                               "dofs: [r]}"),
                                 "free.yaml");
  LoadState tried = trying(0.0125);
  tried.step = 0;
  const std::string h = failure_hints(m, m.steps[0], singular(), along({{0, 0}}), tried);
  EXPECT_NE(h.find("the tangent is singular because a body is free to move rigidly (as `tunica check` warns): part "
                   "'wall': no boundary condition holds z"),
            std::string::npos)
      << h;
  EXPECT_EQ(h.find("beyond what the structure carries"), std::string::npos) << h;
}

TEST(FailureHints, AFreeModelThatStopsWithoutASingularTangentStillNamesTheBody) {
  // Round-off leaves the tangent of a free body regular: Newton stalls at the tolerance instead.
  const Model m = read_deck_text(replace_first(replace_first(kHeldTube, "dofs: [z]}", "dofs: [r]}"), "dofs: [z]}",
                                               "dofs: [r]}"),
                                 "free.yaml");
  LoadState tried = trying(0.0125);
  tried.step = 0;
  const std::string h =
      failure_hints(m, m.steps[0], failed("no convergence in 12 iterations", 9.9e-10), along({{0, 0}}), tried);
  EXPECT_NE(h.find("a body is free to move rigidly (as `tunica check` warns), so the tangent is singular or nearly so "
                   "and Newton's corrections wander along the free motion whatever the iteration limit: part 'wall': no "
                   "boundary condition holds z"),
            std::string::npos)
      << h;
  EXPECT_EQ(h.find("raise `max_iterations`"), std::string::npos) << h;
}

TEST(FailureHints, WithoutParaViewFramesTheHintPointsToWhatWasWritten) {
  // The hint for a local failure sends the user to the last frame; with `vtk: false` there is none.
  Model m = one_load_model();
  const auto slowing = along({{0, 0}, {1, 1}, {1.1, 2}, {1.18, 3}, {1.24, 4}});
  const std::string with = failure_hints(m, raising(3), failed("diverging", 1), slowing, trying(1.25));
  EXPECT_NE(with.find("look at newton.csv (active_changes) and the last frame"), std::string::npos) << with;
  m.output.vtk = false;
  const std::string without = failure_hints(m, raising(3), failed("diverging", 1), slowing, trying(1.25));
  EXPECT_EQ(without.find("frame where"), std::string::npos) << without;
  EXPECT_EQ(without.find("last frame"), std::string::npos) << without;
  EXPECT_NE(without.find("look at newton.csv (active_changes) and history.csv"), std::string::npos) << without;
  EXPECT_NE(without.find("no ParaView frames were written, `output.vtk` is false"), std::string::npos) << without;
}

TEST(FailureHints, ALongStepIsJudgedByItsFirstAndLastIncrements) {
  // The trace keeps the step's start, its first converged increment and the last three: a step
  // of many increments gives the hint its first and last slopes give.
  const Model m = one_load_model();
  std::vector<std::pair<double, double>> pv = {{0, 0}, {1, 1}};
  for (int k = 2; k < 40; ++k) pv.push_back({1 + 0.01 * (k - 1), static_cast<double>(k)});  // dp/dV = 0.01
  const StepTrace long_step = along(pv);
  EXPECT_EQ(long_step.count(), 40);
  EXPECT_EQ(long_step.kept().size(), StepTrace::kFirst + StepTrace::kLast);
  EXPECT_EQ(long_step.first(1).volume[0], 1);
  EXPECT_EQ(long_step.last(0).volume[0], 39);
  EXPECT_EQ(long_step.last(2).volume[0], 37);
  const std::string h = failure_hints(m, raising(3), failed("diverging", 1), long_step, trying(1.4));
  EXPECT_NE(h.find("dp/dV down to 1 %"), std::string::npos) << h;
  // What a restart file records reads back as the same trace; a record that cannot be one is refused.
  const StepTrace again = StepTrace::recorded(long_step.kept(), long_step.count());
  EXPECT_EQ(failure_hints(m, raising(3), failed("diverging", 1), again, trying(1.4)), h);
  EXPECT_THROW(StepTrace::recorded(long_step.kept(), 3), std::invalid_argument);
}

namespace {

/// A neo-Hookean tube (slave, `balloon` elements) pressed 0.001 mm into a Fung tube (master,
/// `artery` elements) beyond the offset, both 1 mm long.
std::string pressed_tubes(int balloon, int artery, const std::string& more = "") {
  return fmt::format(R"(title: a tube pressed into a tube
units: {{length: mm, force: N}}
materials:
  soft: {{type: neo_hookean, mu: 0.1 MPa}}
  wall: {{type: fung, c: 0.2 MPa, a1: 1.0, a2: 1.0, a4: 0.1}}
parts:
  balloon:
    element: axisymmetric_membrane
    material: soft
    thickness: 0.1 mm
    mesh: {{type: line, from: [1, 0], to: [1, 1], elements: {}}}
  artery:
    element: axisymmetric_membrane
    material: wall
    thickness: 0.1 mm
    mesh: {{type: line, from: [1.2, 0], to: [1.2, 1], elements: {}}}
boundary:
  a0: {{node_set: artery.start, dofs: [r, z]}}
  a1: {{node_set: artery.end, dofs: [r, z]}}
loads:
  lumen: {{type: pressure, part: balloon}}
contact:
  press: {{slave: balloon, master: artery, master_orientation: reversed, penalty: 1e3 N/mm^3, offset: 0.1 mm{}}}
steps:
  - {{name: press, increments: 1, set: {{lumen: 0.01 MPa}}}}
output:
  vtk: false
)",
                     balloon, artery, more);
}

/// The hint for the tubes with the slave's nodes moved out by 0.101 mm (all in contact).
std::string hint_for_pressed(int balloon, int artery, const std::string& more = "") {
  const Model m = read_deck_text(pressed_tubes(balloon, artery, more), "tubes.yaml");
  const System system(m);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(m.num_dofs());
  for (int n : m.parts[static_cast<std::size_t>(m.find_part("balloon"))].nodes) u(m.dofs_per_node() * n) = 0.101;
  return contact_resolution_hints(system, u, 0);
}

}  // namespace

TEST(FailureHints, ASlaveCoarserThanItsMasterInContactIsNamed) {
  // 4 slave elements on 16 master segments: neighbouring slave nodes 4 segments apart.
  const std::string h = hint_for_pressed(4, 16);
  EXPECT_NE(h.find("in contact pair 'press' the 5 active slave nodes lie on average 4.0 master segments apart"),
            std::string::npos)
      << h;
  EXPECT_NE(h.find("`passes: 2`, so that the nodes of 'artery' push back"), std::string::npos) << h;
  // Matching meshes, or a finer slave: nothing to say.
  EXPECT_EQ(hint_for_pressed(8, 8), "");
  EXPECT_EQ(hint_for_pressed(16, 4), "");
  // Two-pass contact already holds the master's nodes: nothing to say either.
  EXPECT_EQ(hint_for_pressed(4, 16, ", passes: 2"), "");
}

TEST(FailureHints, ALoadWrittenWithoutAUnitComesFirst) {
  // A bare `150` meant as mmHg is 150 N/mm²: no iteration limit or increment carries it.
  const Model m = one_load_model();
  Step s = raising(150);
  s.unitless_loads["blood"] = {"deck.yaml:27:19: key 'steps[1].set.blood'", "150"};
  const auto linear = along({{0, 1}, {1, 2}, {2, 3}});
  const std::string h = failure_hints(m, s, failed("no convergence in 12 iterations", 9e-7), linear, trying(2.5));
  EXPECT_NE(h.find("load 'blood' is set to `150` without a unit (deck.yaml:27:19: key 'steps[1].set.blood')"),
            std::string::npos)
      << h;
  EXPECT_NE(h.find("`150 mmHg`"), std::string::npos) << h;
  EXPECT_EQ(h.find("raise `max_iterations` in"), std::string::npos) << "one hint per failure: " << h;
  // A load the step does not set: no such hint.
  Step other = raising(150);
  other.unitless_loads["wall"] = {"deck.yaml:30:9", "4"};
  EXPECT_EQ(failure_hints(m, other, failed("no convergence in 12 iterations", 9e-7), linear, trying(2.5))
                .find("without a unit"),
            std::string::npos);
}

TEST(FailureHints, AnInverseStepThatStopsPointsToTheImagedMesh) {
  const Model m = one_load_model();
  Step s = raising(0.01);
  s.inverse = true;
  const auto linear = along({{0, 1}, {0.001, 2}});
  const std::string h = failure_hints(m, s, failed("stagnating", 0.07), linear, trying(0.002));
  EXPECT_NE(h.find("an inverse step finds a reference only for an imaged mesh that the discrete membrane can carry"),
            std::string::npos)
      << h;
  EXPECT_NE(h.find("user guide §3.5"), std::string::npos) << h;
  EXPECT_EQ(failure_hints(m, raising(0.01), failed("stagnating", 0.07), linear, trying(0.002)), "");
}

TEST(FailureHints, NoIncrementFromTheStressFreeStateSuggestsALittlePressureOrTheStiffenedStart) {
  Model m = one_load_model();
  m.steps.push_back(raising(10));
  const StepTrace at_rest = along({{0, 1}});
  const std::string h = failure_hints(m, m.steps.front(), failed("diverging", 1), at_rest, trying(2.5));
  EXPECT_NE(h.find("no increment converged from the stress-free reference state"), std::string::npos) << h;
  EXPECT_NE(h.find("a little pressure"), std::string::npos) << h;
  EXPECT_NE(h.find("`increments`"), std::string::npos) << h;
  // With the plain start asked for: leave it out.
  m.steps.front().solver.stiffen_stress_free_start = false;
  const std::string plain = failure_hints(m, m.steps.front(), failed("diverging", 1), at_rest, trying(2.5));
  EXPECT_NE(plain.find("`stress_free_start: exact`"), std::string::npos) << plain;
  // Not once an increment of the step converged, nor in a later step.
  m.steps.front().solver.stiffen_stress_free_start = true;
  EXPECT_EQ(failure_hints(m, m.steps.front(), failed("diverging", 1), along({{0, 1}, {1, 1.1}}), trying(2.5)), "");
  m.steps.push_back(raising(20));
  EXPECT_EQ(failure_hints(m, m.steps.back(), failed("diverging", 1), at_rest, trying(12)), "");
}

TEST(FailureHints, ALoadPushingItsSurfaceInwardFromTheStartNamesFlipNotTheStressFreeStart) {
  Model m = one_load_model();
  m.parts.emplace_back();
  m.parts.back().name = "sac";
  m.loads[0].part = 0;
  m.geometry = Geometry::three_d;
  m.steps.push_back(raising(10));
  const std::string h = failure_hints(m, m.steps.front(), failed("diverging", 1), along({{0, -1}}), trying(2.5));
  EXPECT_NE(h.find("load 'blood' pushes its surface (part 'sac') inward"), std::string::npos) << h;
  EXPECT_NE(h.find("set `flip: true` on the load"), std::string::npos) << h;
  EXPECT_EQ(h.find("stress-free reference state"), std::string::npos) << h;
  // flip: true already set: remove it.
  m.loads[0].sign = -1;
  const std::string flipped = failure_hints(m, m.steps.front(), failed("diverging", 1), along({{0, -1}}), trying(2.5));
  EXPECT_NE(flipped.find("remove `flip: true`"), std::string::npos) << flipped;
}

TEST(FailureHints, AVolumeTargetBelowTheStressFreeVolumeSaysItCompressesTheMembrane) {
  // Issue #17 C3: deflating below the rest volume needs a suction and compresses the membrane.
  const Model m = one_load_model();
  Step controlled = raising(0);
  controlled.targets.clear();
  controlled.volume_control.load = 0;
  controlled.volume_control.target = 1000;
  const auto start = along({{0, 1315.12}});
  const std::string h =
      failure_hints(m, controlled, failed("diverging", 1e9), start, trying(0), std::vector<double>{1315.12});
  EXPECT_NE(h.find("`volume_control.volume`, 1000 mm³, is below the stress-free volume of load 'blood', 1315.12 mm³"),
            std::string::npos)
      << h;
  EXPECT_NE(h.find("give a volume above 1315.12 mm³"), std::string::npos) << h;
  // Above the stress-free volume, or the reference volume not known: no such hint.
  controlled.volume_control.target = 2500;
  EXPECT_EQ(failure_hints(m, controlled, failed("diverging", 1e9), start, trying(0), std::vector<double>{1315.12})
                .find("stress-free volume"),
            std::string::npos);
  controlled.volume_control.target = 1000;
  EXPECT_EQ(failure_hints(m, controlled, failed("diverging", 1e9), start, trying(0)).find("stress-free volume"),
            std::string::npos);
}

TEST(FailureHints, AStretchWithoutPressureOnA3dMembraneSuggestsALittlePressure) {
  const Model m = read_deck_text(R"(units: {length: mm, force: N}
materials:
  artery: {type: neo_hookean, mu: 30 kPa}
parts:
  wall: {element: membrane, material: artery, thickness: 0.3 mm, mesh: {type: tube, radius: 2 mm, length: 4 mm, around: 16, along: 2}}
boundary:
  sym_x: {node_set: wall.x0, dofs: [x]}
  sym_y: {node_set: wall.y0, dofs: [y]}
  base: {node_set: wall.bottom, dofs: [z]}
  stretch: {node_set: wall.top, dofs: [z]}
loads:
  blood: {type: pressure, part: wall}
steps:
  - {name: prestretch, increments: 4, set: {stretch: 2 mm}}
  - {name: inflate, increments: 4, set: {blood: 120 mmHg}}
)",
                                 "tube.yaml");
  const StepTrace none = along({{0.0, 1.0}, {0.0, 1.0}});
  const std::string h =
      failure_hints(m, m.steps[0], failed("the residual is not finite", 1), none, trying(0.0));
  EXPECT_NE(h.find("step 'prestretch' moves the membrane with no pressure on it"), std::string::npos) << h;
  EXPECT_NE(h.find("`blood: 10 mmHg` in this step's `set`"), std::string::npos) << h;
  // Still converging at the limit: on an unstructured mesh more iterations do not get past, so the
  // hint names the pressure and not the iteration limit.
  const std::string slow = failure_hints(m, m.steps[0], failed("no convergence in 12 iterations", 1e-5), none, trying(0.0));
  EXPECT_NE(slow.find("no iteration limit or increment size gets such a step past, only the pressure."),
            std::string::npos)
      << slow;
  EXPECT_EQ(slow.find("6-node triangles"), std::string::npos) << slow;  // quadrilaterals: not their remedy
  EXPECT_EQ(slow.find("raise `max_iterations`"), std::string::npos) << slow;
  // A step that raises the pressure is not one.
  const std::string inflating =
      failure_hints(m, m.steps[1], failed("the residual is not finite", 1), none, trying(0.001));
  EXPECT_EQ(inflating.find("no pressure on it"), std::string::npos) << inflating;
}

TEST(FailureHints, ALoadFarBeyondTheWallsPressureScaleIsNamed) {
  // A neo-Hookean tube, μ₀ = 30 kPa, H = 0.3 mm, R = 2 mm: μ₀H/R = 4.5 kPa. 80 MPa is 17800 times that.
  const std::string deck = R"(units: {length: mm, force: N}
materials:
  artery: {type: neo_hookean, mu: 30 kPa}
parts:
  wall: {element: membrane, material: artery, thickness: 0.3 mm, mesh: {type: tube, radius: 2 mm, length: 4 mm, around: 16, along: 2}}
boundary:
  sym_x: {node_set: wall.x0, dofs: [x]}
  sym_y: {node_set: wall.y0, dofs: [y]}
  base: {node_set: wall.bottom, dofs: [z]}
loads:
  blood: {type: pressure, part: wall}
steps:
  - {name: inflate, increments: 4, set: {blood: 80 MPa}}
)";
  const Model m = read_deck_text(deck, "tube.yaml");
  const StepTrace start = along({{0.0, 1.0}});
  const std::string h = failure_hints(m, m.steps[0], failed("diverging", 1e9), start, trying(20));
  EXPECT_NE(h.find("load 'blood' is raised to 8e+04 kPa"), std::string::npos) << h;
  // The facets' curvature of a coarse tube is within 20 % of 1/(2R): the scale 4.5 kPa within as much.
  EXPECT_NE(h.find("times the pressure scale of part 'wall', 2μ₀H|H_m| = 5.268 kPa"), std::string::npos) << h;
  EXPECT_NE(h.find("μ₀ = 30 kPa"), std::string::npos) << h;
  EXPECT_NE(h.find("Check the value and its unit"), std::string::npos) << h;
  // 120 mmHg, 3.6 times the scale, is no such load.
  const Model fine = read_deck_text(replace_first(deck, "80 MPa", "120 mmHg"), "tube.yaml");
  EXPECT_EQ(failure_hints(fine, fine.steps[0], failed("diverging", 1e9), start, trying(0.01)).find("pressure scale"),
            std::string::npos);
}

TEST(FailureHints, ADisplacementFarBeyondTheModelsSizeIsNamed) {
  // The rat aorta's tube, 1 mm long and 0.763 mm in radius (diagonal 1.258 mm), pulled 99 mm: a
  // stretch of 100, which no setting carries (a value or unit mistyped).
  const std::string deck = R"(units: {length: mm, force: N}
materials:
  aorta: {type: fung, c: 61.163 kPa, a1: 0.68238, a2: 0.60558, a4: 0.1067}
parts:
  wall: {element: axisymmetric_membrane, material: aorta, thickness: 0.122 mm, mesh: {type: line, from: [0.763 mm, 0 mm], to: [0.763 mm, 1 mm], elements: 1}}
boundary:
  base: {node_set: wall.start, dofs: [z]}
  stretch: {node_set: wall.end, dofs: [z]}
loads:
  lumen: {type: pressure, part: wall}
steps:
  - {name: prestretch, increments: 6, set: {stretch: 99 mm}}
)";
  const Model m = read_deck_text(deck, "aorta.yaml");
  const StepTrace start = along({{0.0, 1.0}});
  for (const char* failure : {"diverging", "the residual is not finite"}) {
    const std::string h = failure_hints(m, m.steps[0], failed(failure, 1e9), start, trying(0));
    EXPECT_NE(h.find("boundary 'stretch' is moved by 99 mm, 78.7 times the size of the whole model (the diagonal of "
                     "its bounding box, 1.258 mm): a stretch of at least 79.7"),
              std::string::npos)
        << h;
  }
  // Its 0.6 mm (a stretch of 1.6) is no such value, and neither is 3 mm (4 mm long, a balloon's stretch).
  for (const char* fine : {"0.6 mm", "3 mm"}) {
    const Model ok = read_deck_text(replace_first(deck, "99 mm", fine), "aorta.yaml");
    EXPECT_EQ(failure_hints(ok, ok.steps[0], failed("diverging", 1e9), start, trying(0)).find("size of the whole model"),
              std::string::npos)
        << fine;
  }
}

TEST(FailureHints, AStretchWithoutPressureOnTrianglesAlsoNamesSixNodeTriangles) {
  const Model m = read_deck_text(R"(units: {length: mm, force: N}
materials:
  artery: {type: neo_hookean, mu: 30 kPa}
parts:
  wall: {element: membrane, material: artery, thickness: 0.3 mm, mesh: {type: tube, radius: 2 mm, length: 4 mm, around: 16, along: 2, shape: triangle}}
boundary:
  sym_x: {node_set: wall.x0, dofs: [x]}
  sym_y: {node_set: wall.y0, dofs: [y]}
  base: {node_set: wall.bottom, dofs: [z]}
  stretch: {node_set: wall.top, dofs: [z]}
loads:
  blood: {type: pressure, part: wall}
steps:
  - {name: prestretch, increments: 4, set: {stretch: 2 mm}}
)",
                                 "tube.yaml");
  const StepTrace none = along({{0.0, 1.0}, {0.0, 1.0}});
  const std::string h =
      failure_hints(m, m.steps[0], failed("no convergence in 12 iterations", 1e-5), none, trying(0.0));
  EXPECT_NE(h.find("only the pressure (or 6-node triangles, `Mesh.ElementOrder = 2`)"), std::string::npos) << h;
  EXPECT_EQ(h.find("shortens"), std::string::npos) << h;
}

TEST(FailureHints, AShorteningWithoutPressureOnA3dMembraneSaysItCompressesTheWall) {
  const std::string deck = R"(units: {length: mm, force: N}
materials:
  artery: {type: neo_hookean, mu: 30 kPa}
parts:
  wall: {element: membrane, material: artery, thickness: 0.3 mm, mesh: {type: tube, radius: 2 mm, length: 4 mm, around: 16, along: 2}}
boundary:
  sym_x: {node_set: wall.x0, dofs: [x]}
  sym_y: {node_set: wall.y0, dofs: [y]}
  base: {node_set: wall.bottom, dofs: [z]}
  stretch: {node_set: wall.top, dofs: [z]}
loads:
  blood: {type: pressure, part: wall}
steps:
  - {name: shorten, increments: 4, set: {stretch: -0.4 mm}}
)";
  const StepTrace none = along({{0.0, 1.0}, {0.0, 1.0}});
  const Model m = read_deck_text(deck, "tube.yaml");
  const std::string h =
      failure_hints(m, m.steps[0], failed("no convergence in 12 iterations", 1e-5), none, trying(0.0));
  EXPECT_NE(h.find("step 'shorten' shortens the wall with no pressure on it (boundary 'stretch' moves z by -0.4 mm "
                   "toward boundary 'base', 10 % of the model's extent in z): a membrane carries no compression"),
            std::string::npos)
      << h;
  // The base moved down is a stretch, and so is the top moved up.
  for (const char* stretch : {"set: {base: -0.4 mm}", "set: {stretch: 0.4 mm}"}) {
    const Model s = read_deck_text(replace_first(deck, "set: {stretch: -0.4 mm}", stretch), "tube.yaml");
    const std::string hs =
        failure_hints(s, s.steps[0], failed("no convergence in 12 iterations", 1e-5), none, trying(0.0));
    EXPECT_EQ(hs.find("shortens"), std::string::npos) << hs;
    EXPECT_NE(hs.find("moves the membrane with no pressure on it"), std::string::npos) << hs;
  }
}
