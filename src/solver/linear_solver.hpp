#pragma once
// Sparse direct solvers behind one interface. The symbolic analysis is done
// once per pattern and reused by every numeric factorization.
//
//   cholmod    SuiteSparse CHOLMOD, supernodal LLᵀ of the lower triangle: for
//              symmetric positive definite tangents (a hyperelastic membrane
//              under prescribed displacements, or under pressure on a closed
//              or held surface at a stable state).
//   umfpack    SuiteSparse UMFPACK, unsymmetric multifrontal LU: any regular
//              tangent (an open loaded surface, a bordered volume-control
//              system, a state beyond a limit point).
//   sparse_lu  Eigen's own supernodal LU (COLAMD): the fallback without SuiteSparse.
//   auto       per factorization: CHOLMOD if K is symmetric to round-off
//              (max |K_ij − K_ji| ≤ 1e-12 max |K_ij|) and positive definite,
//              otherwise UMFPACK.
#include <memory>
#include <string>

#include "assembly/system.hpp"

namespace tunica {

class LinearSolver {
public:
  virtual ~LinearSolver() = default;
  /// Numeric factorization; the symbolic analysis is done on the first call and
  /// reused (the pattern of K never changes). Returns false if K is singular
  /// (or, for cholmod, not positive definite).
  virtual bool factorize(const SparseMatrix& K) = 0;
  virtual Eigen::VectorXd solve(const Eigen::VectorXd& b) = 0;
  /// The solver that did the last factorization ("cholmod", "umfpack", "sparse_lu").
  virtual const char* used() const = 0;
};

/// "auto", "cholmod", "umfpack" or "sparse_lu".
std::unique_ptr<LinearSolver> make_linear_solver(const std::string& name);

/// Relative tolerance of the symmetry test of "auto".
constexpr double kSymmetryTolerance = 1e-12;

}  // namespace tunica
