#pragma once
// Kinematics policies of the element kernels (contributions/element_loop.hpp): how an
// element's nodal state is gathered from the model's DOF vector and where each element
// unknown sits in it. The axisymmetric/3-D difference is this policy, not a second code
// path: positions in the (r, z) meridian plane (2 per node), positions in space (3 per
// node), or meridian positions and slopes (4 per node, the shells' DOF map, model/model.hpp).
#include <Eigen/Dense>

#include "elements/hermite_meridian.hpp"
#include "model/model.hpp"

namespace tunica {

/// N nodes in the (r, z) meridian plane: column a of X and x is (r_a, z_a).
template <int N>
struct PlaneKinematics {
  static constexpr int kNodes = N, kUnknowns = 2;
  struct State {
    Eigen::Matrix<double, 2, N> X, x;
  };
  static void gather(const Model& m, const int* en, const Eigen::VectorXd& u, State& s) {
    for (int a = 0; a < N; ++a) {
      s.X.col(a) = m.X[en[a]].template head<2>();
      s.x.col(a) = s.X.col(a) + u.template segment<2>(2 * en[a]);
    }
  }
  static int dof(const Model&, const int* en, int k) { return 2 * en[k / 2] + k % 2; }
};

/// N nodes in space: column a of x is the current position of node a (the reference data
/// of the 3-D membranes are computed once, contributions/surface_references.hpp).
template <int N>
struct SpaceKinematics {
  static constexpr int kNodes = N, kUnknowns = 3;
  struct State {
    Eigen::Matrix<double, 3, N> x;
  };
  static void gather(const Model& m, const int* en, const Eigen::VectorXd& u, State& s) {
    for (int a = 0; a < N; ++a) s.x.col(a) = m.X[en[a]] + u.template segment<3>(3 * en[a]);
  }
  static int dof(const Model&, const int* en, int k) { return 3 * en[k / 3] + k % 3; }
  /// R(dof(k)) += f(k) for every unknown k of the element: node by node, three at a time.
  template <class Vector>
  static void add(const Model&, const int* en, const Vector& f, Eigen::VectorXd& R) {
    for (int a = 0; a < N; ++a) R.template segment<3>(3 * en[a]) += f.template segment<3>(3 * a);
  }
};

/// The 2 nodes of an axisymmetric shell element: column a = (r, z, r′, z′) of node en[a], X from
/// the reference positions and slopes, x = X + (u_r, u_z, u′_r, u′_z) (theory manual §11).
struct ShellKinematics {
  static constexpr int kNodes = 2, kUnknowns = 4;
  struct State {
    ShellNodes X, x;
  };
  static void gather(const Model& m, const int* en, const Eigen::VectorXd& u, State& s) {
    for (int a = 0; a < 2; ++a) {
      const int n = en[a];
      s.X.block<2, 1>(0, a) = m.X[n].head<2>();
      s.X.block<2, 1>(2, a) = m.slope_ref[n];
      s.x.block<2, 1>(0, a) = s.X.block<2, 1>(0, a) + u.segment<2>(2 * n);
      s.x.block<2, 1>(2, a) = s.X.block<2, 1>(2, a) + u.segment<2>(m.slope_dof[n]);
    }
  }
  static int dof(const Model& m, const int* en, int k) { return m.node_dof(en[k / 4], k % 4); }
};

}  // namespace tunica
