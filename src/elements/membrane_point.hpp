#pragma once
// The state of a membrane at one Gauss point, for output (history, ParaView),
// the same for the axisymmetric and the 3-D elements. Directions 1 and 2 are the
// material frame (axisymmetric: 1 = hoop, 2 = meridian); components are taken in
// that frame, except the Cauchy tensor, which is in global Cartesian axes
// (axisymmetric: the meridian plane θ = 0, x = r, y = hoop, z = z).
#include <Eigen/Dense>

namespace tunica {

struct MembranePoint {
  Eigen::Vector3d X = Eigen::Vector3d::Zero();  ///< reference position (axisymmetric: (R, Z, 0))
  Eigen::Vector3d x = Eigen::Vector3d::Zero();  ///< current position (axisymmetric: (r, z, 0))
  double R = 0, r = 0, z = 0;      ///< reference and current distance from the axis (3-D: the global z axis), current z
  Eigen::Vector3d lambda = Eigen::Vector3d::Ones();  ///< λ1 = √C11, λ2 = √C22, λ3 = √C33 (thickness)
  Eigen::Vector3d E = Eigen::Vector3d::Zero();       ///< Green–Lagrange strains (E11, E22, E12) in the material frame
  Eigen::Vector3d S = Eigen::Vector3d::Zero();       ///< 2nd Piola–Kirchhoff stresses (S11, S22, S12) in the material frame
  Eigen::Vector2d sigma = Eigen::Vector2d::Zero();   ///< Cauchy normal stresses along the convected directions: σ_α = t_α·σ t_α
  Eigen::Vector2d sigma_principal = Eigen::Vector2d::Zero();  ///< in-plane principal Cauchy stresses (max, min)
  Eigen::Matrix3d cauchy = Eigen::Matrix3d::Zero();  ///< Cauchy stress tensor σ = F S Fᵀ in global axes
  Eigen::Vector3d e1 = Eigen::Vector3d::UnitX();     ///< reference material direction 1 (unit, tangent)
  Eigen::Vector3d e2 = Eigen::Vector3d::UnitY();     ///< reference material direction 2 (unit, tangent)
  double thickness = 0;            ///< current thickness h = λ3 H (shells: ∫ dη, elements/shell_output.hpp)
  double reference_thickness = 0;  ///< reference thickness H (membranes; theory manual (13.12))
  /// Axisymmetric shells only (elements/shell_output.hpp; zero for membranes): bending moments
  /// (M_hoop, M_meridian) per current length, and the linearized surface stresses σ ± 6M/h²
  /// on the outer (side n) and inner surface.
  Eigen::Vector2d moment = Eigen::Vector2d::Zero();
  Eigen::Vector2d sigma_outer = Eigen::Vector2d::Zero();
  Eigen::Vector2d sigma_inner = Eigen::Vector2d::Zero();
  double W = 0;                    ///< strain energy per reference volume Ŵ
  double weight = 0;               ///< quadrature weight × reference volume element (Σ W·weight = stored energy)
};

}  // namespace tunica
