#pragma once
// Linear solvers behind one interface, registered by name: the deck's `solver.linear_solver`
// takes its choices from the registry, and the deck reference lists them with their one-line
// descriptions (`tunica reference`; the shipped ones are in linalg/linear_solvers.cpp). The
// symbolic analysis is done once per pattern and reused by every numeric factorization.
#include <Eigen/Dense>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "linalg/sparse_matrix.hpp"

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
  /// Why a factorize() that returned false may not mean a singular K: a solver that takes only
  /// some matrices (symmetric, positive definite) names what it needs and which solver takes
  /// the rest. Empty: false means singular. Newton's failure message quotes it.
  virtual std::string refusal() const { return ""; }
};

/// A linear solver a deck can name.
struct LinearSolverType {
  std::string name;
  std::string doc;  ///< one line for the deck reference
  std::function<std::unique_ptr<LinearSolver>()> make;
};

/// Adds a solver to the registry (at static initialization: a `static const bool` initialized
/// by register_linear_solver in the solver's own .cpp). Throws std::logic_error on a name
/// registered twice.
bool register_linear_solver(LinearSolverType type);
/// The registered solvers, by name.
std::vector<std::string> linear_solver_names();
/// One line per solver ("`name`: doc"), for the deck reference.
std::string linear_solver_docs();
/// A new solver of a registered name; std::invalid_argument for an unknown name.
std::unique_ptr<LinearSolver> make_linear_solver(const std::string& name);

/// Relative tolerance of the symmetry test of "auto".
constexpr double kSymmetryTolerance = 1e-12;

}  // namespace tunica
