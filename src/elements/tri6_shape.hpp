#pragma once
// The 6-node quadratic triangle (theory manual §5.1, (5.7)): a shape of the 3-D membrane
// elements (surface_shape.hpp). Gmsh's node order (element type 9): corners 0, 1, 2
// counterclockwise at (ξ, η) = (0, 0), (1, 0), (0, 1), then the mid-edge nodes 3 (edge 0–1),
// 4 (edge 1–2), 5 (edge 2–0). With λ = 1 − ξ − η,
//     N0 = λ(2λ − 1),  N1 = ξ(2ξ − 1),  N2 = η(2η − 1),  N3 = 4λξ,  N4 = 4ξη,  N5 = 4ηλ.
// Quadrature: the symmetric 6-point rule of degree 4 (exact for every polynomial of degree
// ≤ 4 in ξ, η), in barycentric coordinates
//     (1 − 2a, a, a) and its permutations, weight w_a/2,  a = (8 − √10 + √(38 − 44√(2/5)))/18,
//     (1 − 2b, b, b) and its permutations, weight w_b/2,  b = (8 − √10 − √(38 − 44√(2/5)))/18,
//     w_a = (620 + √(213125 − 53320√10))/3720,  w_b = (620 − √(213125 − 53320√10))/3720,
// the weights summing to ½ (the parametric triangle's area, as the 3-node triangle's one
// point). Points 0–2 are the b-points nearest corners 0–2, points 3–5 the a-points nearest
// mid-edge nodes 3–5 (point q is the one nearest node q). Degree 4 integrates exactly the
// follower pressure, its load stiffness and the enclosed volume and its gradient (6.4)–(6.6)
// (n = g1 × g2 is of degree 2, N_a of degree 2) and, on a flat element with straight edges
// and mid-edge nodes at the midpoints, the stiffness of a linear material (∂N_a/∂s linear).
//
// Code that instantiates or calls the element and load kernels for N = 6 includes this header
// (the explicit instantiations are in tri6.cpp and loads/surface_pressure_tri6.cpp).
#include <stdexcept>

#include "elements/surface_shape.hpp"

namespace tunica {

template <>
struct SurfaceShapeTraits<6> {
  static constexpr int kNodes = 6;
  static constexpr int kPoints = 6;
  static constexpr int kCorners = 3;
  static constexpr const char* kName = "6-node triangle";

  static void gauss_point(int q, double& xi, double& eta, double& weight) {
    // a, b and 1 − 2a, 1 − 2b of the header, and the weights w_a/2, w_b/2 (to 20 digits).
    constexpr double a = 0.44594849091596488632, a1 = 0.10810301816807022736;
    constexpr double b = 0.091576213509770743460, b1 = 0.81684757298045851308;
    constexpr double wa = 0.11169079483900573285, wb = 0.054975871827660933819;
    constexpr double kXi[6] = {b, b1, b, a, a, a1};
    constexpr double kEta[6] = {b, b, b1, a1, a, a};
    if (q < 0 || q >= kPoints) throw std::out_of_range("gauss_point: no such Gauss point");
    xi = kXi[q];
    eta = kEta[q];
    weight = q < 3 ? wb : wa;
  }

  /// Parametric coordinates of node a (the fold check of membrane_reference looks at every node).
  static void node(int a, double& xi, double& eta) {
    constexpr double kXi[6] = {0, 1, 0, 0.5, 0.5, 0}, kEta[6] = {0, 0, 1, 0, 0.5, 0.5};
    xi = kXi[a];
    eta = kEta[a];
  }

  static Eigen::Matrix<double, 6, 1> values(double xi, double eta) {
    const double l = 1.0 - xi - eta;
    Eigen::Matrix<double, 6, 1> n;
    n << l * (2 * l - 1), xi * (2 * xi - 1), eta * (2 * eta - 1), 4 * l * xi, 4 * xi * eta, 4 * eta * l;
    return n;
  }

  static Eigen::Matrix<double, 6, 2> derivatives(double xi, double eta) {
    const double l = 1.0 - xi - eta;  // ∂λ/∂ξ = ∂λ/∂η = −1
    Eigen::Matrix<double, 6, 2> d;
    d << 1 - 4 * l, 1 - 4 * l,       //
        4 * xi - 1, 0,               //
        0, 4 * eta - 1,              //
        4 * (l - xi), -4 * xi,       //
        4 * eta, 4 * xi,             //
        -4 * eta, 4 * (l - eta);
    return d;
  }
};

}  // namespace tunica
