#pragma once
// A symmetric matrix's lower triangle, held in compressed columns by the caller, seen by CHOLMOD
// without a copy: what cholmod_analyze and cholmod_super_numeric read (stype −1: only entries
// with row ≥ column are read). The view borrows the arrays; they must outlive its use.
#include <cholmod.h>

#include <cstddef>

namespace tunica {

/// n × n, `nonzeros` entries: column j's rows `inner[outer[j]] … inner[outer[j+1]−1]`, ascending,
/// and their values `values[…]` (any values when only the pattern is read).
inline cholmod_sparse cholmod_lower_view(int n, long nonzeros, const int* outer, const int* inner,
                                         const double* values) {
  cholmod_sparse A{};
  A.nrow = A.ncol = static_cast<std::size_t>(n);
  A.nzmax = static_cast<std::size_t>(nonzeros);
  A.p = const_cast<int*>(outer);
  A.i = const_cast<int*>(inner);
  A.x = const_cast<double*>(values);
  A.stype = -1;
  A.itype = CHOLMOD_INT;
  A.xtype = CHOLMOD_REAL;
  A.dtype = CHOLMOD_DOUBLE;
  A.sorted = 1;
  A.packed = 1;
  return A;
}

}  // namespace tunica
