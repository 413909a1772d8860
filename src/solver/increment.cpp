#include "solver/increment.hpp"

#include <memory>
#include <optional>

#include "solver/bordered_problem.hpp"
#include "solver/tangent_predictor.hpp"
#include "solver/volume_start.hpp"

namespace tunica {

namespace {

/// A step of a 3-D model with no pressure on any membrane: the increment ends with every pressure
/// at 0 (theory manual §7.3).
bool slack_step(const System& system, const LoadState& loads) {
  if (system.model().dofs_per_node() != 3) return false;
  for (double p : loads.pressure)
    if (p != 0) return false;
  return true;
}

}  // namespace

NewtonResult solve_increment(const System& system, LinearSolver& solver, LoadState& loads, Eigen::VectorXd& u,
                             const SolverSettings& settings,
                             const std::function<void(const IterationRecord&)>& on_iteration,
                             const VolumeConstraint* constraint, const Eigen::VectorXd* converged, bool slack_start) {
  // The tangent's upper triangle is assembled only for a consumer that reads it: the solver (all
  // but CHOLMOD: `auto`'s symmetry test, the LU solvers), the symmetrization and the bordered
  // system. For CHOLMOD alone the lower triangle is the whole matrix it factorizes.
  // The inverse problem's tangent is not symmetric (theory manual §13): both triangles, never symmetrized.
  const bool inverse = system.inverse(loads);
  const bool upper = solver.reads_upper() || settings.symmetrize_pressure_stiffness || constraint || inverse;
  MechanicalProblem equilibrium(system, loads, u, upper);
  // The increment starts at the stress-free reference state, or at a state without pressure that
  // the increment pressurizes (`slack_start`): its wall may carry no tension across the load either.
  const bool stress_free =
      converged && converged->size() > 0 && ((converged->array() == 0.0).all() || slack_start);
  if (constraint) {
    BorderedProblem bordered(equilibrium, loads, constraint->load, constraint->target);
    std::optional<VolumeStartStiffness> start;
    if (settings.stiffen_stress_free_start && stress_free) start.emplace(bordered, *converged, settings);
    NewtonResult r = newton(bordered, solver, settings, on_iteration, start ? &*start : nullptr);
    r.stiffened_start = start.has_value();
    return r;
  }
  const StartStiffness* stiffness = nullptr;
  bool stiffened = false;
  std::unique_ptr<StartStiffness> inverse_k0;  // the metric of a regularized tangent
  if (inverse) {
    // The inverse tangent is regularized at every iteration (13.11), the first included, also the
    // predictor's: the plain one moves the reference along its isometric modes.
    inverse_k0 = std::make_unique<StartStiffness>(system, loads);
    stiffness = inverse_k0.get();
    equilibrium.add_hook(std::make_unique<ScaledRegularization>(
        *inverse_k0, [&equilibrium] { return equilibrium.last_residual_norm(); }));
  } else if (slack_step(system, loads)) {
    // No pressure acts: a 3-D wall without hoop tension ovalizes freely, (7.14).
    inverse_k0 = std::make_unique<StartStiffness>(system, loads, true);
    stiffness = inverse_k0.get();
    equilibrium.add_hook(std::make_unique<ScaledRegularization>(
        *inverse_k0, [&equilibrium] { return equilibrium.last_residual_norm(); }));
  } else if (settings.stiffen_stress_free_start && stress_free) {
    stiffened = true;
    auto hook = std::make_unique<StartStiffness>(system, loads);
    stiffness = hook.get();
    equilibrium.add_hook(std::move(hook));
  }
  if (settings.symmetrize_pressure_stiffness && !inverse) equilibrium.add_hook(std::make_unique<Symmetrization>());
  std::optional<TangentPredictor> predictor;
  if (converged && settings.tangent_predictor) predictor.emplace(equilibrium, *converged, stiffness);
  NewtonResult r = newton(equilibrium, solver, settings, on_iteration, predictor ? &*predictor : nullptr);
  r.stiffened_start = stiffened;
  return r;
}

}  // namespace tunica
