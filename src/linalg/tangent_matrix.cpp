#include "linalg/tangent_matrix.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace tunica {

TangentMatrix::TangentMatrix(SparseMatrix general) : general_(std::move(general)) { general_.makeCompressed(); }

TangentMatrix::TangentMatrix(std::shared_ptr<const TangentLayout> layout, bool upper)
    : layout_(std::move(layout)), values_(static_cast<std::size_t>(layout_->slots()) * (upper ? 2 : 1), 0.0),
      upper_(upper) {}

const TangentLayout& TangentMatrix::layout() const {
  if (!layout_) throw std::logic_error("TangentMatrix: a general matrix has no tangent layout");
  return *layout_;
}

SparseMatrix& TangentMatrix::general() {
  if (layout_) throw std::logic_error("TangentMatrix: a split tangent is not a general matrix (expand it)");
  return general_;
}

const SparseMatrix& TangentMatrix::general() const {
  if (layout_) throw std::logic_error("TangentMatrix: a split tangent is not a general matrix (expand it)");
  return general_;
}

void TangentMatrix::require_both(const char* what) const {
  if (!layout_ || !has_upper())
    throw std::logic_error(std::string("TangentMatrix: ") + what + " needs a split tangent with both triangles");
}

void TangentMatrix::set_zero() {
  std::fill(values_.begin(), values_.end(), 0.0);
  if (!layout_) general_.coeffs().setZero();
}

double TangentMatrix::max_abs() const {
  double m = 0;
  if (!layout_) return general_.nonZeros() ? general_.coeffs().abs().maxCoeff() : 0.0;
  for (double v : values_) m = std::max(m, std::abs(v));
  return m;
}

Eigen::VectorXd TangentMatrix::diagonal() const {
  if (!layout_) return general_.diagonal();
  const std::vector<int>& slot = layout_->diagonal_slots();
  Eigen::VectorXd d(layout_->size());
  for (int i = 0; i < layout_->size(); ++i) d(i) = slot[i] >= 0 ? values_[static_cast<std::size_t>(slot[i])] : 0.0;
  return d;
}

void TangentMatrix::add_to_diagonal(const Eigen::VectorXd& d) {
  if (!layout_) {
    for (int j = 0; j < general_.outerSize(); ++j)
      for (SparseMatrix::InnerIterator it(general_, j); it; ++it)
        if (it.row() == j) it.valueRef() += d(j);
    return;
  }
  const std::vector<int>& slot = layout_->diagonal_slots();
  for (int i = 0; i < layout_->size(); ++i)
    if (slot[i] >= 0) values_[static_cast<std::size_t>(slot[i])] += d(i);
}

bool TangentMatrix::symmetric(double tolerance) const {
  require_both("the symmetry test");
  const int* outer = layout_->lower_outer().data();
  const int* inner = layout_->lower_inner().data();
  const double* lo = lower();
  const double* up = upper();
  double scale = 0, diff = 0;
  for (int c = 0; c < layout_->size(); ++c) {
    int q = outer[c];
    if (q < outer[c + 1] && inner[q] == c) scale = std::max(scale, std::abs(lo[q++]));  // the diagonal: no upper value
    for (; q < outer[c + 1]; ++q) {
      scale = std::max(scale, std::max(std::abs(lo[q]), std::abs(up[q])));
      diff = std::max(diff, std::abs(lo[q] - up[q]));
    }
  }
  return diff <= tolerance * scale;
}

void TangentMatrix::symmetrize() {
  require_both("symmetrization");
  const int* outer = layout_->lower_outer().data();
  const int* inner = layout_->lower_inner().data();
  double* lo = lower();
  double* up = upper();
  for (int c = 0; c < layout_->size(); ++c) {
    int q = outer[c];
    if (q < outer[c + 1] && inner[q] == c) ++q;  // the diagonal stays
    for (; q < outer[c + 1]; ++q) lo[q] = up[q] = 0.5 * (lo[q] + up[q]);
  }
}

void TangentMatrix::expand(SparseMatrix& out) const {
  if (!layout_) {
    out = general_;
    return;
  }
  require_both("the full matrix");
  const SparseMatrix& pattern = layout_->pattern();
  if (out.rows() != pattern.rows() || out.cols() != pattern.cols() || out.nonZeros() != pattern.nonZeros() ||
      !out.isCompressed() ||
      !std::equal(out.outerIndexPtr(), out.outerIndexPtr() + out.cols() + 1, pattern.outerIndexPtr()))
    out = pattern;
  const std::vector<int>& codes = layout_->pattern_codes();
  double* v = out.valuePtr();
  for (std::size_t q = 0; q < codes.size(); ++q) v[q] = values_[static_cast<std::size_t>(codes[q])];
}

}  // namespace tunica
