#pragma once
// Isoparametric shape functions and quadrature of the 3-D membrane elements:
// the 3-node triangle (ξ, η ≥ 0, ξ + η ≤ 1; N = (1−ξ−η, ξ, η); one Gauss point
// at the centroid, weight ½) and the 4-node quadrilateral (ξ, η ∈ [−1, 1];
// bilinear N; 2 × 2 Gauss points, weights 1). Node order is counterclockwise
// seen from the side the surface normal g1 × g2 points to.
#include <Eigen/Dense>
#include <array>

namespace tunica {

/// Element shapes of 3-D membrane meshes.
enum class SurfaceShape { tri3, quad4 };

template <int N>
struct SurfaceShapeTraits;

template <>
struct SurfaceShapeTraits<3> {
  static constexpr int kNodes = 3;
  static constexpr int kPoints = 1;  ///< Gauss points
  static constexpr SurfaceShape kShape = SurfaceShape::tri3;
};

template <>
struct SurfaceShapeTraits<4> {
  static constexpr int kNodes = 4;
  static constexpr int kPoints = 4;
  static constexpr SurfaceShape kShape = SurfaceShape::quad4;
};

/// Gauss point q of an N-node element: parametric coordinates and weight.
template <int N>
void gauss_point(int q, double& xi, double& eta, double& weight);
/// Shape functions at (ξ, η).
template <int N>
Eigen::Matrix<double, N, 1> shape_values(double xi, double eta);
/// Parametric derivatives: column 0 = ∂N/∂ξ, column 1 = ∂N/∂η.
template <int N>
Eigen::Matrix<double, N, 2> shape_derivatives(double xi, double eta);

}  // namespace tunica
