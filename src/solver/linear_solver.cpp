#include "solver/linear_solver.hpp"

#include <Eigen/SparseLU>
#include <Eigen/UmfPackSupport>
#include <stdexcept>

namespace tunica {

namespace {

/// Adapter for Eigen's sparse LU-type solvers (same API for UMFPACK and SparseLU).
template <class Solver>
class EigenLU final : public LinearSolver {
public:
  bool factorize(const SparseMatrix& K) override {
    if (!analyzed_) {
      solver_.analyzePattern(K);
      analyzed_ = true;
    }
    solver_.factorize(K);
    return solver_.info() == Eigen::Success;
  }
  Eigen::VectorXd solve(const Eigen::VectorXd& b) override { return solver_.solve(b); }

private:
  Solver solver_;
  bool analyzed_ = false;
};

}  // namespace

std::unique_ptr<LinearSolver> make_linear_solver(const std::string& name) {
  if (name == "umfpack") return std::make_unique<EigenLU<Eigen::UmfPackLU<SparseMatrix>>>();
  if (name == "sparse_lu") return std::make_unique<EigenLU<Eigen::SparseLU<SparseMatrix, Eigen::COLAMDOrdering<int>>>>();
  throw std::invalid_argument("unknown linear solver '" + name + "'");
}

}  // namespace tunica
