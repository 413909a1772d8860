#pragma once
// Four-node axisymmetric finite-strain solid element (theory manual §10, (10.1)–(10.5);
// the plaque of the paper's angioplasty example, §12.2).
//
// Bilinear quadrilateral in the (r, z) meridian plane, total Lagrangian, 2×2 Gauss
// quadrature, reference volume element dV = 2πR dA. Nodes are numbered counter-
// clockwise in the (r, z) plane; DOFs per element are (u_r1, u_z1, …, u_r4, u_z4).
// Deformation gradient in the directions (r, z, θ):
//   F = [[∂r/∂R, ∂r/∂Z, 0], [∂z/∂R, ∂z/∂Z, 0], [0, 0, r/R]].
//
// Two formulations of the same decoupled energy W = W_iso(C̄) + U(J)
// (materials/solid_material.hpp):
//   displacement:     Π_e = Σ_g w_g [W_iso(C̄_g) + U(J_g)]
//   mean_dilatation:  Π_e = Σ_g w_g W_iso(C̄_g) + V U(θ),  θ = v/V,
//                     the Q1/P0 element with the element-constant pressure
//                     p = U'(θ) and dilatation θ condensed out (see the .cpp).
// Both return the element energy Π_e, the internal force f = ∂Π_e/∂x and the
// tangent K = ∂²Π_e/∂x² (symmetric), exactly (f and K are the derivatives of the
// quadrature energy).
#include <Eigen/Dense>
#include <array>

#include "materials/solid_material.hpp"

namespace tunica {

/// Nodal coordinates of a 4-node axisymmetric solid element: column a = (r_a, z_a).
using SolidNodes = Eigen::Matrix<double, 2, 4>;
using SolidVector = Eigen::Matrix<double, 8, 1>;
using SolidMatrix = Eigen::Matrix<double, 8, 8>;

enum class SolidFormulation {
  displacement,     ///< plain Q1 element (locks when nearly incompressible)
  mean_dilatation,  ///< Q1/P0 mixed element (Simo, Taylor & Pister 1985)
};

/// The state at one Gauss point, for output.
struct SolidPoint {
  double R = 0, Z = 0;                            ///< reference position
  double r = 0, z = 0;                            ///< current position
  Eigen::Vector4d sigma = Eigen::Vector4d::Zero();  ///< Cauchy stress (σ_rr, σ_zz, σ_θθ, σ_rz)
  double p = 0;       ///< hydrostatic stress tr σ/3 (positive in tension): U'(J) or, mixed, U'(θ)
  double J = 0;       ///< det F at the point
  double theta = 0;   ///< the dilatation the volumetric energy sees: J, or, mixed, θ = v/V
  double W = 0;       ///< energy density W_iso + U(theta) per reference volume (Σ W·weight = Π_e)
  double weight = 0;  ///< Gauss weight × 2πR det(∂X/∂ξ)
};

/// Energy Π_e, internal force f (8) and, if K is given, the tangent K = ∂f/∂u (8×8) of
/// one element with reference nodes X and current nodes x. `points`, if given,
/// receives the Gauss-point states. Throws std::domain_error if the reference
/// element is inverted or degenerate, a Gauss point is not at R > 0 and r > 0, or
/// J (or θ) is not positive.
double axisym_solid(const SolidNodes& X, const SolidNodes& x, const SolidMaterial& material,
                    SolidFormulation formulation, SolidVector& f, SolidMatrix* K,
                    std::array<SolidPoint, 4>* points = nullptr);

}  // namespace tunica
