#pragma once
// Where the entries of the assembled tangent are stored (docs/performance.md, "What is assembled
// for which solver").
//
// CHOLMOD's supernodal numeric factorization (cholmod_super_numeric) reads the lower triangle of
// P K Pᵀ in compressed columns, P the fill-reducing ordering of its symbolic analysis. Handed the
// lower triangle of K, cholmod_factorize builds that matrix with two transposes (one, handed the
// upper triangle) at every factorization. TangentLayout runs CHOLMOD's symbolic analysis once on
// the tangent's pattern and numbers the entries so that the assembly writes tril(P K Pᵀ) itself,
// which the CHOLMOD solver hands to cholmod_super_numeric as it is:
//
// - each pair {i, j} of the pattern, i ≥ j in Tunica's equation numbering, has one slot s: the
//   position of (max(pᵢ, pⱼ), min(pᵢ, pⱼ)) in tril(P K Pᵀ), pᵢ the row of P K Pᵀ that row i becomes;
// - lower[s] holds K_ij, the entry of K's lower triangle: what CHOLMOD factorized when it was
//   handed that triangle, so the factor does not change, bit for bit, whichever triangle of
//   P K Pᵀ the entry lands in;
// - upper[s] holds K_ji, at the same slot, when a consumer reads the upper triangle (the symmetry
//   test of `auto`, UMFPACK and Eigen's LU through the full matrix, the symmetrized pressure
//   stiffness, the bordered system of volume control); a diagonal slot has no upper value.
//
// An entry (i, j) is addressed by its code: 2s for lower[s], 2s + 1 for upper[s] (i < j).
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
  /// tril(P K Pᵀ) in compressed columns: the slots of column c are lower_outer()[c] …
  /// lower_outer()[c + 1], rows ascending (the diagonal, where present, first).
  const std::vector<int>& lower_outer() const { return lower_outer_; }
  const std::vector<int>& lower_inner() const { return lower_inner_; }
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
  std::vector<int> diagonal_;
  std::vector<int> ordering_;
  std::unique_ptr<Cholmod> cholmod_;
};

}  // namespace tunica
