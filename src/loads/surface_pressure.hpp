#pragma once
// Follower pressure on 3-D membrane elements and the volume they enclose (theory
// manual §6.1, (6.4)–(6.6)).
//
// Pressure p acts on the current surface along n dA = g1 × g2 dξ dη
// (g_α = ∂x/∂ξ^α; node order gives the side, see surface_shape.hpp):
//     f_a = p ∫ N_a (g1 × g2) dξ dη,
// exact with the element's Gauss rule (the integrand is polynomial). Its
// derivative ∂f/∂x is the load stiffness (nonsymmetric per element; symmetric
// after assembly over a closed surface).
//
// Enclosed volume contributed by an element, with respect to a reference point p₀:
//     V_e = ⅓ ∫ (x − p₀)·n dA                       (closed surfaces, or surfaces
//           closed by planes through p₀, such as symmetry planes),
// or, about an axis through p₀ with unit direction a:
//     V_e = ½ ∫ (x − p₀)⊥·n dA,  y⊥ = y − (a·y) a   (tubes closed by end planes
//           normal to the axis, such as an open vessel segment).
// Both are exact for the discrete surface; summing V_e over the surface gives the volume.
#include <Eigen/Dense>

#include "elements/membrane3d.hpp"

namespace tunica {

/// External nodal force f (3N) of pressure p on the current element x and, if
/// dfdx is given, ∂f/∂x (3N × 3N; the tangent gets −∂f/∂x). Defined, with enclosed_volume, in
/// surface_pressure_impl.hpp, instantiated per shape (surface_pressure.cpp: N = 3, 4).
template <int N>
void surface_pressure(const SurfaceNodes<N>& x, double p, ElementVector<N>& f, ElementMatrix<N>* dfdx);

/// The same load subtracted in place, as the element loop forms R_e = f_int − f_p and
/// K_e = K − ∂f_p/∂x (theory manual (6.3)): r −= f and, if K is given, K −= ∂f/∂x, with f and
/// ∂f/∂x those of surface_pressure; returns ‖f‖² (the element's term of the round-off yardstick).
/// No 3N × 3N load matrix is formed: ∂f_a/∂x_b is a cross-product matrix, subtracted entry by entry.
template <int N>
double subtract_surface_pressure(const SurfaceNodes<N>& x, double p, ElementVector<N>& r, ElementMatrix<N>* K);

/// How an enclosed volume is measured (see above).
struct VolumeMeasure {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  ///< p₀
  bool about_axis = false;
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();  ///< a (unit), if about_axis
};

/// V_e of the current element x and, if grad is given, ∂V_e/∂x (3N).
template <int N>
double enclosed_volume(const SurfaceNodes<N>& x, const VolumeMeasure& how, ElementVector<N>* grad);

}  // namespace tunica
