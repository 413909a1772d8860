#pragma once
// Newton–Raphson on a NonlinearProblem (theory manual §7): the problem's residual, its Jacobian,
// its admissibility and its record; the line search (7.4), the convergence tests (7.2), the
// divergence and iteration limits, all declared settings (model/solver_settings.hpp). What one
// load increment adds to this — free DOFs, contact, the volume constraint, the stiffened start,
// symmetrization, the tangent predictor — is composed in solver/increment.hpp.
#include <functional>
#include <string>

#include "linalg/linear_solver.hpp"
#include "linalg/perturbed_solve.hpp"
#include "model/solver_settings.hpp"
#include "solver/first_correction.hpp"
#include "solver/nonlinear_problem.hpp"

namespace tunica {

/// One Newton iteration, for newton.csv and the progress line.
struct IterationRecord {
  int iteration = 0;             ///< 0 = residual before the first correction
  double residual = 0;           ///< ‖R_free‖ (force units)
  double relative_residual = 1;  ///< ‖R‖ / ‖R₀‖
  double energy = 0;             ///< |Δu_k · R_k|: last correction against the residual it left
  double relative_energy = 1;    ///< energy / |Δu_1 · R_0|
  int backtracks = 0;             ///< line-search halvings of the last correction before this residual
  int active_contacts = 0;        ///< active contact slave nodes at this residual
  int active_changes = 0;         ///< slave nodes whose contact status (active or not) differs from the
                                  ///< previous iteration's of this attempt (0 at the first residual)
  std::string solver;             ///< the linear solver that factorized K (empty: no solve); "+shift": K was
                                  ///< singular and its diagonal was perturbed (linalg/perturbed_solve.hpp);
                                  ///< "+reused": solved with an earlier iteration's factorization, (7.11)
  double assembly_seconds = 0;
  double factor_seconds = 0;      ///< numeric factorization (+ symbolic analysis on the first of a step)
  double solve_seconds = 0;       ///< forward/back substitution
};

/// The suffix of IterationRecord::solver for a correction solved with an earlier factorization.
inline constexpr const char* kReusedFactorization = "+reused";

struct NewtonResult {
  bool converged = false;
  int iterations = 0;
  std::string failure;  ///< why it did not converge
  double last_relative_residual = 0;
  double last_residual = 0;     ///< ‖R‖ of the last iterate (force units)
  double last_force_scale = 0;  ///< the forces that cancel in that R (NonlinearProblem::evaluate)
  bool residual_falling = false;  ///< ‖R‖ fell in each of the last two iterations
  int perturbed = 0;  ///< iterations whose singular tangent was solved with a perturbed diagonal
  /// Iterations of the attempt whose contact active set differed from the iteration before's
  /// (IterationRecord::active_changes > 0), and the active contact nodes at its last residual.
  int active_set_changes = 0;
  int active_contacts = 0;
  /// The attempt stopped on a singular tangent (`failure` says so; why, the model's holds or the
  /// load, is for the caller to tell: solver/failure_hints.hpp).
  /// The increment's first correction was the stiffened start (theory manual §7.2): a plain retry
  /// differs from this attempt.
  bool stiffened_start = false;
  bool singular = false;
  /// > 0: at the last iterate the residual test of (7.2) held and the energy test did not; the
  /// relative energy |Δx·r| / |Δx₁·R₀| it stalled at (`failure` says so).
  double energy_stall = 0;
};

/// Iterates on the problem's state until the tests of `settings` hold, (7.2):
/// ‖r‖ ≤ tol_r ‖R₀‖ and |Δx·r| ≤ tol_e |Δx₁·R₀| and the side conditions, or ‖r‖ at round-off
/// (≤ settings.roundoff_tolerance times the force scale of evaluate()) with the side conditions.
/// The norm and the work are the problem's (NonlinearProblem::residual_norm, work).
///
/// Each correction solves J Δx = −r with J = problem.jacobian(k) (solve_perturbed: a singular J
/// is retried with a perturbed diagonal where the problem allows it). Backtracking line search
/// (7.4), where the problem allows it: a correction that raises ‖r‖, makes it non-finite or
/// leaves the admissible states is halved, up to settings.line_search_halvings times, unless it
/// took the work along it down to half, |Δx·r(x + Δx)| ≤ ½ |Δx·r(x)|. The full step is always
/// tried first, so quadratic convergence is untouched near a solution.
///
/// `first`, if given, may take the first correction itself (solver/first_correction.hpp); it
/// then counts as iteration 0 and its R₀ and slope are the yardsticks. On failure the state is
/// left as it was last.
NewtonResult newton(NonlinearProblem& problem, LinearSolver& solver, const SolverSettings& settings,
                    const std::function<void(const IterationRecord&)>& on_iteration,
                    FirstCorrectionStrategy* first = nullptr);

}  // namespace tunica
