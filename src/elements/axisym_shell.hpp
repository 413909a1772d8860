#pragma once
// Two-node axisymmetric Kirchhoff–Love shell element (theory manual §11; issue #4 item 6:
// the paper cross-checks its membranes against an axisymmetric Kirchhoff-type shell, §12.2).
// Finite strain, finite rotation, thin shell of revolution; the meridian lies in
// the (r, z) plane.
//
// Discretization. Each node carries its position and its slope, the derivative
// of the position with respect to the reference arc length S of the meridian:
//     node a: (r_a, z_a, r′_a, z′_a),   ′ = ∂/∂S,
// and the meridian is the cubic Hermite interpolant of both, ξ ∈ [0, 1]:
//     x(ξ) = h₀₀(ξ) x₁ + L h₁₀(ξ) x′₁ + h₀₁(ξ) x₂ + L h₁₁(ξ) x′₂,
//     h₀₀ = 2ξ³ − 3ξ² + 1, h₁₀ = ξ³ − 2ξ² + ξ, h₀₁ = −2ξ³ + 3ξ², h₁₁ = ξ³ − ξ²,
// the same for the reference X(ξ) with the reference unit tangents T_a = X′_a.
// L is a reference constant of the element, L = 2c / (1 + cos β̄) with c the
// reference chord and cos β̄ the mean cosine between T_a and the chord (the
// Hermite length of the best cubic on a circular arc, 4ρ tan(α/4): a half circle
// in 8 elements has its curvatures within 5e-5; L = c when straight),
// so |∂X/∂ξ| = L at both nodes and ∂x/∂ξ = L x′_a there: the interpolation is C¹
// in S across elements. This is the planar "gradient-deficient" absolute nodal
// coordinate formulation (ANCF) of Euler–Bernoulli beams (Shabana, Multibody
// Syst. Dyn. 1 (1997) 339–348; Berzeri & Shabana, J. Sound Vib. 235 (2000)
// 539–565; Gerstmayr & Shabana, Nonlinear Dyn. 45 (2006) 109–130), here with the
// hoop terms of a shell of revolution. Why this choice:
//  - C¹ meridian: the normal is continuous, so the curvature (second derivatives)
//    is square integrable and the Kirchhoff–Love energy is conforming;
//  - no rotation parameter: x is linear in the nodal unknowns, a finite rotation
//    of the meridian is exact (no angle, no trigonometry, no singularity), and
//    the energy is a smooth rational function of the unknowns;
//  - the alternative (u_r, u_z, φ) with φ the tangent angle leaves the tangent
//    length at the node undefined (it has to be guessed, e.g. from the chord);
//    the price here is 4 unknowns per node and a meridional stretch continuous
//    across nodes (split the node where thickness or material jumps).
//
// Kinematics. Mid-surface: λ_s = |x_ξ|/|X_ξ|, λ_θ = r/R, λ₃ = 1/(λ_s λ_θ), normal
// n = (z_ξ, −r_ξ)/|x_ξ| (to the right of the direction of node order: outward for
// a meridian running towards +z), N likewise; meridional curvature
// k_s = (r_ξ z_ξξ − r_ξξ z_ξ)/|x_ξ|³ and hoop curvature n_r/r (both 1/ρ on a sphere
// of radius ρ with n outward), K_s and N_r/R in the reference. The layer at
// reference distance ζ ∈ [−H/2, H/2] is at
//     X_ζ = X + ζ N,        x_ζ = x + η(ζ) n:
// normals stay normal and straight and layers parallel (Kirchhoff–Love), and
// the current distance η follows from incompressibility, the volume between the
// mid-surface and the layer being conserved:
//     ∫₀^η a (1 + t k_s)(r + t n_r) dt = ∫₀^ζ A (1 + t K_s)(R + t N_r) dt,
//     a = |x_ξ|, A = |X_ξ|   (a cubic in η, η ≈ λ₃ ζ; solved by Newton).
// Since n_ξ ∥ x_ξ in the plane, the layer's principal stretches are exactly
//     λ_s(ζ) = a (1 + η k_s) / (A (1 + ζ K_s)),     λ_θ(ζ) = (r + η n_r) / (R + ζ N_r),
// the mid-surface stretches modified by the curvatures, and the layer's normal
// stretch dη/dζ is exactly 1/(λ_s(ζ) λ_θ(ζ)): kinematics and the incompressible
// plane-stress reduction agree in every layer. (In plane strain, λ_θ ≡ 1, this is
// Rivlin's exact finite bending of an incompressible block. The simpler
// x_ζ = x + ζ n, or + λ₃ζ n, misses the prestress part of the bending stiffness:
// in cylindrical bending at meridional stretch λ, per reference area,
// D = (H³/12) λ² 𝒟₂₂ here against (H³/12)(λ²𝒟₂₂ + S₂₂) with λ₃ζ, i.e. several
// times too stiff at finite membrane strain.) Each layer is a
// membrane point: C = (C₁₁, C₂₂, C₁₂) = (λ_θ(ζ)², λ_s(ζ)², 0) (1 = hoop,
// 2 = meridian, as in the membrane element) through membrane_response()
// (incompressible plane stress, theory manual §2.1).
//
// Energy (exact reference volume element of the layered body; theory manual (11.3)):
//     Π_e = Σ_g Σ_k w_g w_k (H/2) 2π R_ζ A_ζ Ŵ(C(ξ_g, ζ_k)),
//     R_ζ = R + ζ N_r,  A_ζ = A (1 + ζ K_s),
// Gauss–Legendre along ξ and through ζ. f = ∂Π_e/∂x and K = ∂²Π_e/∂x² are its
// exact derivatives (second-order forward differentiation, core/jet.hpp, of the
// layer strains in the 5 local unknowns (r, r_ξ, z_ξ, r_ξξ, z_ξξ), η by implicit
// differentiation; z itself does not enter: a translation along the axis is
// free), so K is symmetric.
//
// Degrees of freedom, per element (u_r1, u_z1, u′_r1, u′_z1, u_r2, u_z2, u′_r2, u′_z2)
// = the column-major flattening of ShellNodes. In a model with membranes and
// solids (whose nodes carry u_r, u_z) a shell node shares u_r, u_z and keeps its
// two slope unknowns to itself; where a shell ends on another body the slope is
// free (a hinge) unless constrained. Common constraints: clamped or symmetry
// edge of a tube (meridian along z): r′ = 0; clamped edge of a meridian along r:
// z′ = 0; a pole of a closed surface: r = 0 and z′ = 0.
#include <Eigen/Dense>
#include <vector>

#include "elements/hermite_meridian.hpp"
#include "materials/membrane_material.hpp"

namespace tunica {

/// Gauss–Legendre points along the meridian and through the thickness (each 1..16).
struct ShellQuadrature {
  int meridian = 3;
  int thickness = 5;
};

/// The state at one meridian Gauss point, for output.
struct ShellPoint {
  double R = 0, Z = 0, r = 0, z = 0;                  ///< reference and current mid-surface position
  Eigen::Vector3d lambda = Eigen::Vector3d::Ones();   ///< mid-surface (λ_θ, λ_s, λ₃ = 1/(λ_θ λ_s))
  Eigen::Vector2d K = Eigen::Vector2d::Zero();        ///< reference curvatures (hoop N_r/R, meridian K_s)
  Eigen::Vector2d k = Eigen::Vector2d::Zero();        ///< current curvatures (hoop n_r/r, meridian k_s)
  std::vector<double> zeta;                           ///< reference distances ζ of the thickness points
  std::vector<double> eta;                            ///< their current distances η from the mid-surface
  Eigen::Matrix2Xd sigma;                             ///< Cauchy (σ_θ, σ_s) = (λ_θ² S₁, λ_s² S₂) per thickness point
  Eigen::Matrix2Xd stretch;                           ///< layer stretches (λ_θ(ζ), λ_s(ζ)) per thickness point
  std::vector<double> weight_zeta;                    ///< Gauss weights of the thickness points (Σ = H)
  Eigen::Vector2d t = Eigen::Vector2d::UnitY();       ///< current unit meridian tangent x_ξ/|x_ξ|
  Eigen::Vector2d T = Eigen::Vector2d::UnitY();       ///< reference unit meridian tangent X_ξ/|X_ξ|
  double W = 0;       ///< energy per reference mid-surface area ∫ Ŵ (R_ζ A_ζ)/(R A) dζ
  double weight = 0;  ///< Gauss weight × 2πR A (Σ W·weight = Π_e)
};

/// Energy Π_e, internal force f = ∂Π_e/∂x (8) and, if K is given, the tangent
/// K = ∂f/∂x (8×8, symmetric) of one element with reference nodes X, current nodes x,
/// reference thickness H. `points`, if given, receives the meridian Gauss-point states.
/// Throws std::invalid_argument for H ≤ 0, a bad quadrature, non-unit reference slopes
/// or reference slopes pointing against the element; std::domain_error if a stretch is
/// not positive (r ≤ 0, x_ξ = 0, a layer folded: λ_s(ζ) ≤ 0 or λ_θ(ζ) ≤ 0) or the
/// reference layers degenerate (R ≤ 0, or H/2 beyond a reference radius of curvature).
double axisym_shell(const ShellNodes& X, const ShellNodes& x, double H, const MembraneMaterial& material,
                    ShellVector& f, ShellMatrix* K, const ShellQuadrature& quadrature = {},
                    std::vector<ShellPoint>* points = nullptr);

}  // namespace tunica
