#pragma once
// The sparse matrix type of the assembled tangent (compressed columns, int indices).
#include <Eigen/Sparse>

namespace tunica {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

}  // namespace tunica
