#pragma once
// Linear solvers behind one interface, registered by name: the deck's `solver.linear_solver`
// takes its choices from the registry, and the deck reference lists them with their one-line
// descriptions (`tunica reference`; the shipped ones are in linalg/linear_solvers.cpp). The
// symbolic analysis is done once per pattern and reused by every numeric factorization. A solver
// is handed the assembled tangent in split storage (linalg/tangent_matrix.hpp: the lower triangle,
// from which CHOLMOD's tril(P K Pᵀ) is gathered, and the upper one beside it if the solver reads
// it) or a general matrix; one that wants the full matrix expands it (TangentMatrix::expand).
#include <Eigen/Dense>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "linalg/tangent_matrix.hpp"

namespace tunica {

class LinearSolver {
public:
  virtual ~LinearSolver() = default;
  /// Numeric factorization; the symbolic analysis is done on the first call and
  /// reused (the pattern of K never changes). Returns false if K is singular
  /// (or, for cholmod, not positive definite). K may be a temporary: a solver that reads it again
  /// in solve() keeps a copy.
  virtual bool factorize(const TangentMatrix& K) = 0;
  virtual Eigen::VectorXd solve(const Eigen::VectorXd& b) = 0;
  /// The solver that did the last factorization ("cholmod", "umfpack", "sparse_lu").
  virtual const char* used() const = 0;
  /// Why a factorize() that returned false may not mean a singular K: a solver that takes only
  /// some matrices (symmetric, positive definite) names what it needs and which solver takes
  /// the rest. Empty: false means singular. Newton's failure message quotes it.
  virtual std::string refusal() const { return ""; }
  /// Whether factorize() reads the upper triangle of a split tangent. A solver that reads the lower
  /// one only (CHOLMOD) says false, and the assembly then leaves the upper one out
  /// (solver/increment.cpp).
  virtual bool reads_upper() const { return true; }
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
