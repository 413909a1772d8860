#pragma once
// The stiffened first correction from a stress-free state under volume control (theory manual
// §7.2, (7.10)): the bordered system (7.5) solved with K + K₀(p̂), K₀ the normal-tension stiffness
// (7.7) of the Laplace tension (7.8) of the pressure p̂ — the pressure the correction itself
// finds. At rest the pressure is 0 and K alone is the stiffness of the unstressed flat facets:
// a tube's (a surface's without double curvature) non-uniform normal modes are nearly free, the
// pressure load excites them, and the plain correction buckles the wall into them. The pressure
// is unknown before the solve, so p̂ is iterated: p̂₀ = p_n, p̂ᵢ₊₁ = p_n + Δpᵢ, until the pressure
// a correction yields lies within 10 % of the p̂ it was stiffened with (a few solves; the Newton
// count does not depend on T₀ within a factor two, §7.2). Only the direction of the first
// correction changes: R₀, every residual and later tangent are exact.
#include "model/solver_settings.hpp"
#include "solver/bordered_problem.hpp"
#include "solver/first_correction.hpp"

namespace tunica {

class VolumeStartStiffness : public FirstCorrectionStrategy {
public:
  /// `converged`: u_n (all DOFs); the problem's state differs from it on prescribed DOFs only.
  VolumeStartStiffness(BorderedProblem& problem, const Eigen::VectorXd& converged, const SolverSettings& settings)
      : problem_(problem), un_(converged), settings_(settings) {}
  /// Declines (Newton starts plainly) where Newton's iteration 0 would end the increment (the
  /// target volume already holds), where no pressurized membrane gives K₀ (a model of shells
  /// or solids alone), or where the start is inadmissible or its bordered matrix singular.
  std::optional<FirstCorrection> take(LinearSolver& solver,
                                      const std::function<void(const IterationRecord&)>& on_iteration) override;

  /// The most bordered solves taken to settle p̂.
  static constexpr int kMaxSolves = 8;

private:
  BorderedProblem& problem_;
  const Eigen::VectorXd& un_;
  const SolverSettings& settings_;
};

}  // namespace tunica
