#include "solver/tangent_predictor.hpp"

#include <chrono>
#include <cmath>
#include <stdexcept>

#include "linalg/perturbed_solve.hpp"
#include "solver/newton.hpp"

namespace tunica {

std::optional<FirstCorrection> TangentPredictor::take(
    LinearSolver& solver, const std::function<void(const IterationRecord&)>& on_iteration) {
  const System& system = problem_.system();
  const LoadState& loads = problem_.loads();
  Eigen::VectorXd& u = problem_.state();
  TangentMatrix& K = problem_.raw_jacobian();
  const Eigen::VectorXd dp = u - un_;  // the prescribed increment (zero on free DOFs)
  if (dp.size() == 0 || dp.cwiseAbs().maxCoeff() == 0) return std::nullopt;
  constexpr double h = 1e-6;
  IterationRecord rec;
  rec.relative_energy = 0;  // as at any iteration 0: no correction has been taken yet
  std::vector<char> active_set;
  const auto t0 = std::chrono::steady_clock::now();
  Eigen::VectorXd R, Rp, Rm;
  try {
    system.assemble(un_ + h * dp, loads, Rp, nullptr);
    system.assemble(un_ - h * dp, loads, Rm, nullptr);
    system.assemble(un_, loads, R, &K, nullptr, &rec.active_contacts, &active_set);
  } catch (const std::domain_error&) {
    return std::nullopt;  // u_n is not admissible under the new loads: start plainly
  }
  const Eigen::VectorXd plain = -(problem_.free_part(R) + problem_.free_part(Eigen::VectorXd((Rp - Rm) / (2 * h))));
  Eigen::VectorXd rhs = plain;  // the right-hand side without the start stiffness
  rec.residual = plain.norm();  // R₀: the yardstick of the tolerances
  if (stiffness_) rhs -= problem_.free_part(stiffness_->add(dp, K));  // K₀ on K_ff, and K₀_fp Δu_p
  rec.assembly_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!std::isfinite(rec.residual) || rec.residual == 0) return std::nullopt;
  FirstCorrection first;
  std::string note;
  if (!solve_perturbed(solver, K, rhs, true, problem_.max_correction(), first.dx, note, rec.factor_seconds,
                       rec.solve_seconds))
    return std::nullopt;
  rec.solver = solver.used() + note;
  problem_.set_active_set(std::move(active_set));  // iteration 1's changes are counted from u_n's
  on_iteration(rec);
  first.reference_residual = rec.residual;
  first.slope = -first.dx.dot(plain);  // Δu·(R_f + K_fp Δu_p): the energy slope along the correction (K₀ left out)
  problem_.step(first.dx, 1.0);
  return first;
}

}  // namespace tunica
