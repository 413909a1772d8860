#pragma once
// A strategy for the first correction of an increment, in place of Newton's plain one at the
// start state (solver/newton.hpp): the tangent predictor (solver/tangent_predictor.hpp).
#include <functional>
#include <optional>

#include <Eigen/Core>

namespace tunica {

class LinearSolver;
struct IterationRecord;

/// What Newton carries on from a first correction already taken (the problem's state moved by dx).
struct FirstCorrection {
  Eigen::VectorXd dx;            ///< the correction taken
  double reference_residual = 0; ///< R₀, the yardstick of the residual tolerance (7.2)
  double slope = 0;              ///< dx · R along it (line search (7.4)); |slope| is the energy yardstick
};

/// The contract with Newton (solver/newton.cpp), which calls take() once, before its loop:
///  - On success the strategy has moved the problem's state by `dx` and reported iteration 0
///    through `on_iteration` itself (residual, relative_energy 0, solver and timings; the
///    problem's own columns, which MechanicalProblem::describe would fill); Newton then starts
///    at iteration 1, re-evaluating the moved state. Newton's iteration-0 tests (round-off, a
///    non-finite R₀) do not run: the strategy declines (nullopt) where they would end the
///    increment, and Newton starts plainly.
///  - `reference_residual` is R₀ of the tolerances (7.2); `slope` is dx·R along the correction,
///    the line search's slope (7.4), and |slope| the energy yardstick.
///  - Tangent hooks of iteration 0 (solver/tangent_hooks.hpp) are not applied by Newton after a
///    strategy (its loop starts at 1): a strategy that solves applies what it wants itself, as
///    TangentPredictor does with StartStiffness.
///  - It may hold references to the problem and to data of the increment: it lives, like the
///    problem and its hooks, inside solve_increment (solver/increment.cpp). Data from earlier
///    increments (u_{n−1}) reach solve_increment from solver/analysis.cpp, which keeps the
///    converged states; a restart holds the last converged state only (output/restart_file.hpp).
class FirstCorrectionStrategy {
public:
  virtual ~FirstCorrectionStrategy() = default;
  /// Takes the first correction, reporting it as iteration 0; std::nullopt (state untouched) when
  /// it does not apply, and Newton starts plainly.
  virtual std::optional<FirstCorrection> take(LinearSolver& solver,
                                              const std::function<void(const IterationRecord&)>& on_iteration) = 0;
};

}  // namespace tunica
