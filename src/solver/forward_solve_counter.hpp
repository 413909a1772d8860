#pragma once
// The observer of the forward solves inside an inverse step's iterations (fixed point, prestress:
// solver/analysis.hpp): it counts them and passes their Newton iterations, cut-backs and retries on.
#include "solver/analysis.hpp"

namespace tunica {

/// Counts what the forward solve of a fixed-point iteration does and passes its Newton iterations,
/// cut-backs and retries on; its converged increments are not states of the run.
class ForwardSolveCounter final : public AnalysisObserver {
public:
  explicit ForwardSolveCounter(AnalysisObserver& outer) : outer_(outer) {}
  int increments = 0, newton_iterations = 0, cutbacks = 0;
  void on_iteration(const IncrementInfo& i, const IterationRecord& r) override { outer_.on_iteration(i, r); }
  void on_cutback(const IncrementInfo& i, const std::string& why) override {
    ++cutbacks;
    outer_.on_cutback(i, why);
  }
  void on_retry(const IncrementInfo& i, const std::string& why, const std::string& how) override {
    outer_.on_retry(i, why, how);
  }
  void on_increment(const Analysis&, const IncrementInfo& i) override {
    ++increments;
    newton_iterations += i.iterations;
  }
  bool stop_requested() override { return outer_.stop_requested(); }

private:
  AnalysisObserver& outer_;
};

}  // namespace tunica
