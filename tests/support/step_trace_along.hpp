#pragma once
// A step's converged states written as (pressure, volume) pairs of its one load, for the tests of
// the hints and notes that read a StepTrace (solver/failure_hints.hpp, output/jump_notes.hpp).
#include <utility>
#include <vector>

#include "solver/step_trace.hpp"

namespace tunica::test {

/// Converged states along p(V): the step's start and each increment's, in internal units.
inline StepTrace along(const std::vector<std::pair<double, double>>& pv) {
  StepTrace out;
  for (auto [p, v] : pv) {
    LoadState s;
    s.pressure = {p};
    s.volume = {v};
    if (out.count() == 0) out.restart_at(s);
    else out.push(s);
  }
  return out;
}

}  // namespace tunica::test
