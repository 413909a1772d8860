#include "solver/volume_start.hpp"

#include <chrono>
#include <cmath>
#include <stdexcept>

#include "linalg/perturbed_solve.hpp"
#include "materials/membrane_material.hpp"
#include "solver/newton.hpp"

namespace tunica {

namespace {

/// A pressure to seed p̂ with when the step starts at p = 0 on a surface that K alone does not hold
/// in the bordered system (a flat sheet: no curvature, so no pressure and no normal stiffness):
/// μ₀H/ℓ of the load's part, μ₀ its material's shear modulus at rest, H its thickness and ℓ its
/// size (the diagonal of its nodes' bounding box), the Laplace pressure of a wall of curvature 1/ℓ
/// at unit tension scale. 0 where the part has no membrane material.
double seed_pressure(const Model& m, int load) {
  const Part& part = m.parts[m.loads[load].part];
  if (!part.material || !(part.thickness > 0) || part.nodes.empty()) return 0;
  const MembraneResponse rest = membrane_response(*part.material, Eigen::Vector3d(1, 1, 0));
  const double mu0 = (rest.D(0, 0) + rest.D(1, 1)) / 8;
  Eigen::Vector3d lo = m.X[part.nodes.front()], hi = lo;
  for (int n : part.nodes) lo = lo.cwiseMin(m.X[n]), hi = hi.cwiseMax(m.X[n]);
  const double size = (hi - lo).norm();
  if (!(mu0 > 0) || !std::isfinite(mu0) || !(size > 0)) return 0;
  return mu0 * part.thickness / size;
}

}  // namespace

std::optional<FirstCorrection> VolumeStartStiffness::take(
    LinearSolver& solver, const std::function<void(const IterationRecord&)>& on_iteration) {
  MechanicalProblem& inner = problem_.inner();
  const System& system = inner.system();
  IterationRecord rec;
  rec.relative_energy = 0;  // as at any iteration 0: no correction has been taken yet
  const auto t0 = std::chrono::steady_clock::now();
  Eigen::VectorXd r;
  double scale = 0;
  try {
    scale = problem_.evaluate(r);
  } catch (const std::domain_error&) {
    return std::nullopt;  // Newton reports the inadmissible start itself
  }
  rec.residual = problem_.residual_norm(r);
  if (!std::isfinite(rec.residual)) return std::nullopt;
  // Newton's iteration-0 round-off test would end the increment here (nothing to correct).
  if (rec.residual <= settings_.roundoff_tolerance * scale && problem_.side_conditions_hold(settings_.residual_tolerance)) return std::nullopt;
  const int nf = inner.size();
  const Eigen::VectorXd dp = inner.state() - un_;  // the prescribed increment (zero on free DOFs)
  const bool moved = dp.size() > 0 && dp.cwiseAbs().maxCoeff() > 0;
  const TangentMatrix K = inner.raw_jacobian();  // the exact tangent at the start, without K₀
  const double pn = problem_.pressure();
  rec.assembly_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  FirstCorrection first;
  double estimate = pn;  // p̂: the pressure whose Laplace tension K₀ is built from
  for (int solve = 0; solve < kMaxSolves; ++solve) {
    TangentMatrix Ks = K;
    Eigen::VectorXd rhs = -r;
    if (estimate != 0) {
      LoadState at = inner.loads();
      at.pressure[problem_.load()] = estimate;
      const Eigen::VectorXd Kd = system.add_start_stiffness(at, moved ? dp : Eigen::VectorXd(), Ks);
      if (moved) rhs.head(nf) -= inner.free_part(Kd);  // the gradient of Q (7.6) at u_n + Δu_p
    }
    std::string note;
    if (!solve_perturbed(solver, problem_.bordered(Ks), rhs, false, problem_.max_correction(), first.dx, note,
                         rec.factor_seconds, rec.solve_seconds)) {
      // At rest on a flat sheet K alone leaves the normal modes free: seed p̂ once, then settle it.
      if (solve == 0 && estimate == 0 && (estimate = seed_pressure(system.model(), problem_.load())) > 0) continue;
      return std::nullopt;
    }
    rec.solver = solver.used() + note;
    const double pressure = pn + first.dx(nf);
    if (!std::isfinite(pressure)) return std::nullopt;
    if (solve > 0 && std::abs(pressure - estimate) <= 0.1 * std::abs(pressure)) break;  // p̂ settled
    if (solve == 0) {
      // No K₀ at that pressure (no pressurized membrane): the plain correction is Newton's own.
      LoadState at = inner.loads();
      at.pressure[problem_.load()] = pressure;
      TangentMatrix probe = K;
      probe.set_zero();
      system.add_start_stiffness(at, Eigen::VectorXd(), probe);
      if (probe.max_abs() == 0) return std::nullopt;
    }
    estimate = pressure;
  }
  problem_.describe(rec);  // of the start's evaluation (add_start_stiffness assembles nothing else)
  on_iteration(rec);
  first.reference_residual = rec.residual;
  first.slope = problem_.work(first.dx, r);  // Δx·r: the work along the correction (K₀ left out)
  problem_.step(first.dx, 1.0);
  return first;
}

}  // namespace tunica
