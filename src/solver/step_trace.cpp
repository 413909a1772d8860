#include "solver/step_trace.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace tunica {

void StepTrace::push(const LoadState& s) {
  kept_.push_back(s);
  ++count_;
  if (kept_.size() > kFirst + kLast) kept_.erase(kept_.begin() + kFirst);
}

StepTrace StepTrace::recorded(std::vector<LoadState> kept, long count) {
  const long expected = count < static_cast<long>(kFirst + kLast) ? count : static_cast<long>(kFirst + kLast);
  if (count < 0 || static_cast<long>(kept.size()) != expected)
    throw std::invalid_argument(fmt::format("a step trace of {} states keeps {}, not {}", count, expected, kept.size()));
  StepTrace t;
  t.kept_ = std::move(kept);
  t.count_ = count;
  return t;
}

}  // namespace tunica
