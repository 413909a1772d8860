#pragma once
// History quantities: the values of the deck's `output.history` requests at
// the current state of an analysis, converted to their output units.
#include <vector>

#include "solver/analysis.hpp"

namespace tunica {

/// One value per request of model.output.history, in the requested units.
std::vector<double> history_values(const Analysis& analysis, const IncrementInfo& info);

}  // namespace tunica
