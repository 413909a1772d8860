#pragma once
// Newton–Raphson for one load increment: R(u) = 0 on the free DOFs with the
// consistent tangent K = ∂R/∂u (theory manual §7). Newton sees the residual and the
// Jacobian only.
#include <functional>

#include "assembly/system.hpp"
#include "model/model.hpp"
#include "linalg/linear_solver.hpp"

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
                                  ///< singular and its diagonal was perturbed by 1e-6 |K_ii| (newton.cpp)
  double assembly_seconds = 0;
  double factor_seconds = 0;      ///< numeric factorization (+ symbolic analysis on the first of a step)
  double solve_seconds = 0;       ///< forward/back substitution
};

struct NewtonResult {
  bool converged = false;
  int iterations = 0;
  std::string failure;  ///< why it did not converge
  double last_relative_residual = 0;
  int perturbed = 0;  ///< iterations whose singular tangent was solved with a perturbed diagonal (newton.cpp)
};

/// An enclosed-volume constraint V(u) = target whose pressure (of `load`) is an unknown.
struct VolumeConstraint {
  int load = -1;
  double target = 0;
};

/// Factorizes M and solves M x = b. If M is singular — the factorization fails, x is not
/// finite, or x moves a DOF farther than `max_step` (Newton passes ten times the model's size:
/// a near-null mode amplified by a tiny pivot) — and `allow_shift`, retries with the diagonal
/// perturbed, M + δ diag(|M_ii|), δ = 1e-6, 1e-4, 1e-2 in turn (a zero diagonal entry: δ times
/// the largest): a pivot perturbation as in PARDISO or MUMPS. The residual is untouched, so a
/// converged state is exact; only the Newton direction changes, in the near-null modes: those
/// of a membrane without stress (the inextensional modes of a cylinder, an unstressed flat
/// region), which the stress of the next iterates stiffens. `note` is "+shift" when the
/// perturbation was used; the seconds of all attempts are added up. False if every attempt fails.
bool solve_perturbed(LinearSolver& solver, const SparseMatrix& M, const Eigen::VectorXd& b, bool allow_shift,
                     double max_step, Eigen::VectorXd& x, std::string& note, double& factor_seconds,
                     double& solve_seconds);

/// Iterates on u (prescribed DOFs already set; theory manual (7.1)) until the convergence tests
/// of `settings` hold, (7.2): ‖R‖ ≤ tol_r ‖R₀‖ and |Δu·R| ≤ tol_e |Δu₁·R₀|, or ‖R‖ at
/// round-off (≤ settings.roundoff_tolerance of the force scale of System::assemble). On failure u is left as it was last.
/// With a volume constraint the pressure loads.pressure[constraint->load] is a further
/// unknown: the bordered system (7.5) [K −g; ∂V/∂uᵀ 0] [Δu; Δp] = −[R; V − target]
/// (g = ∂f_ext/∂p) is solved as one sparse matrix, which stays regular at a
/// pressure maximum, and |V − target| ≤ tol_r |target| is required too.
///
/// Tangent predictor (settings.tangent_predictor, no volume constraint): given the last
/// converged state u_n (`converged`; u differs from it on prescribed DOFs only), the first
/// correction is not computed at u (where the moved boundary nodes alone have taken the
/// whole prescribed increment Δu_p, e.g. one ring of elements stretched several-fold) but
/// linearized at u_n, theory manual (7.3):
///   K_ff(u_n) Δu_f = −R_f(u_n) − K_fp(u_n) Δu_p,
/// with the new loads. K_fp Δu_p, the directional derivative of R along Δu_p, is taken by
/// central differences, (R(u_n + hΔu_p) − R(u_n − hΔu_p))/2h with h = 1e-6 (error
/// O(h²) ≈ 1e-12 relative; it moves the predictor only, Newton then converges to the exact
/// solution). Its norm is R₀ (what the plain start's residual is for a linear model), and
/// the predictor counts as the first iteration. If K(u_n) cannot be factorized or u_n is not
/// admissible under the new loads, Newton starts plainly from u.
///
/// Stress-free start (settings.stiffen_stress_free_start, no volume constraint): when the increment
/// starts at the reference state (u_n = 0), the first correction — the predictor's, or iteration
/// 0's — is computed with K + K₀, K₀ the normal-tension stiffness of a Laplace tension estimate on
/// every pressurized 3-D membrane element (System::add_start_stiffness; theory manual §7.2, (7.6)–(7.8)). A
/// stress-free membrane resists the relative normal motion of its nodes only with its facets'
/// in-plane stiffness, which is mesh-irregular (a cube-sphere's valence-3 corner) and vanishes as
/// the mesh is refined (a cylinder's inextensional modes), while the pressure's load stiffness
/// pushes them out: the plain first correction dimples the surface, and the tangent is indefinite
/// (UMFPACK, not CHOLMOD). K₀ acts on the normal displacement's gradient only, so a uniform
/// expansion and in-plane stretching are untouched. The predictor's right-hand side gets
/// K₀_fp Δu_p (K₀ is the Hessian of ½ (u − u_n)ᵀ K₀ (u − u_n)); R₀, the residual and the later
/// tangents are exact, so the converged state is the same as without it.
NewtonResult newton(const System& system, LinearSolver& solver, LoadState& loads, Eigen::VectorXd& u,
                    const SolverSettings& settings, const std::function<void(const IterationRecord&)>& on_iteration,
                    const VolumeConstraint* constraint = nullptr, const Eigen::VectorXd* converged = nullptr);

}  // namespace tunica
