#pragma once
// Follower pressure on a 2-node axisymmetric Kirchhoff–Love shell element,
// integrated on its cubic Hermite mid-surface (elements/hermite_meridian.hpp),
// not on the nodal chord. As for the membrane (loads/axisym_pressure.hpp,
// theory manual §6), p acts on the current mid-surface along n ds = (z_ξ, −r_ξ) dξ
// (the meridian direction turned clockwise) on the revolved area 2πr ds:
//   δW_ext = ∫₀¹ 2π p r (z_ξ δr − r_ξ δz) dξ,      (theory manual (11.4))
//   f_(j,r) = 2π p ∫ r z_ξ h_j dξ,   f_(j,z) = −2π p ∫ r r_ξ h_j dξ,
// h_j the Hermite functions (positions and slopes). Its derivative, the load
// stiffness (not symmetric):
//   ∂f_(j,r)/∂u_(k,r) = 2πp ∫ z_ξ h_j h_k,   ∂f_(j,r)/∂u_(k,z) = 2πp ∫ r h_j h_k,ξ,
//   ∂f_(j,z)/∂u_(k,r) = −2πp ∫ (r_ξ h_j h_k + r h_j h_k,ξ),   ∂f_(j,z)/∂u_(k,z) = 0.
// The integrands are polynomials of degree ≤ 8 in ξ: 5 Gauss points are exact.
// The enclosed volume about the z axis, V = π ∫ r² dz = π ∫₀¹ r² z_ξ dξ (degree 8,
// exact too), with ∂V/∂u_(k,r) = 2π ∫ r z_ξ h_k, ∂V/∂u_(k,z) = π ∫ r² h_k,ξ.
#include "elements/hermite_meridian.hpp"

namespace tunica {

/// External force f (8) of pressure p on the current shell element x (ShellNodes: positions
/// and slopes), reference X (for its Hermite length), and, if dfdu is given, ∂f/∂u (8×8;
/// the tangent gets −∂f/∂u).
void axisym_shell_pressure(const ShellNodes& X, const ShellNodes& x, double p, ShellVector& f, ShellMatrix* dfdu);

/// The element's share π ∫ r² dz of the enclosed volume about the z axis and, if grad is
/// given, its gradient (8).
double axisym_shell_volume(const ShellNodes& X, const ShellNodes& x, ShellVector* grad);

}  // namespace tunica
