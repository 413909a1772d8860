#include "solver/newton.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace tunica {

namespace {

/// Whether iteration k's correction is solved with the last factorization, (7.11): r = ‖R_k‖/‖R₀‖,
/// rho = ‖R_k‖/‖R_k−1‖. In the quadratic basin a Newton correction leaves about ρ² ‖R_k‖, one solved with
/// the factorization at u_k−1 about 2ρ ‖R_k‖ (7.12).
bool reuse_pays(const SolverSettings& settings, double r, double rho) {
  using Reuse = SolverSettings::FactorizationReuse;
  if (rho > 0.1 || r > 1e-4) return false;
  switch (settings.reuse_factorization) {
    case Reuse::last: return 2 * rho * r <= settings.residual_tolerance;
    case Reuse::basin: return true;
    default: return false;
  }
}

}  // namespace

NewtonResult newton(NonlinearProblem& problem, LinearSolver& solver, const SolverSettings& settings,
                    const std::function<void(const IterationRecord&)>& on_iteration, FirstCorrectionStrategy* first) {
  NewtonResult result;
  Eigen::VectorXd r, dx;
  double r0 = 0, e1 = 0, energy = 0, previous_residual = 0;
  double slope0 = 0;  // Δx·r(x) of the correction Δx being tried (line search; halved with it)
  int k0 = 0;
  std::vector<double> residuals;  // ‖R‖ of every iteration of this attempt
  bool factored = false;           // the solver holds a factorization of this attempt's Jacobian
  bool contact_step_taken = false;  // a whole correction into contact was kept though ‖r‖ rose
  if (first) {
    if (auto f = first->take(solver, on_iteration)) {
      dx = std::move(f->dx);
      r0 = previous_residual = f->reference_residual;
      slope0 = f->slope;
      e1 = std::abs(f->slope);
      k0 = 1;
    }
  }
  for (int k = k0;; ++k) {
    IterationRecord rec;
    rec.iteration = k;
    double scale = 0;
    const auto t0 = std::chrono::steady_clock::now();
    std::string inadmissible;
    for (;;) {  // line search, (7.4)
      inadmissible.clear();
      try {
        scale = problem.evaluate(r);
        rec.residual = problem.residual_norm(r);
      } catch (const std::domain_error& e) {
        inadmissible = e.what();
      }
      // Kept when ‖r‖ fell, or when the step went at least halfway to the energy's stationary
      // point along Δx (from a stress-free membrane the first correction can raise ‖r‖ through
      // stiff in-plane modes of little energy while leaving a small slope).
      const bool slope_ok = inadmissible.empty() && std::isfinite(rec.residual) && k > 0 && slope0 != 0 &&
                            std::abs(problem.work(dx, r)) <= 0.5 * std::abs(slope0);
      // The first whole correction of an attempt that brings nodes into contact is kept though ‖r‖
      // rose: the penalty forces of the overshoot are what the next tangent, with those nodes
      // active, corrects; halved, it would stop short of the surface and let the active set grow a
      // node or two per iteration. Once only: later ones are searched as any (theory manual (7.4)).
      const bool entering = !contact_step_taken && rec.backtracks == 0 && inadmissible.empty() &&
                            problem.entering_contact() > 0;
      const bool worse = !inadmissible.empty() || !std::isfinite(rec.residual) ||
                         (rec.residual > previous_residual && !slope_ok && !entering);
      if (k == 0 || !worse || !problem.allows_backtracking() || !settings.line_search ||
          rec.backtracks == settings.line_search_halvings) {
        contact_step_taken = contact_step_taken || (k > 0 && entering && rec.residual > previous_residual);
        break;
      }
      ++rec.backtracks;
      problem.step(dx, -0.5);  // back to half the correction taken so far
      dx *= 0.5;               // the correction actually taken
      slope0 *= 0.5;           // Δx·r(x) along it
    }
    if (!inadmissible.empty()) {
      result.failure = inadmissible;
      return result;
    }
    problem.describe(rec);
    if (rec.active_changes > 0) ++result.active_set_changes;
    result.active_contacts = rec.active_contacts;
    rec.assembly_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    previous_residual = rec.residual;
    if (k == 0 || (problem.yardstick_after_first_correction() && k == 1)) r0 = std::max(r0, rec.residual);
    if (k > 0) energy = std::abs(problem.work(dx, r));  // last correction · new residual
    rec.relative_residual = r0 > 0 ? rec.residual / r0 : 0.0;
    rec.energy = energy;
    rec.relative_energy = e1 > 0 ? energy / e1 : 0.0;
    result.last_relative_residual = rec.relative_residual;
    result.last_residual = rec.residual;
    result.last_force_scale = scale;
    result.residual_falling = residuals.size() >= 2 && rec.residual < residuals.back() &&
                              residuals.back() < residuals[residuals.size() - 2];
    result.iterations = k;
    if (!std::isfinite(rec.residual)) {
      on_iteration(rec);
      result.failure = "the residual is not finite";
      return result;
    }
    const bool side = problem.side_conditions_hold(settings.residual_tolerance);
    const bool at_roundoff = rec.residual <= settings.roundoff_tolerance * scale && side;
    const bool residual_met = k > 0 && rec.residual <= settings.residual_tolerance * r0 && side;
    const bool tests = residual_met && (e1 == 0 || energy <= settings.energy_tolerance * e1);
    if (at_roundoff || tests) {
      on_iteration(rec);
      result.converged = true;
      return result;
    }
    if (k > 0 && rec.residual > settings.divergence_ratio * r0) {
      on_iteration(rec);
      result.failure = "diverging";
      return result;
    }
    residuals.push_back(rec.residual);
    const std::size_t n = residuals.size();
    // Stagnating: the last m + 1 residuals lie within 10 % of each other (neither falling nor
    // climbing out: a residual that rises and falls is still searching).
    const auto flat = [&](int m) {
      if (m <= 0 || n <= static_cast<std::size_t>(m)) return false;
      const auto [lo, hi] = std::minmax_element(residuals.end() - (m + 1), residuals.end());
      return *hi < *lo / 0.9;
    };
    // The residual test of (7.2) holds and the energy test does not: the failure says which.
    const auto energy_stalled = [&] {
      if (!residual_met) return std::string();
      result.energy_stall = rec.relative_energy;
      return fmt::format("; ‖R‖ met `residual_tolerance` ({:.3g} ≤ {:g}), the energy test did not (|Δu·R| at "
                         "{:.3g} of |Δu₁·R₀|, above `energy_tolerance` {:g})",
                         rec.relative_residual, settings.residual_tolerance, rec.relative_energy,
                         settings.energy_tolerance);
    };
    if (const int m = settings.stagnation_iterations; flat(m)) {
      on_iteration(rec);
      result.failure = fmt::format("stagnating (‖R‖ within 10 % over the last {} iterations)", m) + energy_stalled();
      return result;
    }
    if (k >= settings.max_iterations) {
      // Past the limit only while converging surely: each of the last three iterations halved ‖R‖
      // at a rate that improves by 10 % each time (q₁ < 0.9 q₂ < 0.81 q₃ ≤ 0.405, Newton entering
      // its quadratic basin). A steady
      // rate is not enough: far out on an exponential material each correction removes a fixed
      // part of the exponent, and ‖R‖ falls at a constant rate from an absurd R₀.
      const auto q = [&](std::size_t i) { return residuals[n - i] / residuals[n - i - 1]; };
      const bool contracting = n >= 4 && q(3) <= 0.5 && q(2) < 0.9 * q(3) && q(1) < 0.9 * q(2);
      if (!contracting || k >= settings.max_iterations_contracting) {
        on_iteration(rec);
        result.failure = fmt::format("no convergence in {} iterations", k) + energy_stalled();
        return result;
      }
    }
    // A reused factorization, (7.11): the correction is solved with the factorization of an
    // earlier iteration of this attempt. One that is not finite or beyond the credible size is
    // solved afresh; one that converges poorly makes the next iteration factorize (its ratio fails
    // the test). Not for the last iterate the limit allows: a correction that converges less
    // than predicted there would fail the attempt.
    if (factored && problem.allows_factorization_reuse() && rec.active_changes == 0 && n >= 2 &&
        k + 1 < settings.max_iterations &&
        reuse_pays(settings, rec.relative_residual, residuals[n - 1] / residuals[n - 2])) {
      const auto t = std::chrono::steady_clock::now();
      dx = solver.solve(-r);
      rec.solve_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
      if (dx.allFinite() && dx.cwiseAbs().maxCoeff() <= problem.max_correction()) {
        rec.solver = solver.used() + std::string(kReusedFactorization);
        on_iteration(rec);
        slope0 = problem.work(dx, r);
        problem.step(dx, 1.0);
        continue;
      }
    }
    const TangentMatrix& J = problem.jacobian(k);
    std::string note;
    const double reuse_solve_seconds = rec.solve_seconds;
    const bool solved = solve_perturbed(solver, J, Eigen::VectorXd(-r), problem.allows_perturbation(),
                                        problem.max_correction(), dx, note, rec.factor_seconds, rec.solve_seconds);
    rec.solve_seconds += reuse_solve_seconds;
    rec.solver = solver.used() + note;
    if (!note.empty()) ++result.perturbed;
    factored = solved && note.empty();
    if (!solved) {
      on_iteration(rec);
      const std::string refusal = solver.refusal();
      result.singular = refusal.empty();
      result.failure = refusal.empty() ? "the tangent matrix is singular"
                                       : "the linear solver could not factorize the tangent: " + refusal;
      return result;
    }
    on_iteration(rec);
    slope0 = problem.work(dx, r);
    if (k == 0) e1 = std::abs(slope0);  // first correction · R₀
    problem.step(dx, 1.0);
  }
}

}  // namespace tunica
