#pragma once
// Total-Lagrangian 3-D membrane elements: 3-node triangles and 4-node
// quadrilaterals on curved surfaces, any incompressible material through the
// general C-based path of membrane_response() (theory manual §2.1), not principal axes
// (theory manual §5.1).
//
// At a Gauss point the reference tangent plane carries an orthonormal material
// frame (e1, e2); s_i is arc length along e_i. With the reference Jacobian
// A_iα = e_i·G_α (G_α = ∂X/∂ξ^α), ∂N_a/∂s_i = Σ_α ∂N_a/∂ξ^α (A⁻¹)_αi and the
// convected vectors f_i = ∂x/∂s_i = Σ_a x_a ∂N_a/∂s_i give
//     C_ij = f_i·f_j,   E_ij = ½(C_ij − δ_ij)              (i, j ∈ {1, 2}),
//     δE_ij = ½ Σ_a δx_a·(f_i ∂N_a/∂s_j + f_j ∂N_a/∂s_i),
//     f_int,a = ∫ Σ_ij S_ij f_i ∂N_a/∂s_j H dA₀,
//     K_ab = ∫ [B_aᵀ D B_b + Σ_ij S_ij ∂N_a/∂s_i ∂N_b/∂s_j I₃] H dA₀,
// B_a the 3×3 map δx_a ↦ (δE11, δE22, 2δE12). Element DOFs are node-major:
// (u_x1, u_y1, u_z1, u_x2, ...). Reference data are computed once per element.
#include <Eigen/Dense>
#include <array>
#include <functional>

#include "elements/membrane_point.hpp"
#include "elements/surface_shape.hpp"
#include "materials/membrane_material.hpp"

namespace tunica {

template <int N>
using SurfaceNodes = Eigen::Matrix<double, 3, N>;  ///< column a = position of node a
template <int N>
using ElementVector = Eigen::Matrix<double, 3 * N, 1>;
template <int N>
using ElementMatrix = Eigen::Matrix<double, 3 * N, 3 * N>;

/// Gives the wanted material direction 1 at a reference point X with unit
/// surface normal n; it need not be tangent or of unit length: its projection
/// on the tangent plane, normalized, is e1, and e2 = n × e1.
using DirectionRule = std::function<Eigen::Vector3d(const Eigen::Vector3d& X, const Eigen::Vector3d& n)>;

/// A direction 1 whose tangent projection is shorter than this fraction of its
/// length (within 0.06° of the normal) is refused as normal to the surface.
constexpr double kMinTangentFraction = 1e-3;

/// What an element needs of its reference configuration, per Gauss point.
template <int N>
struct MembraneReference {
  static constexpr int Q = SurfaceShapeTraits<N>::kPoints;
  // What the residual and tangent read first, side by side (the rest is for the Gauss-point output).
  std::array<Eigen::Matrix<double, N, 2>, Q> dNds;   ///< ∂N_a/∂s_i
  std::array<double, Q> weight{};                    ///< Gauss weight × dA₀ × H (reference volume)
  std::array<Eigen::Matrix<double, N, 1>, Q> shape;  ///< N_a at the Gauss point
  std::array<Eigen::Vector3d, Q> X;                  ///< reference position
  std::array<Eigen::Vector3d, Q> e1, e2;             ///< material frame (unit, tangent)
  std::array<double, Q> thickness{};                 ///< reference thickness H
};

/// Gauss point q of `ref` made one of a prestressed reference (theory manual (13.20)): the stress-free
/// coordinates s̃ with s = P s̃, so ∂N/∂s̃ = (∂N/∂s) P and the stress-free volume element the weight / det P.
template <int N>
void prestretch_reference(MembraneReference<N>& ref, int q, const Eigen::Matrix2d& P) {
  ref.dNds[q] = ref.dNds[q] * P;
  ref.weight[q] /= P.determinant();
}

/// Why a reference element cannot be used.
class BadElement : public std::domain_error {
public:
  using std::domain_error::domain_error;
};

/// Reference data of an element with reference nodes X and thickness H.
/// Throws BadElement if the element is degenerate (area ≤ 1e-12 × the square of
/// its longest edge, corner to corner, at a Gauss point), folded (an element of
/// several Gauss points whose normal g1 × g2 reverses between them: "folded
/// <shape name>"), or if the direction rule gives a direction normal to the
/// surface (see kMinTangentFraction) or not finite.
/// Defined in membrane3d_impl.hpp, instantiated per shape (membrane3d.cpp: N = 3, 4).
template <int N>
MembraneReference<N> membrane_reference(const SurfaceNodes<N>& X, double H, const DirectionRule& direction1);

/// Internal force f (3N) and, if K is given, the tangent ∂f/∂x (material +
/// geometric, symmetric) of the element at current nodes x. `points`, if
/// given, receives the Gauss-point states. Throws std::domain_error if the
/// in-plane det C is not positive at a Gauss point.
template <int N>
void membrane3d(const MembraneReference<N>& ref, const SurfaceNodes<N>& x, const MembraneMaterial& material,
                ElementVector<N>& f, ElementMatrix<N>* K,
                std::array<MembranePoint, SurfaceShapeTraits<N>::kPoints>* points = nullptr);

}  // namespace tunica
