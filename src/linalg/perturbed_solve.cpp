#include "linalg/perturbed_solve.hpp"

#include <chrono>
#include <cmath>

namespace tunica {

namespace {
double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

bool solve_perturbed(LinearSolver& solver, const TangentMatrix& M, const Eigen::VectorXd& b, bool allow_shift,
                     double max_step, Eigen::VectorXd& x, std::string& note, double& factor_seconds,
                     double& solve_seconds) {
  note.clear();
  factor_seconds = solve_seconds = 0;
  // 0: singular (failed factorization or a non-finite x); 1: x beyond max_step; 2: fine.
  const auto attempt = [&](const TangentMatrix& A) {
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
  if (!allow_shift) return plain == 1;
  note = "+shift";
  const Eigen::VectorXd diagonal = M.diagonal();
  const double largest = diagonal.cwiseAbs().maxCoeff();
  for (double delta : {1e-6, 1e-4, 1e-2}) {
    TangentMatrix S = M;
    S.add_to_diagonal(diagonal.unaryExpr([&](double v) { return delta * (v != 0 ? std::abs(v) : largest); }));
    if (attempt(S) == 2) return true;
  }
  return false;
}

}  // namespace tunica
