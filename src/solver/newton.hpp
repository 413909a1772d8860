#pragma once
// Newton–Raphson for one load increment: R(u) = 0 on the free DOFs with the
// consistent tangent K = ∂R/∂u. Newton sees the residual and the Jacobian only.
#include <functional>

#include "assembly/system.hpp"
#include "model/model.hpp"
#include "solver/linear_solver.hpp"

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
  std::string solver;             ///< the linear solver that factorized K (empty: no solve)
  double assembly_seconds = 0;
  double factor_seconds = 0;      ///< numeric factorization (+ symbolic analysis on the first of a step)
  double solve_seconds = 0;       ///< forward/back substitution
};

struct NewtonResult {
  bool converged = false;
  int iterations = 0;
  std::string failure;  ///< why it did not converge
  double last_relative_residual = 0;
};

/// An enclosed-volume constraint V(u) = target whose pressure (of `load`) is an unknown.
struct VolumeConstraint {
  int load = -1;
  double target = 0;
};

/// Iterates on u (prescribed DOFs already set) until the convergence tests of
/// `settings` hold: ‖R‖ ≤ tol_r ‖R₀‖ and |Δu·R| ≤ tol_e |Δu₁·R₀|, or ‖R‖ at
/// round-off (≤ 1e-14 of the force scale of System::assemble). On failure u is left as it was last.
/// With a volume constraint the pressure loads.pressure[constraint->load] is a further
/// unknown: the bordered system [K −g; ∂V/∂uᵀ 0] [Δu; Δp] = −[R; V − target]
/// (g = ∂f_ext/∂p) is solved as one sparse matrix, which stays regular at a
/// pressure maximum, and |V − target| ≤ tol_r |target| is required too.
NewtonResult newton(const System& system, LinearSolver& solver, LoadState& loads, Eigen::VectorXd& u,
                    const SolverSettings& settings, const std::function<void(const IterationRecord&)>& on_iteration,
                    const VolumeConstraint* constraint = nullptr);

}  // namespace tunica
