#pragma once
// The stress-free start's normal-tension stiffness (theory manual §7.2, (7.6)–(7.7)) of a 2-node
// axisymmetric membrane segment: with n = (t_z, −t_r) the segment's reference normal in the (r, z)
// plane and w_a = u_a·n the normal displacement of node a, Q = ½ T₀ ∫ (∂w/∂s)² dA₀ over the
// surface of revolution, dA₀ = 2πR dS, ∂w/∂s = (w_b − w_a)/L on the straight segment, gives
//     K₀ = T₀ 2π R_mid / L · b bᵀ,   b = (−n_r, −n_z, n_r, n_z)           (DOFs u_r1, u_z1, u_r2, u_z2),
// symmetric, positive semidefinite, zero for a uniform normal displacement and any tangential
// motion of the segment: it resists only the relative normal motion of its two nodes (the kinks of
// a meridian nearly flat across the axis, which an unstressed membrane resists with nothing).
#include <Eigen/Dense>

namespace tunica {

/// K₀ (4×4) of the segment from reference node Xa to Xb (each (r, z)) for the tension T₀, overwritten.
void axisym_normal_tension_stiffness(const Eigen::Vector2d& Xa, const Eigen::Vector2d& Xb, double T0,
                                     Eigen::Matrix4d& K);

}  // namespace tunica
