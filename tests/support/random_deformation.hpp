#pragma once
// Random, moderately large in-plane deformations for the finite-difference tests over the
// material registry (material_registry.hpp): principal stretches in [0.8, 1.6], a shear and a
// rotation, the Cauchy–Green tensor taken in a material frame at a given angle.
#include <Eigen/Dense>
#include <cmath>
#include <random>

namespace tunica::test {

inline Eigen::Matrix2d rotation2(double angle) {
  Eigen::Matrix2d Q;
  Q << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
  return Q;
}

/// F = Q(φ) diag(λ1, λ2) [[1, γ], [0, 1]]: λ1, λ2 ∈ [0.8, 1.6], γ ∈ [−0.3, 0.3], φ any rotation
/// (which C = FᵀF does not see: it is there for the elements, whose current state it turns).
inline Eigen::Matrix2d random_F2(std::mt19937& rng) {
  std::uniform_real_distribution<double> stretch(0.8, 1.6), shear(-0.3, 0.3), turn(-3.14159, 3.14159);
  const double l1 = stretch(rng), l2 = stretch(rng), g = shear(rng), phi = turn(rng);
  Eigen::Matrix2d S;
  S << 1, g, 0, 1;
  return rotation2(phi) * Eigen::Vector2d(l1, l2).asDiagonal() * S;
}

/// In-plane C = (C11, C22, C12) of F in a material frame turned by `angle` from the axes of F's
/// reference side: C = Qᵀ FᵀF Q, Q = Q(angle).
inline Eigen::Vector3d C_in_frame(const Eigen::Matrix2d& F, double angle) {
  const Eigen::Matrix2d Q = rotation2(angle);
  const Eigen::Matrix2d C = Q.transpose() * F.transpose() * F * Q;
  return Eigen::Vector3d(C(0, 0), C(1, 1), C(0, 1));
}

/// A general material argument v = (C11, C22, C12, C33): C33 off the incompressible value 1/det C
/// by a factor in [0.7, 1.4], so that the partial derivatives in C33 are checked on their own.
inline Eigen::Vector4d general_v(const Eigen::Vector3d& C, std::mt19937& rng) {
  const double det = C(0) * C(1) - C(2) * C(2);
  return Eigen::Vector4d(C(0), C(1), C(2), std::uniform_real_distribution<double>(0.7, 1.4)(rng) / det);
}

}  // namespace tunica::test
