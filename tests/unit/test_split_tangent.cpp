// The tangent's split storage (linalg/tangent_layout.hpp, linalg/tangent_matrix.hpp): the lower
// triangle, the upper one beside it, and CHOLMOD's tril(P K Pᵀ) gathered from the lower one.
// - every entry of the pattern has its slot, the full matrix expands from the two arrays entry for
//   entry, and CHOLMOD's tril(P K Pᵀ) gathers from the lower one;
// - CHOLMOD factorizes the split lower triangle as cholmod_factorize factorized K's lower
//   triangle: the same solution bit for bit;
// - every solver solves the same assembled tangent to 1e-10;
// - the assembled tangent, both triangles, is the Jacobian of the assembled residual;
// - `auto` sends an unsymmetric tangent to UMFPACK, which gets both triangles.
#include <gtest/gtest.h>

#include <Eigen/CholmodSupport>
#include <random>
#include <string>

#include "io/deck.hpp"
#include "linalg/linear_solver.hpp"
#include "linalg/matrix_symmetry.hpp"
#include "solver/analysis.hpp"
#include "../support/fung_tube.hpp"
#include "../support/system_fd.hpp"

namespace tunica {
namespace {

/// The benchmark's Fung tube, 8 × 8 split quads, converged at 120 mmHg and λz = 1.3: a
/// pressure-loaded state whose tangent is symmetric positive definite.
struct TubeState {
  Model model;
  std::unique_ptr<Analysis> analysis;
  TubeState() : model(read_deck_text(test::fung_tube_deck(8, "", 3), "tube.yaml")) {
    analysis = std::make_unique<Analysis>(model);
    AnalysisObserver quiet;
    analysis->run(quiet);
  }
  const System& system() const { return analysis->system(); }
  TangentMatrix tangent(bool upper) const {
    TangentMatrix K = system().tangent(upper);
    Eigen::VectorXd R;
    system().assemble(analysis->displacement(), analysis->loads(), R, &K);
    return K;
  }
};

const TubeState& tube() {
  static const TubeState state;
  return state;
}

TEST(SplitTangent, EveryEntryHasOneSlotAndCholmodGetsTheLowerTriangleOfThePermutedMatrix) {
  const System& system = tube().system();
  const TangentLayout& layout = *system.layout();
  const int n = system.num_free();
  // A matrix on the pattern with distinct, unsymmetric values.
  SparseMatrix A = system.pattern();
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> U(-1, 1);
  for (Eigen::Index k = 0; k < A.nonZeros(); ++k) A.valuePtr()[k] = U(rng);
  TangentMatrix T = system.tangent(true);
  for (int j = 0; j < n; ++j)
    for (SparseMatrix::InnerIterator it(A, j); it; ++it) T.add(layout.entry(static_cast<int>(it.row()), j), it.value());
  const SparseMatrix full = T.full();
  ASSERT_EQ(full.nonZeros(), A.nonZeros());
  for (Eigen::Index k = 0; k < A.nonZeros(); ++k) ASSERT_EQ(full.valuePtr()[k], A.valuePtr()[k]) << k;
  // The slots are A's lower triangle column by column, rows ascending from the diagonal: lower
  // holds A_ij (i ≥ j), upper A_ji.
  const std::vector<int>& outer = layout.lower_outer();
  const std::vector<int>& inner = layout.lower_inner();
  int diagonal = 0;
  for (int j = 0; j < n; ++j)
    for (int s = outer[j]; s < outer[j + 1]; ++s) {
      const int i = inner[s];
      ASSERT_GE(i, j);
      if (s > outer[j]) {
        ASSERT_GT(i, inner[s - 1]);
      }
      ASSERT_EQ(T.lower()[s], A.coeff(i, j)) << i << ", " << j;
      if (i == j) {
        ++diagonal;
      } else {
        ASSERT_EQ(T.upper()[s], A.coeff(j, i)) << i << ", " << j;
      }
    }
  EXPECT_EQ(2L * layout.slots() - diagonal, static_cast<long>(A.nonZeros()));
  // CHOLMOD's matrix: column c is column c of tril(P A Pᵀ), rows ascending, built from A's lower
  // triangle (the entries CHOLMOD read when it was handed that triangle).
  std::vector<double> cholmod(static_cast<std::size_t>(layout.slots()));
  layout.to_cholmod(T.lower(), cholmod.data());
  const std::vector<int>& P = layout.ordering();
  const std::vector<int>& c_outer = layout.cholmod_outer();
  const std::vector<int>& c_inner = layout.cholmod_inner();
  ASSERT_EQ(c_outer[n], layout.slots());
  for (int c = 0; c < n; ++c)
    for (int t = c_outer[c]; t < c_outer[c + 1]; ++t) {
      const int r = c_inner[t];
      ASSERT_GE(r, c);
      if (t > c_outer[c]) {
        ASSERT_GT(r, c_inner[t - 1]);
      }
      ASSERT_EQ(cholmod[t], A.coeff(std::max(P[r], P[c]), std::min(P[r], P[c]))) << r << ", " << c;
    }
  const Eigen::VectorXd d = A.diagonal();
  EXPECT_EQ(T.diagonal(), d);
}

TEST(SplitTangent, CholmodFactorizesTheLowerTriangleAsCholmodFactorizeDoes) {
  const TangentMatrix K = tube().tangent(true);
  const TangentMatrix lower_only = tube().tangent(false);
  ASSERT_FALSE(lower_only.has_upper());
  for (int s = 0; s < K.layout().slots(); ++s) ASSERT_EQ(lower_only.lower()[s], K.lower()[s]) << s;
  // cholmod_factorize on K's lower triangle (Eigen's wrapper, as linear_solvers.cpp used it).
  Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> reference;
  reference.cholmod().print = 0;
  reference.compute(K.full());
  ASSERT_EQ(reference.info(), Eigen::Success);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(K.rows(), -1.0, 2.0);
  const Eigen::VectorXd expected = reference.solve(b);
  for (const TangentMatrix* M : {&K, &lower_only}) {
    auto cholmod = make_linear_solver("cholmod");
    ASSERT_TRUE(cholmod->factorize(*M));
    const Eigen::VectorXd x = cholmod->solve(b);
    for (Eigen::Index i = 0; i < x.size(); ++i) ASSERT_EQ(x(i), expected(i)) << i;  // bit for bit
  }
  // A general matrix (both triangles) goes through cholmod_factorize itself.
  auto cholmod = make_linear_solver("cholmod");
  ASSERT_TRUE(cholmod->factorize(K.full()));
  const Eigen::VectorXd x = cholmod->solve(b);
  for (Eigen::Index i = 0; i < x.size(); ++i) ASSERT_EQ(x(i), expected(i)) << i;
}

TEST(SplitTangent, EverySolverSolvesTheSameTangent) {
  const TangentMatrix K = tube().tangent(true);
  const SparseMatrix full = K.full();
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(K.rows(), 1.0, -1.0);
  auto umfpack = make_linear_solver("umfpack");
  ASSERT_TRUE(umfpack->factorize(K));
  const Eigen::VectorXd reference = umfpack->solve(b);
  EXPECT_LT((full * reference - b).norm(), 1e-10 * b.norm());
  for (const std::string name : {"auto", "cholmod", "sparse_lu"}) {
    auto solver = make_linear_solver(name);
    const TangentMatrix M = tube().tangent(solver->reads_upper());  // what Newton's problem assembles for it
    ASSERT_TRUE(solver->factorize(M)) << name;
    const Eigen::VectorXd x = solver->solve(b);
    EXPECT_LT((x - reference).norm(), 1e-10 * reference.norm()) << name;
    EXPECT_LT((full * x - b).norm(), 1e-10 * b.norm()) << name;
  }
  EXPECT_FALSE(make_linear_solver("cholmod")->reads_upper());
  for (const char* name : {"auto", "umfpack", "sparse_lu"}) EXPECT_TRUE(make_linear_solver(name)->reads_upper()) << name;
}

TEST(SplitTangent, TheAssembledTangentIsTheJacobianOfTheAssembledResidual) {
  // The element loop scatters the elements whose unknowns are all free through runs of their codes
  // and the others (the end rings') code by code: every entry of both triangles against central
  // differences of R, at the converged pressurized state.
  const TangentMatrix K = tube().tangent(true);
  const Eigen::MatrixXd dense = Eigen::MatrixXd(K.full());
  const double error = test::fd_tangent_error(tube().system(), tube().analysis->loads(), tube().analysis->displacement(),
                                              dense, 1e-6);
  EXPECT_LT(error, 1e-7 * dense.cwiseAbs().maxCoeff());
}

TEST(SplitTangent, AutoSendsAnUnsymmetricTangentToUmfpackWithBothTriangles) {
  const TangentMatrix K = tube().tangent(true);
  ASSERT_TRUE(K.symmetric(kSymmetryTolerance));
  auto solver = make_linear_solver("auto");
  ASSERT_TRUE(solver->factorize(K));
  EXPECT_STREQ(solver->used(), "cholmod");
  // One off-diagonal entry of either triangle made unsymmetric beyond the tolerance.
  const int slot = K.layout().lower_outer()[0] + 1;  // column 0's first slot below the diagonal
  ASSERT_NE(K.layout().lower_inner()[slot], 0);
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(K.rows());
  for (const bool in_upper : {true, false}) {
    TangentMatrix U = K;
    (in_upper ? U.upper() : U.lower())[slot] += 1e-3 * K.max_abs();
    EXPECT_FALSE(U.symmetric(kSymmetryTolerance));
    const SparseMatrix full = U.full();
    EXPECT_FALSE(TransposeMap(full).symmetric(full, kSymmetryTolerance));
    ASSERT_TRUE(solver->factorize(U));
    EXPECT_STREQ(solver->used(), "umfpack");
    // UMFPACK solved the unsymmetric matrix, not a symmetric one built from a triangle.
    EXPECT_LT((full * solver->solve(b) - b).norm(), 1e-9 * b.norm());
    // Symmetrized, it is CHOLMOD's again: (K + Kᵀ)/2 in both arrays.
    U.symmetrize();
    EXPECT_TRUE(U.symmetric(0.0));
    EXPECT_EQ(U.lower()[slot], U.upper()[slot]);
    EXPECT_NEAR(U.lower()[slot], K.lower()[slot] + 0.5e-3 * K.max_abs(), 1e-12 * K.max_abs());
    ASSERT_TRUE(solver->factorize(U));
    EXPECT_STREQ(solver->used(), "cholmod");
  }
  // Round-off below the tolerance stays with CHOLMOD.
  TangentMatrix R = K;
  R.upper()[slot] *= 1 + 1e-15;
  EXPECT_TRUE(R.symmetric(kSymmetryTolerance));
  // A tangent without its upper triangle cannot be tested.
  EXPECT_THROW(solver->factorize(tube().tangent(false)), std::logic_error);
}

}  // namespace
}  // namespace tunica
