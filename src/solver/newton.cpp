#include "solver/newton.hpp"

#include "linalg/matrix_symmetry.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <optional>
#include <stdexcept>

namespace tunica {

namespace {
double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// The pattern of K bordered by a full last column and row (index nf).
SparseMatrix bordered_pattern(const SparseMatrix& K) {
  const int nf = static_cast<int>(K.cols());
  SparseMatrix A(nf + 1, nf + 1);
  A.resizeNonZeros(K.nonZeros() + 2 * nf + 1);
  int* outer = A.outerIndexPtr();
  int* inner = A.innerIndexPtr();
  int k = 0;
  for (int j = 0; j < nf; ++j) {
    outer[j] = k;
    for (int q = K.outerIndexPtr()[j]; q < K.outerIndexPtr()[j + 1]; ++q) inner[k++] = K.innerIndexPtr()[q];
    inner[k++] = nf;
  }
  outer[nf] = k;
  for (int i = 0; i <= nf; ++i) inner[k++] = i;
  outer[nf + 1] = k;
  std::fill(A.valuePtr(), A.valuePtr() + k, 0.0);
  return A;
}

/// Fills the bordered matrix A (pattern of bordered_pattern) from K, the column −g and the row ∂V/∂u.
void fill_bordered(const SparseMatrix& K, const Eigen::VectorXd& g, const Eigen::VectorXd& dV, SparseMatrix& A) {
  const int nf = static_cast<int>(K.cols());
  double* a = A.valuePtr();
  int k = 0;
  for (int j = 0; j < nf; ++j) {
    for (int q = K.outerIndexPtr()[j]; q < K.outerIndexPtr()[j + 1]; ++q) a[k++] = K.valuePtr()[q];
    a[k++] = dV(j);
  }
  for (int i = 0; i < nf; ++i) a[k++] = -g(i);
  a[k++] = 0.0;
}
/// Ten times the diagonal of the model's bounding box (current positions do not matter for a
/// bound this loose): no Newton correction of a sound tangent moves a node that far.
double step_bound(const System& system) {
  const Model& m = system.model();
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
  for (const auto& X : m.X) {
    lo = lo.cwiseMin(X);
    hi = hi.cwiseMax(X);
  }
  return m.X.empty() ? 1e300 : 10.0 * std::max((hi - lo).norm(), 1e-300);
}

/// The tangent predictor (newton.hpp): on success u = u_n + Δu (free) with the new prescribed
/// values, du the correction, r0 = ‖R_f(u_n) + K_fp Δu_p‖, e1 = |Δu·(that)|, and the record of
/// iteration 0 reported; on failure u is untouched and false is returned.
template <class ToFree>
bool predict(const System& system, LinearSolver& solver, const LoadState& loads, const Eigen::VectorXd& un,
             Eigen::VectorXd& u, SparseMatrix& K, Eigen::VectorXd& R, Eigen::VectorXd& Rf, Eigen::VectorXd& du,
             double bound, bool stiffen, double& r0, double& e1, double& slope, const ToFree& to_free,
             const std::function<void(const IterationRecord&)>& on_iteration) {
  const Eigen::VectorXd dp = u - un;  // the prescribed increment (zero on free DOFs)
  if (dp.size() == 0 || dp.cwiseAbs().maxCoeff() == 0) return false;
  constexpr double h = 1e-6;
  IterationRecord rec;
  const auto t0 = std::chrono::steady_clock::now();
  const int nf = system.num_free();
  Eigen::VectorXd Rp, Rm, d(nf);
  try {
    system.assemble(un + h * dp, loads, Rp, nullptr);
    system.assemble(un - h * dp, loads, Rm, nullptr);
    system.assemble(un, loads, R, &K, nullptr, &rec.active_contacts);
  } catch (const std::domain_error&) {
    return false;  // u_n is not admissible under the new loads: start plainly
  }
  to_free(R, Rf);
  to_free(Eigen::VectorXd((Rp - Rm) / (2 * h)), d);
  const Eigen::VectorXd plain = -(Rf + d);  // the right-hand side without the start stiffness
  Eigen::VectorXd rhs = plain;
  rec.residual = plain.norm();  // R₀: the yardstick of the tolerances
  if (stiffen) {  // K₀ on K_ff, and K₀_fp Δu_p: the gradient of ½ (u − u_n)ᵀ K₀ (u − u_n) at u_n + Δu_p
    Eigen::VectorXd k0(nf);
    to_free(system.add_start_stiffness(loads, dp, K), k0);
    rhs -= k0;
  }
  rec.assembly_seconds = seconds_since(t0);
  if (!std::isfinite(rec.residual) || rec.residual == 0) return false;
  Eigen::VectorXd step;
  std::string note;
  if (!solve_perturbed(solver, K, rhs, true, bound, step, note, rec.factor_seconds, rec.solve_seconds))
    return false;
  rec.solver = solver.used() + note;
  on_iteration(rec);
  r0 = rec.residual;
  slope = -step.dot(plain);  // Δu·(R_f + K_fp Δu_p): the energy slope along the correction (K₀ left out)
  e1 = std::abs(slope);
  du = std::move(step);
  for (int i = 0; i < system.num_dofs(); ++i)
    if (system.equation(i) >= 0) u(i) += du(system.equation(i));
  return true;
}

}  // namespace

bool solve_perturbed(LinearSolver& solver, const SparseMatrix& M, const Eigen::VectorXd& b, bool allow_shift,
                     double max_step, Eigen::VectorXd& x, std::string& note, double& factor_seconds,
                     double& solve_seconds) {
  note.clear();
  factor_seconds = solve_seconds = 0;
  // 0: singular (failed factorization or a non-finite x); 1: x beyond max_step; 2: fine.
  const auto attempt = [&](const SparseMatrix& A) {
    auto t = std::chrono::steady_clock::now();
    const bool regular = solver.factorize(A);
    factor_seconds += seconds_since(t);
    if (!regular) return 0;
    t = std::chrono::steady_clock::now();
    x = solver.solve(b);
    solve_seconds += seconds_since(t);
    if (!x.allFinite()) return 0;
    return x.cwiseAbs().maxCoeff() <= max_step ? 2 : 1;
  };
  const int plain = attempt(M);
  if (plain == 2) return true;
  if (!allow_shift) return plain == 1;  // volume control: a large but finite correction is kept
  note = "+shift";
  const double largest = M.diagonal().cwiseAbs().maxCoeff();
  for (double delta : {1e-6, 1e-4, 1e-2}) {
    SparseMatrix S = M;
    for (int j = 0; j < S.outerSize(); ++j)
      for (SparseMatrix::InnerIterator it(S, j); it; ++it)
        if (it.row() == j) it.valueRef() += delta * (it.value() != 0 ? std::abs(it.value()) : largest);
    if (attempt(S) == 2) return true;
  }
  return false;
}

NewtonResult newton(const System& system, LinearSolver& solver, LoadState& loads, Eigen::VectorXd& u,
                    const SolverSettings& settings, const std::function<void(const IterationRecord&)>& on_iteration,
                    const VolumeConstraint* constraint, const Eigen::VectorXd* converged) {
  NewtonResult result;
  const int nf = system.num_free();
  Eigen::VectorXd R, Rf(nf);
  SparseMatrix K = system.pattern();
  double r0 = 0, e1 = 0, energy = 0, previous_residual = 0;
  Eigen::VectorXd du;
  // Volume control: constraint residual c = V − target, the bordered matrix and its border vectors.
  SparseMatrix A;
  Eigen::VectorXd gfree(nf), dVfree(nf), dV;
  double c = 0;
  if (constraint) A = bordered_pattern(K);
  // pressure_stiffness: symmetrized — K ← (K + Kᵀ)/2 (a modified Newton method; not under volume control).
  std::optional<TransposeMap> symmetrize;
  if (settings.symmetrize_pressure_stiffness && !constraint) symmetrize.emplace(K);
  const auto to_free = [&](const Eigen::VectorXd& full, Eigen::VectorXd& free) {
    for (int i = 0; i < system.num_dofs(); ++i)
      if (system.equation(i) >= 0) free(system.equation(i)) = full(i);
  };
  const double bound = step_bound(system);
  // The increment starts at the stress-free reference state (newton.hpp, stress-free start).
  const bool stiffen = settings.stiffen_stress_free_start && !constraint && converged && converged->size() > 0 &&
                       (converged->array() == 0.0).all();
  int first = 0;
  double slope0 = 0;  // Δu·R(u) of the correction Δu being tried (line search; halved with it)
  if (converged && settings.tangent_predictor && !constraint &&
      predict(system, solver, loads, *converged, u, K, R, Rf, du, bound, stiffen, r0, e1, slope0, to_free,
              on_iteration)) {
    previous_residual = r0;
    first = 1;
  }
  std::vector<char> active_set, previous_set;  // contact active set at this / the previous residual
  for (int k = first;; ++k) {
    IterationRecord rec;
    rec.iteration = k;
    double scale = 0;
    const auto t0 = std::chrono::steady_clock::now();
    // Backtracking line search (theory manual (7.4)): a correction that raises ‖R‖, makes it
    // non-finite or leaves the admissible states (an inverted element) is halved, up to
    // settings.line_search_halvings times. The full Newton step is always tried first, so quadratic convergence
    // is untouched near a solution.
    std::string inadmissible;
    for (;;) {
      inadmissible.clear();
      try {
        system.assemble(u, loads, R, &K, &scale, &rec.active_contacts, &active_set);
        to_free(R, Rf);
        rec.residual = Rf.norm();
      } catch (const std::domain_error& e) {
        inadmissible = e.what();
      }
      // A correction is kept when ‖R‖ fell or when it took the energy slope along it down to half:
      // |Δu·R(u + Δu)| ≤ ½ |Δu·R(u)| (the step went at least halfway to the energy's stationary
      // point along Δu; theory manual (7.4)). From a stress-free membrane the first correction can
      // raise ‖R‖ through stiff in-plane modes of little energy while leaving a small slope;
      // halving such a correction only costs iterations.
      const bool slope_ok = inadmissible.empty() && std::isfinite(rec.residual) && k > 0 && slope0 != 0 &&
                            std::abs(du.head(nf).dot(Rf)) <= 0.5 * std::abs(slope0);
      const bool worse = !inadmissible.empty() || !std::isfinite(rec.residual) ||
                         (rec.residual > previous_residual && !slope_ok);
      if (k == 0 || !worse || constraint || !settings.line_search || rec.backtracks == settings.line_search_halvings) break;
      ++rec.backtracks;
      for (int i = 0; i < system.num_dofs(); ++i)
        if (system.equation(i) >= 0) u(i) -= 0.5 * du(system.equation(i));  // back to half the correction taken so far
      du *= 0.5;  // the correction actually taken
      slope0 *= 0.5;  // Δu·R(u) along it
    }
    if (!inadmissible.empty()) {
      result.failure = inadmissible;
      return result;
    }
    if (constraint) {
      c = system.volume(u, constraint->load, &dV) - constraint->target;
      to_free(dV, dVfree);
      to_free(system.pressure_load(u, constraint->load), gfree);
    }
    // The active set's changes since the previous residual (nodes entering plus leaving).
    if (previous_set.size() == active_set.size())
      for (std::size_t i = 0; i < active_set.size(); ++i) rec.active_changes += active_set[i] != previous_set[i];
    previous_set.swap(active_set);
    rec.assembly_seconds = seconds_since(t0);
    previous_residual = rec.residual;
    // Under volume control R₀ is ~0 (only the target moved): the first corrected residual is the yardstick.
    if (k == 0 || (constraint && k == 1)) r0 = std::max(r0, rec.residual);
    if (k > 0) energy = std::abs(du.head(nf).dot(Rf) + (constraint ? du(nf) * c : 0.0));  // last correction · new residual
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
    const bool volume_ok = !constraint || std::abs(c) <= settings.residual_tolerance * std::abs(constraint->target);
    const bool at_roundoff = rec.residual <= settings.roundoff_tolerance * scale && volume_ok;
    const bool tests = k > 0 && rec.residual <= settings.residual_tolerance * r0 &&
                       (e1 == 0 || energy <= settings.energy_tolerance * e1) && volume_ok;
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
    if (k == settings.max_iterations) {
      on_iteration(rec);
      result.failure = fmt::format("no convergence in {} iterations", settings.max_iterations);
      return result;
    }
    if (k == 0 && stiffen) system.add_start_stiffness(loads, Eigen::VectorXd(), K);  // the tangent only; R stays exact
    if (constraint) fill_bordered(K, gfree, dVfree, A);
    else if (symmetrize) symmetrize->symmetrize(K);
    Eigen::VectorXd rhs(constraint ? nf + 1 : nf);
    if (constraint) rhs << -Rf, -c;
    else rhs = -Rf;
    std::string note;
    // No perturbation of the bordered volume-control matrix (its last diagonal entry is 0 by design).
    const bool solved = solve_perturbed(solver, constraint ? A : K, rhs, !constraint, bound, du, note,
                                        rec.factor_seconds, rec.solve_seconds);
    rec.solver = solver.used() + note;
    if (!note.empty()) ++result.perturbed;
    if (!solved) {
      on_iteration(rec);
      result.failure = "the tangent matrix is singular (is the model held against rigid-body motion?)";
      return result;
    }
    on_iteration(rec);
    slope0 = du.head(nf).dot(Rf);
    if (k == 0) e1 = std::abs(du.head(nf).dot(Rf) + (constraint ? du(nf) * c : 0.0));  // first correction · R₀
    for (int i = 0; i < system.num_dofs(); ++i)
      if (system.equation(i) >= 0) u(i) += du(system.equation(i));
    if (constraint) loads.pressure[constraint->load] += du(nf);
  }
}

}  // namespace tunica
