#include "linalg/tangent_layout.hpp"

#include <cholmod.h>

#include <algorithm>
#include <climits>
#include <stdexcept>

#include "linalg/cholmod_lower_view.hpp"
#include "linalg/compute_threads.hpp"

namespace tunica {

/// The symbolic factor and the CHOLMOD workspace that owns it.
struct TangentLayout::Cholmod {
  cholmod_common common{};
  cholmod_factor* factor = nullptr;
  Cholmod() {
    cholmod_start(&common);
    common.print = 0;  // failures are reported by us
    common.supernodal = CHOLMOD_SUPERNODAL;
    common.final_asis = 1;
  }
  ~Cholmod() {
    if (factor) cholmod_free_factor(&factor, &common);
    cholmod_finish(&common);
  }
  Cholmod(const Cholmod&) = delete;
  Cholmod& operator=(const Cholmod&) = delete;
};

TangentLayout::TangentLayout(SparseMatrix pattern) : pattern_(std::move(pattern)) {
  pattern_.makeCompressed();
  const int n = static_cast<int>(pattern_.rows());
  if (pattern_.cols() != n) throw std::invalid_argument("TangentLayout: the pattern is not square");
  const int* outer = pattern_.outerIndexPtr();
  const int* inner = pattern_.innerIndexPtr();
  const auto find = [&](int i, int j) {  // position of (i, j) in the pattern, −1 if absent
    const int* begin = inner + outer[j];
    const int* end = inner + outer[j + 1];
    const int* at = std::lower_bound(begin, end, i);
    return at == end || *at != i ? -1 : static_cast<int>(at - inner);
  };

  // The ordering: CHOLMOD's analysis of the lower triangle, as cholmod_factorize's callers hand it
  // over (stype −1: the upper entries are ignored), so that P is the one CHOLMOD chose before.
  std::vector<int>& perm = ordering_;
  perm.assign(static_cast<std::size_t>(n), 0);
  if (n > 0) {
    cholmod_ = std::make_unique<Cholmod>();
    cholmod_sparse A = cholmod_lower_view(n, pattern_.nonZeros(), pattern_.outerIndexPtr(),
                                          pattern_.innerIndexPtr(), pattern_.valuePtr());
    {
      const SerialOpenMP serial;  // CHOLMOD's own loops on the calling thread (linalg/compute_threads.hpp)
      cholmod_->factor = cholmod_analyze(&A, &cholmod_->common);
    }
    if (!cholmod_->factor || cholmod_->common.status < CHOLMOD_OK)
      throw std::runtime_error("CHOLMOD's symbolic analysis of the tangent's pattern failed (status " +
                               std::to_string(cholmod_->common.status) + ")");
    const int* P = static_cast<const int*>(cholmod_->factor->Perm);
    std::copy(P, P + n, perm.begin());
  }
  // The storage: K's lower triangle in Tunica's numbering, column by column with ascending rows (the
  // pattern's own order, which follows the mesh: the element loop's writes stay near each other);
  // an upper entry (i < j) shares the slot of its transpose, S further on.
  const long nnz = pattern_.nonZeros();
  codes_.assign(static_cast<std::size_t>(nnz), -1);
  lower_outer_.assign(static_cast<std::size_t>(n) + 1, 0);
  lower_inner_.clear();
  lower_inner_.reserve(static_cast<std::size_t>((nnz + n) / 2));
  for (int j = 0; j < n; ++j) {
    lower_outer_[j] = static_cast<int>(lower_inner_.size());
    for (int q = outer[j]; q < outer[j + 1]; ++q)
      if (const int i = inner[q]; i >= j) {
        if (find(j, i) < 0) throw std::invalid_argument("TangentLayout: the sparsity pattern is not symmetric");
        codes_[q] = static_cast<int>(lower_inner_.size());
        lower_inner_.push_back(i);
      }
  }
  const long slots = static_cast<long>(lower_inner_.size());
  lower_outer_[n] = static_cast<int>(slots);
  if (2 * slots + 1 > INT_MAX) throw std::length_error("TangentLayout: too many nonzeros for int indices");
  for (int j = 0; j < n; ++j)
    for (int q = outer[j]; q < outer[j + 1]; ++q)
      if (const int i = inner[q]; i < j) codes_[q] = static_cast<int>(slots) + codes_[find(j, i)];
  diagonal_.assign(static_cast<std::size_t>(n), -1);
  for (int i = 0; i < n; ++i)
    if (const int q = find(i, i); q >= 0) diagonal_[i] = codes_[q];

  // CHOLMOD's matrix, tril(P K Pᵀ), column by column with ascending rows: the slots bucketed by
  // their row of P K Pᵀ, then appended to their columns row by row.
  std::vector<int> row_of(static_cast<std::size_t>(n));  // pᵢ: the row of P K Pᵀ that row i becomes
  for (int k = 0; k < n; ++k) row_of[perm[k]] = k;
  std::vector<int> by_row_start(static_cast<std::size_t>(n) + 1, 0);
  cholmod_outer_.assign(static_cast<std::size_t>(n) + 1, 0);
  for (int j = 0; j < n; ++j)
    for (int s = lower_outer_[j]; s < lower_outer_[j + 1]; ++s) {
      const int i = lower_inner_[s];
      ++by_row_start[std::max(row_of[i], row_of[j]) + 1];
      ++cholmod_outer_[std::min(row_of[i], row_of[j]) + 1];
    }
  for (int k = 0; k < n; ++k) {
    by_row_start[k + 1] += by_row_start[k];
    cholmod_outer_[k + 1] += cholmod_outer_[k];
  }
  std::vector<int> by_row(static_cast<std::size_t>(slots)), column_of(static_cast<std::size_t>(slots));
  {
    std::vector<int> next(by_row_start.begin(), by_row_start.end() - 1);
    for (int j = 0; j < n; ++j)
      for (int s = lower_outer_[j]; s < lower_outer_[j + 1]; ++s) {
        by_row[next[std::max(row_of[lower_inner_[s]], row_of[j])]++] = s;
        column_of[s] = j;
      }
  }
  cholmod_inner_.resize(static_cast<std::size_t>(slots));
  cholmod_from_.resize(static_cast<std::size_t>(slots));
  std::vector<int> next(cholmod_outer_.begin(), cholmod_outer_.end() - 1);
  for (int r = 0; r < n; ++r)
    for (int k = by_row_start[r]; k < by_row_start[r + 1]; ++k) {
      const int s = by_row[k];
      const int t = next[std::min(row_of[lower_inner_[s]], row_of[column_of[s]])]++;
      cholmod_inner_[t] = r;
      cholmod_from_[t] = s;
    }
}

void TangentLayout::to_cholmod(const double* lower, double* out) const {
  const int* from = cholmod_from_.data();
  const std::size_t count = cholmod_from_.size();
  for (std::size_t t = 0; t < count; ++t) out[t] = lower[from[t]];
}

TangentLayout::~TangentLayout() = default;

int TangentLayout::entry(int i, int j) const {
  if (i < 0 || j < 0) return -1;
  const int* inner = pattern_.innerIndexPtr();
  const int* begin = inner + pattern_.outerIndexPtr()[j];
  const int* end = inner + pattern_.outerIndexPtr()[j + 1];
  const int* at = std::lower_bound(begin, end, i);
  if (at == end || *at != i) throw std::logic_error("an entry of the tangent is missing from its pattern");
  return codes_[static_cast<std::size_t>(at - inner)];
}

const cholmod_factor_struct* TangentLayout::symbolic() const { return cholmod_ ? cholmod_->factor : nullptr; }

}  // namespace tunica
