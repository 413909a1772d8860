#pragma once
// Where the entries of the assembled tangent are stored, and the matrix CHOLMOD is handed
// (docs/performance.md, "What is assembled for which solver").
//
// CHOLMOD's supernodal numeric factorization (cholmod_super_numeric) reads the lower triangle of
// P K Pᵀ in compressed columns, P the fill-reducing ordering of its symbolic analysis. Handed the
// lower triangle of K, cholmod_factorize builds that matrix at every factorization with two
// transposes (cholmod_transpose_sym, allocating both), after the assembly has scattered both
// triangles of a full K. TangentLayout runs CHOLMOD's symbolic analysis once on the tangent's
// pattern and lays the tangent out in two arrays of one slot per pair {i, j} of the pattern:
//
// - the slots follow K's lower triangle in Tunica's numbering, column by column: the order of the
//   mesh's nodes, in which an element's entries lie near those of the elements before it. In
//   P K Pᵀ's order, over which nested dissection spreads a mesh neighbourhood, the element loop
//   would write all over the array, and its cache misses cost more than the transposes saved;
// - lower[s] holds K_ij (i ≥ j), the entry of K's lower triangle: what CHOLMOD factorized when it
//   was handed that triangle, so the factor is the same bit for bit;
// - upper[s] holds K_ji, at the same slot, only where a consumer reads the upper triangle (the
//   symmetry test of `auto`, which then compares the arrays in order; UMFPACK and Eigen's LU
//   through the full matrix; the symmetrized pressure stiffness; the bordered system of volume
//   control); a diagonal slot has no upper value;
// - CHOLMOD is handed tril(P K Pᵀ) gathered from `lower` through a precomputed map (to_cholmod):
//   one pass that reads each slot once, in place of the two transposes.
//
// The two arrays are one: values [0, S) are `lower`, [S, 2S) `upper` (S = slots()), and an entry
// (i, j) is addressed by its code, its index there: s (i ≥ j) or S + s (i < j). The assembly adds
// an element's K_e(a, b) at the code of (row of a, row of b), one add per entry as into a full
// matrix; a tangent without the upper triangle stores [0, S) only and skips codes from S.
#include <memory>
#include <vector>

#include "linalg/sparse_matrix.hpp"

struct cholmod_factor_struct;

namespace tunica {

class TangentLayout {
public:
  /// `pattern`: the tangent's sparsity pattern, both triangles, symmetric, compressed columns with
  /// sorted rows. Runs CHOLMOD's symbolic analysis (ordering, supernodes) on its lower triangle,
  /// with the settings of the CHOLMOD solver (linalg/linear_solvers.cpp). Throws
  /// std::invalid_argument if the pattern is not symmetric, std::runtime_error if CHOLMOD fails.
  explicit TangentLayout(SparseMatrix pattern);
  ~TangentLayout();
  TangentLayout(const TangentLayout&) = delete;
  TangentLayout& operator=(const TangentLayout&) = delete;

  int size() const { return static_cast<int>(pattern_.rows()); }
  /// Slots: the entries of one triangle, the diagonal included.
  int slots() const { return static_cast<int>(lower_inner_.size()); }
  /// The code of entry (i, j) (Tunica's numbering); −1 if i or j is negative (a prescribed DOF).
  /// Throws std::logic_error if (i, j) is not in the pattern.
  int entry(int i, int j) const;
  /// The pattern: both triangles, Tunica's numbering, zero values.
  const SparseMatrix& pattern() const { return pattern_; }
  /// Per entry of pattern(), in its order: the entry's code (expands the split storage).
  const std::vector<int>& pattern_codes() const { return codes_; }
  /// The slots: K's lower triangle in compressed columns (Tunica's numbering); column j's slots are
  /// lower_outer()[j] … lower_outer()[j + 1], rows ascending (the diagonal, where present, first).
  const std::vector<int>& lower_outer() const { return lower_outer_; }
  const std::vector<int>& lower_inner() const { return lower_inner_; }
  /// CHOLMOD's matrix tril(P K Pᵀ) in compressed columns (rows ascending), and per entry of it the
  /// slot its value comes from.
  const std::vector<int>& cholmod_outer() const { return cholmod_outer_; }
  const std::vector<int>& cholmod_inner() const { return cholmod_inner_; }
  const std::vector<int>& cholmod_slots() const { return cholmod_from_; }
  /// out[t] = lower[cholmod_slots()[t]]: the values of tril(P K Pᵀ) (slots() of them).
  void to_cholmod(const double* lower, double* out) const;
  /// CHOLMOD's fill-reducing ordering P: row k of P K Pᵀ is row ordering()[k] of K.
  const std::vector<int>& ordering() const { return ordering_; }
  /// Per equation i (Tunica's numbering): the slot of K_ii, −1 if the pattern has none.
  const std::vector<int>& diagonal_slots() const { return diagonal_; }
  /// CHOLMOD's symbolic supernodal factor (cholmod_factor); null for an empty pattern. The
  /// CHOLMOD solver factorizes into a copy of it.
  const cholmod_factor_struct* symbolic() const;

private:
  struct Cholmod;
  SparseMatrix pattern_;
  std::vector<int> codes_;
  std::vector<int> lower_outer_, lower_inner_;
  std::vector<int> cholmod_outer_, cholmod_inner_, cholmod_from_;
  std::vector<int> diagonal_;
  std::vector<int> ordering_;
  std::unique_ptr<Cholmod> cholmod_;
};

}  // namespace tunica
