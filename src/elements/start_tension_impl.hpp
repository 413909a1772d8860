#pragma once
// Definition of the normal-tension stiffness template (start_tension.hpp; theory manual (7.7)):
// K₀_ab = T₀ Σ_q (w_q/H) (∂N_a/∂s · ∂N_b/∂s) n_q n_qᵀ.
// Included only by the files that instantiate it for a shape (start_tension.cpp: tri3 and
// quad4; a new shape: its own file); every other file includes start_tension.hpp.
#include "elements/start_tension.hpp"

namespace tunica {

template <int N>
void normal_tension_stiffness(const MembraneReference<N>& ref, double T0, ElementMatrix<N>& K) {
  K.setZero();
  for (int q = 0; q < MembraneReference<N>::Q; ++q) {
    const Eigen::Vector3d n = ref.e1[q].cross(ref.e2[q]);  // reference unit normal
    const Eigen::Matrix3d nn = n * n.transpose();
    const Eigen::Matrix<double, N, N> G = ref.dNds[q] * ref.dNds[q].transpose();
    const double w = T0 * ref.weight[q] / ref.thickness[q];
    for (int a = 0; a < N; ++a)
      for (int b = 0; b < N; ++b) K.template block<3, 3>(3 * a, 3 * b) += (w * G(a, b)) * nn;
  }
}

}  // namespace tunica
