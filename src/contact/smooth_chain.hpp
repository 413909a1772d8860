#pragma once
// A C¹-smooth master surface for deformable contact in the (r, z) meridian
// plane: the Catmull–Rom cubic through the master chain's nodes, and the
// penalty contact of a slave node against it (theory manual §9.3, (9.7)–(9.8)).
//
// Why. On a faceted master (node to segment, axisym_contact.hpp) the normal
// jumps at every master node. A flexible slave (a membrane balloon, ≈3 nodes per
// plaque facet) pressed hard onto it must turn its tension round each facet
// corner, so its load gathers on the few nodes next to the corners, and which
// nodes those are depends on the penalty: the nodal contact pressure scatters,
// and its maximum does not converge as ε grows. Smoothing the master surface
// removes the corners (Wriggers, Computational Contact Mechanics, 2nd ed. 2006,
// ch. 9, on smoothing the master surface; Wriggers, Krstulovic-Opara & Korelc,
// "Smooth C1-interpolations for two-dimensional frictional contact problems",
// IJNME 2001, with Bézier/Hermite interpolation of the master).
//
// Curve. Master chain P_0 … P_{m−1}; segment k (P_k → P_{k+1}, chord length ℓ_k)
// is the cubic Hermite curve
//   c(ξ) = h00 P_k + h10 d_k + h01 P_{k+1} + h11 d_{k+1},   ξ ∈ [0, 1],
//   h00 = 2ξ³−3ξ²+1, h10 = ξ³−2ξ²+ξ, h01 = −2ξ³+3ξ², h11 = ξ³−ξ²,
// with the chord-weighted nodal tangents (Catmull–Rom for even spacing)
//   d_k = ℓ_k (P_{k+1} − P_{k−1})/(ℓ_{k−1} + ℓ_k),   d_{k+1} = ℓ_k (P_{k+2} − P_k)/(ℓ_k + ℓ_{k+1}),
// so segment k depends on the window (P_{k−1}, P_k, P_{k+1}, P_{k+2}). Beyond
// the ends the window uses the reflected ghosts P_{−1} = 2P_0 − P_1 and
// P_m = 2P_{m−1} − P_{m−2} (the end tangent is the end chord). The curve passes
// through every node; both segments meeting at node j have tangents along
// P_{j+1} − P_{j−1} there, so the normal is continuous; a straight chain of
// nodes, however unevenly spaced, gives its straight line run monotonically
// (|d| = ℓ_k at both ends), so a flat master keeps the faceted gap and normal
// (the contact patch test). The curve departs from the chord by the sagitta
// O(ℓ² κ), the error of the faceted chain itself.
//
// Contact. Closest point ξ* of the slave x_s: F(ξ) = (x_s − c(ξ))·c′(ξ) = 0,
// found by Newton from the faceted search (contact_search.hpp), moving to the
// neighbouring segment when ξ leaves [0, 1] (beyond the chain's ends: no contact,
// except within kSmoothMasterEndTolerance of the end segment). Normal n = (c′_z, −c′_r)/|c′| (the
// chain's convention: t turned clockwise), gap g_N = (x_s − c(ξ*))·n − c_offset.
// Penalty energy Π = ½ ε ⟨−g_N⟩² A_s as for a faceted master; with
// y = (x_s, P_{k−1}, P_k, P_{k+1}, P_{k+2}) (10 unknowns)
//   f = ∂Π/∂y = ε A_s g_N ∂g_N/∂y,   K = ε A_s (∂g_N/∂y ⊗ ∂g_N/∂y + g_N ∂²g_N/∂y²),
// where the derivatives of g_N include those of ξ*(y): they are taken exactly
// by second-order forward differentiation (core/jet.hpp) of one Newton step of
// F = 0 started at the converged ξ*. That step makes ξ*'s value and gradient
// exact (implicit function theorem), and the Hessian of g_N needs no more:
// ∂g_N/∂ξ = (x − c)·n′ = 0 at the foot (x − c ∥ n ⊥ n′), so the term with
// ∂²ξ*/∂y² drops out. The state (gap, pressure, energy) is taken from the same
// jet, so energy, force and tangent agree.
#include <Eigen/Dense>
#include <array>

#include "contact/axisym_contact.hpp"
#include "contact/contact_search.hpp"

namespace tunica {

/// The end tolerance τ of a smooth master: a slave node whose foot point lies beyond an end of the
/// chain by at most this fraction of the end segment (on the cubic's continuation) is still in
/// contact with it, if that shift is at most half its distance and it is not more than τ end
/// segments behind the surface (project_on_smooth_chain). Two bodies ending in one plane z = const (both held there)
/// keep their end nodes in contact although the master's end tangent tilts as it deforms: a node
/// at distance s from the master has its foot shifted by s·sin(tilt), far more than round-off.
constexpr double kSmoothMasterEndTolerance = 0.5;

using ContactVector10 = Eigen::Matrix<double, 10, 1>;
using ContactMatrix10 = Eigen::Matrix<double, 10, 10>;

/// The window of segment k of an m-node chain: the chain indices of (P_{k−1}, P_k, P_{k+1}, P_{k+2}),
/// −1 where the window runs past an end and a reflected ghost stands in.
std::array<int, 4> smooth_window(int k, int m);

/// Where a point stands with respect to the smooth master curve.
struct SmoothProjection {
  bool found = false;   ///< false: beyond an end of the chain (no side there, no contact)
  int segment = -1;     ///< segment k of the foot point
  double xi = 0;        ///< ξ* on segment k
  double signed_distance = 0;  ///< (x − c(ξ*))·n [length]
  Eigen::Vector2d normal = Eigen::Vector2d::Zero();
};

/// The curve point c(ξ) of segment k of `chain` (2×m, m ≥ 2).
Eigen::Vector2d smooth_point(const Eigen::Ref<const Eigen::Matrix2Xd>& chain, int k, double xi);

/// Closest point of x on the smooth curve through `chain`, starting from the faceted search's
/// result `start` (project_on_chain, called with the same end tolerance). Beyond an end of the
/// chain the point is not found unless its foot lies within `end_tolerance` (fraction of the end
/// segment) of the end, shifted along the tangent by at most half its distance |s|, and the
/// point is at most `end_tolerance` end segments behind the surface (s ≥ −τℓ).
SmoothProjection project_on_smooth_chain(const Eigen::Vector2d& x, const Eigen::Ref<const Eigen::Matrix2Xd>& chain,
                                         const ChainProjection& start, double end_tolerance);

/// Slave x_s against segment k of the smooth curve at its foot point ξ* (from
/// project_on_smooth_chain), tributary area A_s > 0. Returns the state; f (10) and, if K is given,
/// K (10×10) for y = (x_s, window nodes of smooth_window(k, m)); rows of ghost slots are zero.
ContactPoint smooth_contact(const Eigen::Vector2d& xs, const Eigen::Ref<const Eigen::Matrix2Xd>& chain, int k,
                            double xi, double area, const ContactLaw& law, ContactVector10& f, ContactMatrix10* K);

}  // namespace tunica
