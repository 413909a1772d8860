// The hints a stopped run's message gives (solver/failure_hints.hpp): raise max_iterations when
// Newton was still converging; volume_control when the pressure–volume curve has flattened
// (a limit point); nothing otherwise.
#include <gtest/gtest.h>

#include "solver/failure_hints.hpp"

using namespace tunica;

namespace {

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

/// Converged states along p(V): the step's start and each increment's.
std::vector<LoadState> along(const std::vector<std::pair<double, double>>& pv) {
  std::vector<LoadState> out;
  for (auto [p, v] : pv) {
    LoadState s;
    s.pressure = {p};
    s.volume = {v};
    out.push_back(s);
  }
  return out;
}

NewtonResult failed(const std::string& why, double relative) {
  NewtonResult r;
  r.failure = why;
  r.last_relative_residual = relative;
  return r;
}

}  // namespace

TEST(FailureHints, StillConvergingAtTheLimitSuggestsMoreIterations) {
  const Model m = one_load_model();
  const auto linear = along({{0, 1}, {1, 2}, {2, 3}});
  const std::string h = failure_hints(m, raising(10), failed("no convergence in 12 iterations", 9e-7), linear);
  EXPECT_NE(h.find("raise `max_iterations` in `solver` (now 12)"), std::string::npos) << h;
  EXPECT_EQ(h.find("volume_control"), std::string::npos) << h;
  // Far from converged, or another failure: no such hint.
  EXPECT_EQ(failure_hints(m, raising(10), failed("no convergence in 12 iterations", 0.3), linear), "");
  EXPECT_EQ(failure_hints(m, raising(10), failed("diverging", 1e-6), linear), "");
}

TEST(FailureHints, AFlatteningPressureVolumeCurveNamesVolumeControl) {
  const Model m = one_load_model();
  // dp/dV: 1 at the start, 0.1 at the end of the converged increments.
  const auto flattening = along({{0, 0}, {1, 1}, {1.5, 2}, {1.6, 3}});
  const std::string h = failure_hints(m, raising(3), failed("diverging", 1), flattening);
  EXPECT_NE(h.find("load 'blood' has flattened"), std::string::npos) << h;
  EXPECT_NE(h.find("dp/dV down to 10 %"), std::string::npos) << h;
  EXPECT_NE(h.find("`volume_control: {load: blood, volume: <enclosed volume>}`"), std::string::npos) << h;
  // Not flattening, not raising this load, already under volume control, too few increments: none.
  EXPECT_EQ(failure_hints(m, raising(3), failed("diverging", 1), along({{0, 0}, {1, 1}, {2, 1.8}, {3, 2.6}})), "");
  EXPECT_EQ(failure_hints(m, raising(0), failed("diverging", 1), flattening), "");
  Step controlled = raising(3);
  controlled.volume_control.load = 0;
  EXPECT_EQ(failure_hints(m, controlled, failed("diverging", 1), flattening), "");
  EXPECT_EQ(failure_hints(m, raising(3), failed("diverging", 1), along({{0, 0}, {1, 1}})), "");
}
