#pragma once
// The tangent predictor (theory manual (7.3)): when prescribed displacements move, the first
// correction is not computed at u (where the moved boundary nodes alone have taken the whole
// prescribed increment Δu_p, e.g. one ring of elements stretched several-fold) but linearized
// at the last converged state u_n, with the new loads:
//   K_ff(u_n) Δu_f = −R_f(u_n) − K_fp(u_n) Δu_p.
// K_fp Δu_p, the directional derivative of R along Δu_p, is taken by central differences,
// (R(u_n + hΔu_p) − R(u_n − hΔu_p))/2h with h = 1e-6 (error O(h²) ≈ 1e-12 relative; it moves
// the predictor only, Newton then converges to the exact solution). Its norm is R₀ (what the
// plain start's residual is for a linear model), and the predictor counts as iteration 0. If
// K(u_n) cannot be factorized or u_n is not admissible under the new loads, it does not apply.
//
// With the stiffened start (solver/tangent_hooks.hpp, StartStiffness) the predictor's matrix is
// K + K₀ and its right-hand side gets −K₀_fp Δu_p (K₀ is the Hessian of ½ (u − u_n)ᵀ K₀ (u − u_n));
// R₀ and the slope are those of the exact residual.
#include "solver/first_correction.hpp"
#include "solver/mechanical_problem.hpp"

namespace tunica {

class TangentPredictor : public FirstCorrectionStrategy {
public:
  /// `converged`: u_n (all DOFs); the problem's state differs from it on prescribed DOFs only.
  /// `stiffness`: the start stiffness to add, or nullptr.
  TangentPredictor(MechanicalProblem& problem, const Eigen::VectorXd& converged, const StartStiffness* stiffness)
      : problem_(problem), un_(converged), stiffness_(stiffness) {}
  std::optional<FirstCorrection> take(LinearSolver& solver,
                                      const std::function<void(const IterationRecord&)>& on_iteration) override;

private:
  MechanicalProblem& problem_;
  const Eigen::VectorXd& un_;
  const StartStiffness* stiffness_;
};

}  // namespace tunica
