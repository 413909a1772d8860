// Shape functions and Gauss rules of the 3-D membrane elements (surface_shape.hpp;
// theory manual §5.1).
//  - 3-node triangle: N = (1 − ξ − η, ξ, η); one Gauss point at the centroid
//    (⅓, ⅓), weight ½ (the parametric triangle's area); exact for linear integrands.
//  - 4-node quadrilateral: nodes at (ξ_a, η_a) = (−1, −1), (1, −1), (1, 1), (−1, 1),
//    N_a = ¼(1 + ξ_a ξ)(1 + η_a η); 2 × 2 Gauss points (±1/√3, ±1/√3), weights 1,
//    numbered like the nodes (point q is the one nearest node q); exact for
//    integrands of degree ≤ 3 in each of ξ and η.
#include "elements/surface_shape.hpp"

#include <cmath>
#include <stdexcept>

namespace tunica {

namespace {
constexpr double kQuadXi[4] = {-1, 1, 1, -1};
constexpr double kQuadEta[4] = {-1, -1, 1, 1};
}  // namespace

void SurfaceShapeTraits<3>::gauss_point(int q, double& xi, double& eta, double& weight) {
  if (q < 0 || q >= kPoints) throw std::out_of_range("gauss_point: no such Gauss point");
  xi = eta = 1.0 / 3.0;
  weight = 0.5;
}

Eigen::Matrix<double, 3, 1> SurfaceShapeTraits<3>::values(double xi, double eta) {
  Eigen::Matrix<double, 3, 1> n;
  n << 1.0 - xi - eta, xi, eta;
  return n;
}

Eigen::Matrix<double, 3, 2> SurfaceShapeTraits<3>::derivatives(double, double) {
  Eigen::Matrix<double, 3, 2> d;
  d << -1, -1,  //
      1, 0,     //
      0, 1;
  return d;
}

void SurfaceShapeTraits<4>::gauss_point(int q, double& xi, double& eta, double& weight) {
  if (q < 0 || q >= kPoints) throw std::out_of_range("gauss_point: no such Gauss point");
  const double g = 1.0 / std::sqrt(3.0);
  xi = kQuadXi[q] * g;
  eta = kQuadEta[q] * g;
  weight = 1.0;
}

Eigen::Matrix<double, 4, 1> SurfaceShapeTraits<4>::values(double xi, double eta) {
  Eigen::Matrix<double, 4, 1> n;
  for (int a = 0; a < 4; ++a) n(a) = 0.25 * (1.0 + kQuadXi[a] * xi) * (1.0 + kQuadEta[a] * eta);
  return n;
}

Eigen::Matrix<double, 4, 2> SurfaceShapeTraits<4>::derivatives(double xi, double eta) {
  Eigen::Matrix<double, 4, 2> d;
  for (int a = 0; a < 4; ++a) {
    d(a, 0) = 0.25 * kQuadXi[a] * (1.0 + kQuadEta[a] * eta);  // ∂N_a/∂ξ
    d(a, 1) = 0.25 * kQuadEta[a] * (1.0 + kQuadXi[a] * xi);   // ∂N_a/∂η
  }
  return d;
}

}  // namespace tunica
