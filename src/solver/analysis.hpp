#pragma once
// Steps and increments: each step ramps its boundary and load targets
// linearly; each increment is solved by Newton. An increment that does not
// converge is halved and retried (at most `max_cutbacks` times in a row), and
// the increment size grows back after two converged reduced increments.
#include <string>

#include "assembly/system.hpp"
#include "solver/newton.hpp"

namespace tunica {

struct IncrementInfo {
  int step = 0;            ///< 1-based
  std::string step_name;
  int increment = 0;       ///< 1-based converged increment within the step
  int attempt = 0;         ///< 0 for the first try of this increment, +1 per cut-back
  double fraction = 0;     ///< fraction of the step done at the end of the increment
  double time = 0;         ///< step − 1 + fraction
  int iterations = 0;      ///< Newton iterations of the converged attempt
};

class Analysis;

/// What a run reports to (output writers, progress, tests).
class AnalysisObserver {
public:
  virtual ~AnalysisObserver() = default;
  virtual void on_iteration(const IncrementInfo&, const IterationRecord&) {}
  virtual void on_cutback(const IncrementInfo&, const std::string& /*why*/) {}
  /// After each converged increment, and once for the reference state (step 0).
  virtual void on_increment(const Analysis&, const IncrementInfo&) {}
};

class Analysis {
public:
  explicit Analysis(const Model& model);
  /// Runs every step. Throws SolveError when an increment cannot converge;
  /// every converged increment has been reported before.
  void run(AnalysisObserver& observer);

  const Model& model() const { return model_; }
  const System& system() const { return system_; }
  const Eigen::VectorXd& displacement() const { return u_; }
  const LoadState& loads() const { return loads_; }
  /// Reaction forces: R = f_int − f_ext at prescribed DOFs (0 elsewhere), at the last converged state.
  const Eigen::VectorXd& reactions() const { return reactions_; }

private:
  void update_reactions();
  const Model& model_;
  System system_;
  Eigen::VectorXd u_;
  LoadState loads_;
  Eigen::VectorXd reactions_;
};

}  // namespace tunica
