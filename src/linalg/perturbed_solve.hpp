#pragma once
// A linear solve that survives a singular Newton tangent by perturbing its diagonal.
#include <string>

#include "linalg/linear_solver.hpp"

namespace tunica {

/// Factorizes M and solves M x = b. If M is singular — the factorization fails, x is not
/// finite, or x moves a DOF farther than `max_step` (Newton passes the problem's largest
/// credible correction: a near-null mode amplified by a tiny pivot) — and `allow_shift`, retries
/// with the diagonal perturbed, M + δ diag(|M_ii|), δ = 1e-6, 1e-4, 1e-2 in turn (a zero diagonal
/// entry: δ times the largest): a pivot perturbation as in PARDISO or MUMPS. The residual is
/// untouched, so a converged state is exact; only the Newton direction changes, in the near-null
/// modes: those of a membrane without stress (the inextensional modes of a cylinder, an
/// unstressed flat region), which the stress of the next iterates stiffens. `note` is "+shift"
/// when the perturbation was used; the seconds of all attempts are added up. False if every
/// attempt fails; without `allow_shift`, a finite x beyond `max_step` is kept (true).
bool solve_perturbed(LinearSolver& solver, const TangentMatrix& M, const Eigen::VectorXd& b, bool allow_shift,
                     double max_step, Eigen::VectorXd& x, std::string& note, double& factor_seconds,
                     double& solve_seconds);

}  // namespace tunica
