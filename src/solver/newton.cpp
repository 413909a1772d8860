#include "solver/newton.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <stdexcept>

namespace tunica {

namespace {
double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

NewtonResult newton(const System& system, LinearSolver& solver, const LoadState& loads, Eigen::VectorXd& u,
                    const SolverSettings& settings, const std::function<void(const IterationRecord&)>& on_iteration) {
  constexpr double kRoundoff = 1e-14;  // ‖R‖ below this fraction of the cancelling forces is round-off
  constexpr double kDivergence = 1e8;  // ‖R‖ above this multiple of ‖R₀‖ is divergence
  NewtonResult result;
  const int nf = system.num_free();
  Eigen::VectorXd R, Rf(nf);
  SparseMatrix K = system.pattern();
  double r0 = 0, e1 = 0, energy = 0;
  Eigen::VectorXd du;
  for (int k = 0;; ++k) {
    IterationRecord rec;
    rec.iteration = k;
    double scale = 0;
    const auto t0 = std::chrono::steady_clock::now();
    try {
      system.assemble(u, loads, R, &K, &scale);
    } catch (const std::domain_error& e) {
      result.failure = e.what();
      return result;
    }
    rec.assembly_seconds = seconds_since(t0);
    for (int i = 0; i < system.num_dofs(); ++i)
      if (system.equation(i) >= 0) Rf(system.equation(i)) = R(i);
    rec.residual = Rf.norm();
    if (k == 0) r0 = rec.residual;
    if (k > 0) energy = std::abs(du.dot(Rf));  // energy norm of the last correction against the new residual
    rec.relative_residual = r0 > 0 ? rec.residual / r0 : 0.0;
    rec.energy = energy;
    rec.relative_energy = e1 > 0 ? energy / e1 : 0.0;
    result.last_relative_residual = rec.relative_residual;
    result.iterations = k;
    if (!std::isfinite(rec.residual)) {
      on_iteration(rec);
      result.failure = "the residual is not finite";
      return result;
    }
    const bool at_roundoff = rec.residual <= kRoundoff * scale;
    const bool tests = k > 0 && rec.residual <= settings.residual_tolerance * r0 &&
                       (e1 == 0 || energy <= settings.energy_tolerance * e1);
    if (at_roundoff || tests) {
      on_iteration(rec);
      result.converged = true;
      return result;
    }
    if (k > 0 && rec.residual > kDivergence * r0) {
      on_iteration(rec);
      result.failure = "diverging";
      return result;
    }
    if (k == settings.max_iterations) {
      on_iteration(rec);
      result.failure = fmt::format("no convergence in {} iterations", settings.max_iterations);
      return result;
    }
    const auto t1 = std::chrono::steady_clock::now();
    if (!solver.factorize(K)) {
      rec.solve_seconds = seconds_since(t1);
      on_iteration(rec);
      result.failure = "the tangent matrix is singular (is the model held against rigid-body motion?)";
      return result;
    }
    du = solver.solve(-Rf);
    rec.solve_seconds = seconds_since(t1);
    if (!du.allFinite()) {
      on_iteration(rec);
      result.failure = "the tangent matrix is singular (is the model held against rigid-body motion?)";
      return result;
    }
    on_iteration(rec);
    if (k == 0) e1 = std::abs(du.dot(Rf));  // reference: first correction against the initial residual
    for (int i = 0; i < system.num_dofs(); ++i)
      if (system.equation(i) >= 0) u(i) += du(system.equation(i));
  }
}

}  // namespace tunica
