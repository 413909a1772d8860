#pragma once
// Frictionless penalty contact of a slave node against deformable master
// surfaces in the axisymmetric (r, z) meridian plane (theory manual §9.1, (9.5);
// balloon, plaque and artery of the paper's angioplasty example, §12.2). A kernel:
// positions in, energy, force and tangent out; the search is
// contact/contact_search.hpp, rigid tools contact/rigid_surface.hpp.
//
// Units: any consistent set (the decks use mm and N). Lengths [mm]; the penalty
// ε is a pressure per unit penetration [N/mm³]; the slave's tributary area A_s
// [mm²]; contact pressure p_c = ε⟨−g_N⟩ [N/mm²]; forces [N]; energy [N·mm].
//
// Penalty energy of one slave node s (Wriggers, Computational Contact
// Mechanics, 2nd ed., Springer 2006: the penalty method, and ch. 9, the 2-D
// node-to-segment discretization for large deformations):
//   Π = ½ ε ⟨−g_N⟩² A_s,   ⟨y⟩ = max(y, 0),
// the integral of ½ ε ⟨−g_N⟩² over the slave's tributary area, which the node
// represents (A_s = 2π R_s × its tributary reference length; the caller passes
// it, e.g. from slave_tributary_areas). The node is active iff g_N < 0. For a
// fixed active set and a fixed master feature every function below returns
//   f = ∂Π/∂x = ε A_s g_N ∂g_N/∂x,   K = ∂f/∂x = ε A_s (∂g_N/∂x ⊗ ∂g_N/∂x + g_N ∂²g_N/∂x²),
// exactly (zero when inactive). f has the sign of an internal force: it enters
// the residual as R = f_int + f − f_ext, and −f is the contact force on the nodes
// (on the slave: p_c A_s n, pushing it out along the master normal n).
//
// Node to segment (Wriggers 2006 ch. 9, 2-D, straight segment, frictionless).
// Slave x_s, master segment x_1 → x_2, element DOFs u = (u_s, u_1, u_2), 6 in the
// order (u_r, u_z) per node:
//   a = x_2 − x_1,  ℓ = |a|,  t = a/ℓ,  n = (t_z, −t_r)   (t turned clockwise),
//   ξ = (x_s − x_1)·t / ℓ              (closest point x_1 + ξ a of the line),
//   g = (x_s − x_1)·n                  (signed distance to the line),
//   g_N = g − c                        (c: the law's offset, e.g. half thicknesses),
//   N = (n, −(1−ξ) n, −ξ n),  T = (t, −(1−ξ) t, −ξ t),  D = (0, −n, n),
//   δg_N = N·δu,
//   δξ   = (T + (g/ℓ) D)·δu / ℓ,
//   Δδg_N = −(T ⊗ D + D ⊗ T)/ℓ − (g/ℓ²) D ⊗ D
// (the geometric terms: the rotation of the segment, δn = −t (n·δa)/ℓ, and the
// variation of the projection δξ). Hence
//   f = ε A_s g_N N,   K = ε A_s [N ⊗ N − (g_N/ℓ)(T ⊗ D + D ⊗ T) − (g_N g/ℓ²) D ⊗ D].
// The formulas hold for any ξ (they differentiate the distance to the segment's
// line); ξ ∉ [0, 1] means the node has slid off the segment, and the search
// (contact_search.hpp) hands it to the neighbouring segment or to the corner.
//
// Node to vertex (the corner region of the search, and rounded corners when
// c > 0). Slave x_s, master node x_v, DOFs u = (u_s, u_v), 4:
//   r = x_s − x_v,  d = |r|,  e = r/d,  g_N = σ d − c  (σ = ±1 the side, see the search),
//   G = σ (e, −e),  δg_N = G·δu,  Δδg_N = (σ/d) [[P, −P], [−P, P]],  P = I − e ⊗ e,
//   f = ε A_s g_N G,   K = ε A_s [G ⊗ G + g_N (σ/d) [[P, −P], [−P, P]]].
// At a segment end (ξ = 0 or 1) r = g n, so segment and vertex forms give the
// same energy and force: the energy is C¹ across the border of the corner region.
#include <Eigen/Dense>

#include "contact/contact_search.hpp"

namespace tunica {

using ContactVector6 = Eigen::Matrix<double, 6, 1>;
using ContactMatrix6 = Eigen::Matrix<double, 6, 6>;

/// The penalty law of a contact pair, theory manual (9.2): the contact pressure p(g_N) per reference
/// area, ε⟨−g_N⟩ for δ = 0; with the smoothing width δ > 0 the quadratic blend
///   p = ε (δ/2 − g_N)²/(2δ) for |g_N| < δ/2,  ε(−g_N) below, 0 above,
/// C¹ across the touch, equal to the plain law beyond a penetration of δ/2.
struct ContactLaw {
  double penalty = 0;    ///< ε > 0 [force/length³]: contact pressure per unit penetration
  double offset = 0;     ///< c ≥ 0 [length]: g_N = s − c (e.g. half the thicknesses of membrane mid-surfaces)
  double smoothing = 0;  ///< δ ≥ 0 [length]: width of the blend around g_N = 0

  /// Whether a node at gap g_N feels the surface: g_N < δ/2.
  bool touching(double gap) const { return gap < 0.5 * smoothing; }
  /// p(g_N) [force/length²].
  double pressure(double gap) const {
    const double h = 0.5 * smoothing;
    if (!(gap < h)) return 0;
    if (gap <= -h) return -penalty * gap;
    return penalty * (h - gap) * (h - gap) / (2 * smoothing);
  }
  /// dp/d(−g_N) [force/length³].
  double stiffness(double gap) const {
    const double h = 0.5 * smoothing;
    if (!(gap < h)) return 0;
    if (gap <= -h) return penalty;
    return penalty * (h - gap) / smoothing;
  }
  /// Π/A_s = ∫ p d(−g_N) [force/length].
  double energy(double gap) const {
    const double h = 0.5 * smoothing;
    if (!(gap < h)) return 0;
    if (gap <= -h) return 0.5 * penalty * gap * gap + penalty * smoothing * smoothing / 24;
    return penalty * (h - gap) * (h - gap) * (h - gap) / (6 * smoothing);
  }
};

/// The state of one contact node, for output.
struct ContactPoint {
  bool active = false;
  double gap = 0;       ///< g_N [length] (negative: penetration)
  double pressure = 0;  ///< p_c = p(g_N) (ε⟨−g_N⟩ without smoothing) [force/length²]
  double energy = 0;    ///< Π = A_s ∫ p d(−g_N) (½ ε ⟨−g_N⟩² A_s without smoothing) [force·length]
  double xi = 0;        ///< projection parameter on the master segment (0 for a cylinder)
  Eigen::Vector2d normal = Eigen::Vector2d::Zero();  ///< unit normal towards the slave's side; force on the slave = p_c A_s normal
};

/// Slave node x_s against the master segment x_1 → x_2 (both deformable), area A_s > 0.
/// Returns the state; f (6) and, if K is given, K (6×6) for u = (u_s, u_1, u_2).
/// Throws std::domain_error if the segment has zero length.
ContactPoint node_to_segment(const Eigen::Vector2d& xs, const Eigen::Vector2d& x1, const Eigen::Vector2d& x2,
                             double area, const ContactLaw& law, ContactVector6& f, ContactMatrix6* K);

/// Slave node x_s against the master node x_v from side σ = ±1 (see contact_search.hpp).
/// f (4) and, if K is given, K (4×4) for u = (u_s, u_v). Throws std::domain_error
/// if the node is active and d = 0 (the direction is undefined).
ContactPoint node_to_vertex(const Eigen::Vector2d& xs, const Eigen::Vector2d& xv, double side, double area,
                            const ContactLaw& law, Eigen::Vector4d& f, Eigen::Matrix4d* K);

/// The contact of slave x_s with the feature `where` of `chain` (from project_on_chain
/// at the same positions), as the 3-node element (slave, P_k, P_{k+1}), k = where.segment:
/// node_to_segment for a segment feature, node_to_vertex (vertex = node k+1, zero
/// rows for node k) for a vertex feature, nothing for none.
ContactPoint chain_contact(const Eigen::Vector2d& xs, const Eigen::Ref<const Eigen::Matrix2Xd>& chain,
                           const ChainProjection& where, double area, const ContactLaw& law, ContactVector6& f,
                           ContactMatrix6* K);

/// Tributary reference areas of the nodes of a slave chain (2×m, reference
/// positions (R, Z)): A_i = 2π R_i (L_{i−1} + L_i)/2 with L_j the reference length
/// of segment j (a missing neighbour counts 0) — the lumped (row-sum with R at
/// the node) area the node stands for. A node on the axis (R_i = 0, a pole) stands for its
/// consistent area instead, A_i = Σ 2π L_j R_other/6 (the weight a pressure load gives it), since
/// the lumped area is 0 there.
Eigen::VectorXd slave_tributary_areas(const Eigen::Ref<const Eigen::Matrix2Xd>& reference_chain);

}  // namespace tunica
