#pragma once
// Central finite differences of the assembled residual R(u) against the assembled
// tangent K (free rows and columns only), for the system-level derivative tests.
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "assembly/system.hpp"

namespace tunica::test {

/// max over free (i, j) of |(R_j(u + h e_i) − R_j(u − h e_i))/(2h) − K(eq j, eq i)|.
inline double fd_tangent_error(const System& sys, const LoadState& loads, const Eigen::VectorXd& u,
                               const Eigen::MatrixXd& K, double h) {
  Eigen::VectorXd Rp, Rm;
  double worst = 0;
  for (int i = 0; i < static_cast<int>(u.size()); ++i) {
    const int col = sys.equation(i);
    if (col < 0) continue;
    Eigen::VectorXd up = u, um = u;
    up(i) += h;
    um(i) -= h;
    sys.assemble(up, loads, Rp, nullptr);
    sys.assemble(um, loads, Rm, nullptr);
    const Eigen::VectorXd d = (Rp - Rm) / (2 * h);
    for (int j = 0; j < static_cast<int>(u.size()); ++j)
      if (const int row = sys.equation(j); row >= 0) worst = std::max(worst, std::abs(d(j) - K(row, col)));
  }
  return worst;
}

}  // namespace tunica::test
