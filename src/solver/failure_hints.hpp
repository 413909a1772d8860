#pragma once
// What a failed increment's message suggests (the likely fix), from the Newton result and the
// step's converged increments so far.
#include <string>
#include <vector>

#include "assembly/system.hpp"
#include "solver/newton.hpp"

namespace tunica {

/// Empty, or one or more sentences, each naming the deck key that would help:
///  - Newton was still converging at `max_iterations` (last relative residual below 1e-3):
///    raise `max_iterations`;
///  - the step raises a pressure without volume control and the pressure–volume curve of that
///    load flattened over the step's converged increments (dp/dV of the last below a fifth of
///    the first's, or negative): a limit point, which `volume_control` passes.
/// `converged`: the step's start and each converged increment's state, in order.
std::string failure_hints(const Model& model, const Step& step, const NewtonResult& last,
                          const std::vector<LoadState>& converged);

}  // namespace tunica
