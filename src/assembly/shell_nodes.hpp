#pragma once
// Reference and current nodal states of an axisymmetric shell element from the
// model's DOF map (model/model.hpp): column a = (r, z, r′, z′) of node en[a],
// X from the reference positions and slopes, x = X + (u_r, u_z, u′_r, u′_z).
#include <Eigen/Dense>

#include "elements/hermite_meridian.hpp"
#include "model/model.hpp"

namespace tunica {

inline void shell_nodes(const Model& m, const int* en, const Eigen::VectorXd& u, ShellNodes& X, ShellNodes& x) {
  for (int a = 0; a < 2; ++a) {
    const int n = en[a];
    X.block<2, 1>(0, a) = m.X[n].head<2>();
    X.block<2, 1>(2, a) = m.slope_ref[n];
    x.block<2, 1>(0, a) = X.block<2, 1>(0, a) + u.segment<2>(2 * n);
    x.block<2, 1>(2, a) = X.block<2, 1>(2, a) + u.segment<2>(m.slope_dof[n]);
  }
}

/// The global DOF of element unknown k (0 … 7, ShellVector order) of a shell element.
inline int shell_dof(const Model& m, const int* en, int k) { return m.node_dof(en[k / 4], k % 4); }

}  // namespace tunica
