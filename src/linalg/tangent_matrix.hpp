#pragma once
// The matrix of a Newton correction's linear solve: either the assembled tangent in the split
// storage of a TangentLayout (linalg/tangent_layout.hpp: the lower triangle, which CHOLMOD reads,
// and the upper triangle at the same slots where a consumer reads it), or a general
// sparse matrix (both triangles, compressed columns: the bordered system of volume control, a
// test's matrix). The full matrix of a tangent is built only for a consumer that needs it (expand).
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "linalg/sparse_matrix.hpp"
#include "linalg/tangent_layout.hpp"

namespace tunica {

class TangentMatrix {
public:
  TangentMatrix() = default;
  /// A general matrix: both triangles, compressed columns.
  TangentMatrix(SparseMatrix general);  // NOLINT(google-explicit-constructor): any sparse matrix is one
  /// A zero tangent in `layout`'s split storage, with the upper triangle if `upper`.
  TangentMatrix(std::shared_ptr<const TangentLayout> layout, bool upper);

  Eigen::Index rows() const { return layout_ ? layout_->size() : general_.rows(); }
  /// Split storage (a TangentLayout's), else a general matrix.
  bool split() const { return layout_ != nullptr; }
  /// The layout of a split tangent (std::logic_error for a general matrix).
  const TangentLayout& layout() const;
  const std::shared_ptr<const TangentLayout>& shared_layout() const { return layout_; }
  /// Whether the upper triangle is stored (always, for a general matrix).
  bool has_upper() const { return !layout_ || upper_; }

  /// Split storage: the values by code (TangentLayout), `lower` then `upper` where it is stored.
  double* values() { return values_.data(); }
  /// Codes below stored() are stored: the slots, or twice the slots with the upper triangle.
  int stored() const { return static_cast<int>(values_.size()); }
  /// The values by slot; upper() is null where it is not stored.
  double* lower() { return values_.data(); }
  const double* lower() const { return values_.data(); }
  double* upper() { return layout_ && upper_ ? values_.data() + layout_->slots() : nullptr; }
  const double* upper() const { return layout_ && upper_ ? values_.data() + layout_->slots() : nullptr; }
  /// Split storage: adds v to the entry of code `code` (TangentLayout::entry; nothing for −1, or for an
  /// upper entry where the upper triangle is not stored).
  void add(int code, double v) {
    if (code >= 0 && code < stored()) values_[static_cast<std::size_t>(code)] += v;
  }
  /// A general matrix's storage (std::logic_error for a split tangent).
  SparseMatrix& general();
  const SparseMatrix& general() const;

  void set_zero();
  double max_abs() const;
  /// K_ii per row (Tunica's numbering; 0 where the pattern has no diagonal entry).
  Eigen::VectorXd diagonal() const;
  /// K_ii += d_i where the pattern has the diagonal entry.
  void add_to_diagonal(const Eigen::VectorXd& d);
  /// Split storage with both triangles: max |K_ij − K_ji| ≤ tolerance · max |K_ij|, comparing the
  /// two arrays slot by slot (std::logic_error otherwise).
  bool symmetric(double tolerance) const;
  /// Split storage with both triangles: K ← (K + Kᵀ)/2 (std::logic_error otherwise).
  void symmetrize();
  /// The full matrix, both triangles, compressed columns, Tunica's numbering, into `out` (its storage
  /// reused when it has the pattern's size). A split tangent needs its upper triangle
  /// (std::logic_error otherwise).
  void expand(SparseMatrix& out) const;
  SparseMatrix full() const {
    SparseMatrix out;
    expand(out);
    return out;
  }

private:
  void require_both(const char* what) const;

  std::shared_ptr<const TangentLayout> layout_;
  std::vector<double> values_;  // split storage: lower, then upper where stored
  bool upper_ = false;
  SparseMatrix general_;
};

}  // namespace tunica
