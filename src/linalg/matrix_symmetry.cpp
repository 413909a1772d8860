#include "linalg/matrix_symmetry.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tunica {

TransposeMap::TransposeMap(const SparseMatrix& pattern) : transpose_(static_cast<std::size_t>(pattern.nonZeros())) {
  const int* outer = pattern.outerIndexPtr();
  const int* inner = pattern.innerIndexPtr();
  for (int j = 0; j < pattern.cols(); ++j)
    for (int k = outer[j]; k < outer[j + 1]; ++k) {
      const int i = inner[k];
      const int* begin = inner + outer[i];
      const int* end = inner + outer[i + 1];
      const int* at = std::lower_bound(begin, end, j);
      if (at == end || *at != j) throw std::invalid_argument("TransposeMap: the sparsity pattern is not symmetric");
      transpose_[k] = static_cast<int>(at - inner);
    }
}

bool TransposeMap::symmetric(const SparseMatrix& K, double tolerance) const {
  const double* v = K.valuePtr();
  double scale = 0, diff = 0;
  for (std::size_t k = 0; k < transpose_.size(); ++k) {
    scale = std::max(scale, std::abs(v[k]));
    diff = std::max(diff, std::abs(v[k] - v[transpose_[k]]));
  }
  return diff <= tolerance * scale;
}

void TransposeMap::symmetrize(SparseMatrix& K) const {
  double* v = K.valuePtr();
  for (std::size_t k = 0; k < transpose_.size(); ++k) {
    const std::size_t t = static_cast<std::size_t>(transpose_[k]);
    if (t <= k) continue;  // each pair once (the diagonal maps to itself)
    const double mean = 0.5 * (v[k] + v[t]);
    v[k] = mean;
    v[t] = mean;
  }
}

}  // namespace tunica
