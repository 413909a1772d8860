#pragma once
// Central finite differences of the assembled residual R(u) against the assembled
// tangent K (free rows and columns only), for the system-level derivative tests.
#include <Eigen/Dense>
#include <algorithm>
#include <climits>
#include <cmath>

#include "assembly/system.hpp"

namespace tunica::test {

/// The fewest and the most active contact nodes over the perturbed states of fd_tangent_error.
struct ActiveRange {
  int fewest = INT_MAX;
  int most = INT_MIN;
};

/// max over free (i, j) of |(R_j(u + h e_i) − R_j(u − h e_i))/(2h) − K(eq j, eq i)|.
/// If `active` is given, it receives the range of System::assemble's active_contacts over all
/// the perturbed states u ± h e_i (a test that the active set stays the same around u).
inline double fd_tangent_error(const System& sys, const LoadState& loads, const Eigen::VectorXd& u,
                               const Eigen::MatrixXd& K, double h, ActiveRange* active = nullptr) {
  Eigen::VectorXd Rp, Rm;
  double worst = 0;
  for (int i = 0; i < static_cast<int>(u.size()); ++i) {
    const int col = sys.equation(i);
    if (col < 0) continue;
    Eigen::VectorXd up = u, um = u;
    up(i) += h;
    um(i) -= h;
    int ap = 0, am = 0;
    sys.assemble(up, loads, Rp, nullptr, nullptr, active ? &ap : nullptr);
    sys.assemble(um, loads, Rm, nullptr, nullptr, active ? &am : nullptr);
    if (active) {
      active->fewest = std::min({active->fewest, ap, am});
      active->most = std::max({active->most, ap, am});
    }
    const Eigen::VectorXd d = (Rp - Rm) / (2 * h);
    for (int j = 0; j < static_cast<int>(u.size()); ++j)
      if (const int row = sys.equation(j); row >= 0) worst = std::max(worst, std::abs(d(j) - K(row, col)));
  }
  return worst;
}

}  // namespace tunica::test
