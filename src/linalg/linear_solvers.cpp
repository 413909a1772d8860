#include "linalg/linear_solver.hpp"

#include <Eigen/CholmodSupport>
#include <Eigen/SparseLU>
#include <Eigen/UmfPackSupport>
#include <optional>
#include <stdexcept>

#include "linalg/compute_threads.hpp"
#include "linalg/matrix_symmetry.hpp"

namespace tunica {

namespace {

/// Adapter for Eigen's sparse direct solvers (same analyzePattern/factorize/solve API).
template <class Solver>
class EigenDirect final : public LinearSolver {
  static constexpr bool kCholmod = requires(Solver s) { s.cholmod(); };
  /// CHOLMOD's own OpenMP loops run on the calling thread (linalg/compute_threads.hpp).
  struct Scope {
    std::optional<SerialOpenMP> serial;
    Scope() {
      if constexpr (kCholmod) serial.emplace();
    }
  };

public:
  EigenDirect(const char* name, const char* refusal) : name_(name), refusal_(refusal) {
    if constexpr (kCholmod) solver_.cholmod().print = 0;  // failures are reported by us
  }
  bool factorize(const SparseMatrix& K) override {
    const Scope scope;
    if (!analyzed_) {
      solver_.analyzePattern(K);
      analyzed_ = true;
    }
    solver_.factorize(K);
    return solver_.info() == Eigen::Success;
  }
  Eigen::VectorXd solve(const Eigen::VectorXd& b) override {
    const Scope scope;
    return solver_.solve(b);
  }
  const char* used() const override { return name_; }
  std::string refusal() const override { return refusal_; }

private:
  Solver solver_;
  bool analyzed_ = false;
  const char* name_;
  const char* refusal_;
};

/// CHOLMOD cannot tell a singular tangent from one that is not symmetric positive definite.
constexpr const char* kCholmodRefusal =
    "cholmod factorizes symmetric positive definite tangents only: this one is singular (is the model held against "
    "rigid-body motion?) or not symmetric positive definite (a follower pressure on an open surface, a state past a "
    "limit point); `linear_solver: auto` or `umfpack` takes any regular tangent";

using Cholmod = EigenDirect<Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower>>;
using Umfpack = EigenDirect<Eigen::UmfPackLU<SparseMatrix>>;
using SparseLU = EigenDirect<Eigen::SparseLU<SparseMatrix, Eigen::COLAMDOrdering<int>>>;

/// CHOLMOD where K is symmetric and positive definite, UMFPACK elsewhere.
class AutoSolver final : public LinearSolver {
public:
  bool factorize(const SparseMatrix& K) override {
    if (!map_ || map_->nonzeros() != K.nonZeros()) map_.emplace(K);
    if (map_->symmetric(K, kSymmetryTolerance) && cholmod_.factorize(K)) {
      active_ = &cholmod_;
      return true;
    }
    active_ = &umfpack_;
    return umfpack_.factorize(K);
  }
  Eigen::VectorXd solve(const Eigen::VectorXd& b) override { return active_->solve(b); }
  const char* used() const override { return active_ ? active_->used() : "auto"; }
  std::string refusal() const override { return active_ ? active_->refusal() : ""; }

private:
  std::optional<TransposeMap> map_;
  Cholmod cholmod_{"cholmod", ""};  // a refused tangent goes on to UMFPACK
  Umfpack umfpack_{"umfpack", ""};
  LinearSolver* active_ = nullptr;
};

const bool registered = register_linear_solver(
                            {"auto", "CHOLMOD when the tangent is symmetric (to 1e-12) and positive definite, else UMFPACK",
                             [] { return std::make_unique<AutoSolver>(); }}) &&
                        register_linear_solver({"cholmod", "SuiteSparse CHOLMOD, supernodal LLᵀ: symmetric positive definite tangents",
                                                [] { return std::make_unique<Cholmod>("cholmod", kCholmodRefusal); }}) &&
                        register_linear_solver({"umfpack", "SuiteSparse UMFPACK, unsymmetric multifrontal LU: any regular tangent",
                                                [] { return std::make_unique<Umfpack>("umfpack", ""); }}) &&
                        register_linear_solver({"sparse_lu", "Eigen's supernodal LU (COLAMD ordering)",
                                                [] { return std::make_unique<SparseLU>("sparse_lu", ""); }});

}  // namespace

}  // namespace tunica
