#pragma once
// The converged states of the step in progress that the hints of a failed increment read
// (failure_hints.hpp: the pressure–volume curve of each load over the step): the step's start,
// its first converged increment and the last three, with their count. It is part of the
// Checkpoint, so that a run continued with --restart gives the hints an uninterrupted run gives;
// the restart file keeps the states' pressures and volumes, which is all the hints read.
#include <cstddef>
#include <vector>

#include "assembly/system.hpp"

namespace tunica {

class StepTrace {
public:
  static constexpr std::size_t kFirst = 2;  ///< states kept from the step's start
  static constexpr std::size_t kLast = 3;   ///< states kept from its end

  /// Starts the trace of a step at its start state.
  void restart_at(const LoadState& start) {
    kept_.assign(1, start);
    count_ = 1;
  }
  /// Appends a converged state, dropping the states between the first kFirst and the last kLast.
  void push(const LoadState& s);
  /// States pushed since the step's start (the start counts); 0 for none.
  long count() const { return count_; }
  /// The k-th state of the step (k < kFirst, k < count()).
  const LoadState& first(std::size_t k) const { return kept_[k]; }
  /// The k-th state from the last (0: the last; k < kLast, k < count()).
  const LoadState& last(std::size_t k) const { return kept_[kept_.size() - 1 - k]; }
  /// The kept states, oldest first: all of them, or the first kFirst and the last kLast.
  const std::vector<LoadState>& kept() const { return kept_; }
  /// A trace as a restart file recorded it; throws std::invalid_argument if `kept` cannot be the
  /// states kept of `count` (too many, or too few for the count).
  static StepTrace recorded(std::vector<LoadState> kept, long count);

private:
  std::vector<LoadState> kept_;
  long count_ = 0;
};

}  // namespace tunica
