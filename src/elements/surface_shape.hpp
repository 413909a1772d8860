#pragma once
// Isoparametric shape functions and quadrature of the 3-D membrane elements
// (theory manual §5.1): the 3-node triangle (ξ, η ≥ 0, ξ + η ≤ 1; N = (1−ξ−η, ξ, η);
// one Gauss point at the centroid, weight ½) and the 4-node quadrilateral
// (ξ, η ∈ [−1, 1]; bilinear N; 2 × 2 Gauss points, weights 1). Node order is
// counterclockwise seen from the side the surface normal g1 × g2 points to.
//
// A shape is a specialization SurfaceShapeTraits<N> (N its number of nodes), defined in its header
// (inline: the kernels see the constants of a shape's rule and derivatives), with
//   kNodes = N, kPoints (Gauss points), kCorners (its first kCorners nodes are the
//   corners, counterclockwise), kName (in messages: "folded <kName>"),
//   static void gauss_point(int q, double& xi, double& eta, double& weight)
//     (throws std::out_of_range unless 0 ≤ q < kPoints),
//   static Eigen::Matrix<double, N, 1> values(double xi, double eta),
//   static Eigen::Matrix<double, N, 2> derivatives(double xi, double eta)
//     (column 0 = ∂N/∂ξ, column 1 = ∂N/∂η).
// The element and load kernels are templates on N that use nothing else of the shape;
// a new shape is its own header declaring the specialization (e.g. tri6_shape.hpp), and
// code that instantiates the kernels for it includes that header.
#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <stdexcept>

namespace tunica {

/// Element shapes of 3-D membrane meshes (tri3, quad4; not needed by the generic code).
enum class SurfaceShape { tri3, quad4 };

template <int N>
struct SurfaceShapeTraits;

template <>
struct SurfaceShapeTraits<3> {
  static constexpr int kNodes = 3;
  static constexpr int kPoints = 1;  ///< Gauss points
  static constexpr int kCorners = 3;
  static constexpr const char* kName = "triangle";
  static constexpr SurfaceShape kShape = SurfaceShape::tri3;
  // N = (1 − ξ − η, ξ, η); one Gauss point at the centroid (⅓, ⅓), weight ½ (the parametric
  // triangle's area); exact for linear integrands.
  static void gauss_point(int q, double& xi, double& eta, double& weight) {
    if (q < 0 || q >= kPoints) throw std::out_of_range("gauss_point: no such Gauss point");
    xi = eta = 1.0 / 3.0;
    weight = 0.5;
  }
  static Eigen::Matrix<double, 3, 1> values(double xi, double eta) {
    Eigen::Matrix<double, 3, 1> n;
    n << 1.0 - xi - eta, xi, eta;
    return n;
  }
  static Eigen::Matrix<double, 3, 2> derivatives(double, double) {
    Eigen::Matrix<double, 3, 2> d;
    d << -1, -1,  //
        1, 0,     //
        0, 1;
    return d;
  }
};

template <>
struct SurfaceShapeTraits<4> {
  static constexpr int kNodes = 4;
  static constexpr int kPoints = 4;
  static constexpr int kCorners = 4;
  static constexpr const char* kName = "quadrilateral";
  static constexpr SurfaceShape kShape = SurfaceShape::quad4;
  // Nodes at (ξ_a, η_a) = (−1, −1), (1, −1), (1, 1), (−1, 1), N_a = ¼(1 + ξ_a ξ)(1 + η_a η); 2 × 2 Gauss
  // points (±1/√3, ±1/√3), weights 1, numbered like the nodes (point q is the one nearest node q);
  // exact for integrands of degree ≤ 3 in each of ξ and η.
  static constexpr double kXi[4] = {-1, 1, 1, -1}, kEta[4] = {-1, -1, 1, 1};
  static void gauss_point(int q, double& xi, double& eta, double& weight) {
    if (q < 0 || q >= kPoints) throw std::out_of_range("gauss_point: no such Gauss point");
    const double g = 1.0 / std::sqrt(3.0);
    xi = kXi[q] * g;
    eta = kEta[q] * g;
    weight = 1.0;
  }
  static Eigen::Matrix<double, 4, 1> values(double xi, double eta) {
    Eigen::Matrix<double, 4, 1> n;
    for (int a = 0; a < 4; ++a) n(a) = 0.25 * (1.0 + kXi[a] * xi) * (1.0 + kEta[a] * eta);
    return n;
  }
  static Eigen::Matrix<double, 4, 2> derivatives(double xi, double eta) {
    Eigen::Matrix<double, 4, 2> d;
    for (int a = 0; a < 4; ++a) {
      d(a, 0) = 0.25 * kXi[a] * (1.0 + kEta[a] * eta);  // ∂N_a/∂ξ
      d(a, 1) = 0.25 * kEta[a] * (1.0 + kXi[a] * xi);   // ∂N_a/∂η
    }
    return d;
  }
};

/// Gauss point q of an N-node element: parametric coordinates and weight.
template <int N>
inline void gauss_point(int q, double& xi, double& eta, double& weight) {
  SurfaceShapeTraits<N>::gauss_point(q, xi, eta, weight);
}
/// Shape functions at (ξ, η).
template <int N>
inline Eigen::Matrix<double, N, 1> shape_values(double xi, double eta) {
  return SurfaceShapeTraits<N>::values(xi, eta);
}
/// Parametric derivatives: column 0 = ∂N/∂ξ, column 1 = ∂N/∂η.
template <int N>
inline Eigen::Matrix<double, N, 2> shape_derivatives(double xi, double eta) {
  return SurfaceShapeTraits<N>::derivatives(xi, eta);
}

}  // namespace tunica
