#pragma once
// One load increment as Newton over a composed problem (theory manual §7): the equilibrium of
// the free DOFs (solver/mechanical_problem.hpp) with the tangent hooks the settings ask for
// (solver/tangent_hooks.hpp), bordered by a volume constraint when the step controls the enclosed
// volume (solver/bordered_problem.hpp), started by the tangent predictor when prescribed
// displacements move (solver/tangent_predictor.hpp).
#include <functional>

#include "assembly/system.hpp"
#include "solver/newton.hpp"

namespace tunica {

/// An enclosed-volume constraint V(u) = target whose pressure (of `load`) is an unknown.
struct VolumeConstraint {
  int load = -1;
  double target = 0;
};

/// Solves the increment from u (prescribed DOFs already set, theory manual (7.1)) under `loads`.
/// `converged`: the last converged state u_n (differs from u on prescribed DOFs only), or nullptr.
///  - Volume constraint: loads.pressure[constraint->load] is a further unknown, (7.5); no
///    predictor or symmetrization (the bordered matrix is solved as it is); from u_n = 0 with
///    settings.stiffen_stress_free_start, the first correction is stiffened with the pressure it
///    finds, (7.10) (solver/volume_start.hpp).
///  - settings.tangent_predictor and `converged`: the first correction is linearized at u_n, (7.3).
///  - settings.stiffen_stress_free_start and u_n = 0: the first correction (the predictor's, or
///    iteration 0's) is computed with K + K₀, (7.6)–(7.8). R₀, the residual and the later tangents
///    are exact, so the converged state is the same as without it.
///  - settings.symmetrize_pressure_stiffness: every plain correction with (K + Kᵀ)/2.
/// On failure u (and the constrained pressure) are left as they were last.
NewtonResult solve_increment(const System& system, LinearSolver& solver, LoadState& loads, Eigen::VectorXd& u,
                             const SolverSettings& settings,
                             const std::function<void(const IterationRecord&)>& on_iteration,
                             const VolumeConstraint* constraint = nullptr, const Eigen::VectorXd* converged = nullptr,
                             bool slack_start = false);

}  // namespace tunica
