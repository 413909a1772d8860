#pragma once
// Symmetry of an assembled tangent whose sparsity pattern is symmetric (the
// pattern of System is: it comes from the node adjacency of the elements).
// The hyperelastic membrane and solid tangents are symmetric; the follower-
// pressure load stiffness is symmetric after assembly only where the loaded
// surface is closed or its boundary is held (the boundary integral of the
// load stiffness then vanishes), so symmetry is a property of the model, and
// it is measured, not assumed.
#include <vector>

#include "linalg/sparse_matrix.hpp"

namespace tunica {

class TransposeMap {
public:
  /// Position in the value array of (j, i) for every entry (i, j) of `pattern`.
  /// Throws std::invalid_argument if the pattern is not symmetric.
  explicit TransposeMap(const SparseMatrix& pattern);
  /// max |K_ij − K_ji| ≤ tolerance · max |K_ij|.
  bool symmetric(const SparseMatrix& K, double tolerance) const;
  /// K ← (K + Kᵀ)/2.
  void symmetrize(SparseMatrix& K) const;
  Eigen::Index nonzeros() const { return static_cast<Eigen::Index>(transpose_.size()); }

private:
  std::vector<int> transpose_;
};

}  // namespace tunica
