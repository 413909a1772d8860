#include "linalg/linear_solver.hpp"

#include <cholmod.h>

#include <Eigen/CholmodSupport>
#include <Eigen/SparseLU>
#include <Eigen/UmfPackSupport>
#include <limits>
#include <optional>
#include <stdexcept>

#include "linalg/cholmod_lower_view.hpp"
#include "linalg/compute_threads.hpp"
#include "linalg/matrix_symmetry.hpp"

namespace tunica {

namespace {

/// Adapter for Eigen's sparse LU solvers (same analyzePattern/factorize/solve API). They factorize
/// the full matrix, expanded from a split tangent, in a copy of their own: UMFPACK's solve reads the
/// matrix again (iterative refinement), which must outlive the caller's.
template <class Solver>
class EigenDirect final : public LinearSolver {
public:
  explicit EigenDirect(const char* name) : name_(name) {}
  bool factorize(const TangentMatrix& K) override {
    K.expand(matrix_);
    if (!analyzed_ || matrix_.rows() != analyzed_rows_ || matrix_.nonZeros() != analyzed_nonzeros_) {
      solver_.analyzePattern(matrix_);
      analyzed_ = true;
      analyzed_rows_ = matrix_.rows();
      analyzed_nonzeros_ = matrix_.nonZeros();
    }
    solver_.factorize(matrix_);
    return solver_.info() == Eigen::Success;
  }
  Eigen::VectorXd solve(const Eigen::VectorXd& b) override { return solver_.solve(b); }
  const char* used() const override { return name_; }

private:
  Solver solver_;
  SparseMatrix matrix_;
  bool analyzed_ = false;
  Eigen::Index analyzed_rows_ = 0, analyzed_nonzeros_ = 0;
  const char* name_;
};

/// CHOLMOD's supernodal LLᵀ. A split tangent's lower triangle is gathered into tril(P K Pᵀ), P the
/// ordering of its layout's symbolic analysis (linalg/tangent_layout.hpp), which
/// cholmod_super_numeric factorizes into a copy of that analysis; cholmod_factorize would build
/// the same matrix from K's lower triangle with two transposes. The factor and the solve
/// (cholmod_solve with the layout's P) are those of cholmod_factorize, bit for bit. A general
/// matrix (both triangles) goes through Eigen's wrapper, its lower triangle factorized, its
/// analysis on the first call.
class Cholmod final : public LinearSolver {
public:
  explicit Cholmod(const char* refusal) : refusal_(refusal) {
    cholmod_start(&common_);
    common_.print = 0;  // failures are reported by us
    common_.supernodal = CHOLMOD_SUPERNODAL;
    common_.final_asis = 1;
    general_.cholmod().print = 0;
  }
  ~Cholmod() override {
    if (factor_) cholmod_free_factor(&factor_, &common_);
    cholmod_finish(&common_);
  }
  Cholmod(const Cholmod&) = delete;
  Cholmod& operator=(const Cholmod&) = delete;

  bool factorize(const TangentMatrix& K) override {
    const SerialOpenMP serial;  // CHOLMOD's own loops on the calling thread (linalg/compute_threads.hpp)
    split_ = K.split();
    return split_ ? factorize_split(K) : factorize_general(K.general());
  }
  Eigen::VectorXd solve(const Eigen::VectorXd& b) override {
    const SerialOpenMP serial;
    if (!split_) return general_.solve(b);
    if (!factor_ || factor_->n == 0) return b;
    cholmod_dense B{};
    B.nrow = B.d = B.nzmax = static_cast<std::size_t>(b.size());
    B.ncol = 1;
    B.x = const_cast<double*>(b.data());
    B.xtype = CHOLMOD_REAL;
    B.dtype = CHOLMOD_DOUBLE;
    cholmod_dense* X = cholmod_solve(CHOLMOD_A, factor_, &B, &common_);
    if (!X) return Eigen::VectorXd::Constant(b.size(), std::numeric_limits<double>::quiet_NaN());
    Eigen::VectorXd x = Eigen::Map<const Eigen::VectorXd>(static_cast<const double*>(X->x), b.size());
    cholmod_free_dense(&X, &common_);
    return x;
  }
  const char* used() const override { return "cholmod"; }
  std::string refusal() const override { return refusal_; }
  bool reads_upper() const override { return false; }

private:
  bool factorize_split(const TangentMatrix& K) {
    const TangentLayout& layout = K.layout();
    if (source_ != K.shared_layout()) {
      if (factor_) cholmod_free_factor(&factor_, &common_);
      source_ = K.shared_layout();
      if (layout.size() == 0) return true;
      factor_ = cholmod_copy_factor(const_cast<cholmod_factor*>(layout.symbolic()), &common_);
      if (!factor_) throw std::runtime_error("CHOLMOD could not copy the symbolic factor");
    }
    if (layout.size() == 0) return true;
    permuted_.resize(static_cast<std::size_t>(layout.slots()));
    layout.to_cholmod(K.lower(), permuted_.data());
    cholmod_sparse S = cholmod_lower_view(layout.size(), layout.slots(), layout.cholmod_outer().data(),
                                          layout.cholmod_inner().data(), permuted_.data());
    double beta[2] = {0.0, 0.0};
    cholmod_super_numeric(&S, nullptr, beta, factor_, &common_);
    if (common_.status == CHOLMOD_INVALID) throw std::logic_error("CHOLMOD: the split tangent is not a valid lower triangle");
    // Not positive definite: a warning (status > 0), minor < n; out of memory: an error. Both refuse K.
    return common_.status == CHOLMOD_OK && factor_->minor == factor_->n;
  }
  bool factorize_general(const SparseMatrix& K) {
    if (!general_analyzed_ || K.rows() != general_rows_ || K.nonZeros() != general_nonzeros_) {
      general_.analyzePattern(K);
      general_analyzed_ = true;
      general_rows_ = K.rows();
      general_nonzeros_ = K.nonZeros();
    }
    general_.factorize(K);
    return general_.info() == Eigen::Success;
  }

  cholmod_common common_{};
  cholmod_factor* factor_ = nullptr;
  std::shared_ptr<const TangentLayout> source_;  // the layout factor_ was copied from
  std::vector<double> permuted_;                 // tril(P K Pᵀ) of the last split tangent
  Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> general_;
  bool general_analyzed_ = false;
  Eigen::Index general_rows_ = 0, general_nonzeros_ = 0;
  bool split_ = true;
  const char* refusal_;
};

/// CHOLMOD cannot tell a singular tangent from one that is not symmetric positive definite.
constexpr const char* kCholmodRefusal =
    "cholmod factorizes symmetric positive definite tangents only: this one is singular (is the model held against "
    "rigid-body motion?) or not symmetric positive definite (a follower pressure on an open surface, a state past a "
    "limit point); `linear_solver: auto` or `umfpack` takes any regular tangent";

using Umfpack = EigenDirect<Eigen::UmfPackLU<SparseMatrix>>;
using SparseLU = EigenDirect<Eigen::SparseLU<SparseMatrix, Eigen::COLAMDOrdering<int>>>;

/// CHOLMOD where K is symmetric and positive definite, UMFPACK elsewhere. The symmetry test reads
/// both triangles: of a split tangent, slot by slot (its two arrays, in the same order); of a
/// general matrix, through a TransposeMap.
class AutoSolver final : public LinearSolver {
public:
  bool factorize(const TangentMatrix& K) override {
    if (symmetric(K) && cholmod_.factorize(K)) {
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
  bool symmetric(const TangentMatrix& K) {
    if (K.split()) return K.symmetric(kSymmetryTolerance);
    const SparseMatrix& A = K.general();
    if (!map_ || map_->nonzeros() != A.nonZeros()) map_.emplace(A);
    return map_->symmetric(A, kSymmetryTolerance);
  }

  std::optional<TransposeMap> map_;
  Cholmod cholmod_{""};  // a refused tangent goes on to UMFPACK
  Umfpack umfpack_{"umfpack"};
  LinearSolver* active_ = nullptr;
};

const bool registered = register_linear_solver(
                            {"auto", "CHOLMOD when the tangent is symmetric (to 1e-12) and positive definite, else UMFPACK",
                             [] { return std::make_unique<AutoSolver>(); }}) &&
                        register_linear_solver({"cholmod", "SuiteSparse CHOLMOD, supernodal LLᵀ: symmetric positive definite tangents",
                                                [] { return std::make_unique<Cholmod>(kCholmodRefusal); }}) &&
                        register_linear_solver({"umfpack", "SuiteSparse UMFPACK, unsymmetric multifrontal LU: any regular tangent",
                                                [] { return std::make_unique<Umfpack>("umfpack"); }}) &&
                        register_linear_solver({"sparse_lu", "Eigen's supernodal LU (COLAMD ordering)",
                                                [] { return std::make_unique<SparseLU>("sparse_lu"); }});

}  // namespace

}  // namespace tunica
