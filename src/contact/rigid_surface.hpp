#pragma once
// Slave node against a rigid tool in the (r, z) meridian plane (theory manual §9,
// (9.1)–(9.4); the catheter that holds the balloon, §12.2). Same penalty law and conventions as
// axisym_contact.hpp: Π = ½ ε ⟨−g_N⟩² A_s, f = ∂Π/∂x_s (2), K = ∂f/∂x_s (2×2),
// exact for a fixed active set and a fixed feature; the tool has no DOFs.
//
// Cylinder r = R_c (a line parallel to the axis, unbounded in z), the slave
// kept outside (σ = +1) or inside (σ = −1):
//   g_N = σ (r_s − R_c) − c,   n = σ e_r,   f = ε A_s g_N n,   K = ε A_s n ⊗ n.
//
// Polyline: an open chain of reference points P_i (columns (r, z)) moved as a
// rigid body by a prescribed displacement d: current points P_i + d. The slave is
// projected with the chain search (contact_search.hpp: nearest segment or
// corner, normal n = t turned clockwise, so order the points to put the slave's
// side on the right of the direction of travel), and the deformable kernels of
// axisym_contact.hpp are evaluated with the master nodes held: f and K are the
// slave rows and columns. On a segment ∂²g_N/∂x_s² = 0, so K = ε A_s n ⊗ n; in
// the region of a corner K = ε A_s [e ⊗ e + g_N (σ/d)(I − e ⊗ e)].
// A body of revolution (a catheter tip) is the open meridian profile from the
// axis back to the axis; beyond the chain's ends there is no contact.
#include <Eigen/Dense>

#include "contact/axisym_contact.hpp"
#include "contact/contact_search.hpp"

namespace tunica {

enum class CylinderSide {
  outside,  ///< the slave stays at r ≥ R_c (e.g. a balloon on a catheter)
  inside,   ///< the slave stays at r ≤ R_c (e.g. a rigid tube around the artery)
};

/// The rigid cylinder r = R_c [length].
struct RigidCylinder {
  double radius = 0;
  CylinderSide side = CylinderSide::outside;
};

/// A rigid open polyline: reference points (2×m, m ≥ 2) and a prescribed rigid
/// translation [length].
struct RigidPolyline {
  Eigen::Matrix2Xd points;
  Eigen::Vector2d displacement = Eigen::Vector2d::Zero();

  /// Current points P_i + d.
  Eigen::Matrix2Xd current() const { return points.colwise() + displacement; }
};

/// Slave node x_s (area A_s) against a rigid cylinder: state, f (2) and, if K is given, K (2×2).
ContactPoint rigid_cylinder_contact(const RigidCylinder& cylinder, const Eigen::Vector2d& xs, double area,
                                    const ContactLaw& law, Eigen::Vector2d& f, Eigen::Matrix2d* K);

/// Slave node x_s (area A_s) against a rigid polyline: state, f (2) and, if K is
/// given, K (2×2); `where`, if given, receives the projection (segment, ξ, corner).
ContactPoint rigid_polyline_contact(const RigidPolyline& tool, const Eigen::Vector2d& xs, double area,
                                    const ContactLaw& law, Eigen::Vector2d& f, Eigen::Matrix2d* K,
                                    ChainProjection* where = nullptr);

}  // namespace tunica
