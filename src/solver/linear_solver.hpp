#pragma once
// Sparse direct solvers behind one interface. The symbolic analysis is done
// once per pattern and reused by every numeric factorization.
#include <memory>
#include <string>

#include "assembly/system.hpp"

namespace tunica {

class LinearSolver {
public:
  virtual ~LinearSolver() = default;
  /// Numeric factorization; the symbolic analysis is done on the first call and
  /// reused (the pattern of K never changes). Returns false if K is singular.
  virtual bool factorize(const SparseMatrix& K) = 0;
  virtual Eigen::VectorXd solve(const Eigen::VectorXd& b) = 0;
};

/// "umfpack" (SuiteSparse, nonsymmetric) or "sparse_lu" (Eigen's own).
std::unique_ptr<LinearSolver> make_linear_solver(const std::string& name);

}  // namespace tunica
