#pragma once
// Closest-point search of slave nodes on a master chain (theory manual §9, §9.1:
// balloon, plaque and artery surfaces in the (r, z) meridian plane). Geometry only: no
// energy, no penalty; axisym_contact.hpp evaluates the contact at the result.
//
// Master chain: an ordered, open polyline of m ≥ 2 nodes P_0 … P_{m−1} (current
// positions, columns (r, z)); segment k joins P_k → P_{k+1}. Its unit tangent
// and normal are
//   t_k = (P_{k+1} − P_k)/ℓ_k,   n_k = (t_z, −t_r)   (t turned clockwise),
// the same convention as the follower pressure (loads/axisym_pressure.hpp): a
// chain running in +z has its normal in +r. The normal points to the side the
// slave must stay on, so the caller orders the chain accordingly: the lumen of
// the plaque seen by the balloon (slave inside, at smaller r) runs in −z; an
// outer surface seen by a slave outside it runs in +z.
//
// Closest point (deterministic, no memory of earlier states):
//   for every segment k: ξ_k = (x − P_k)·(P_{k+1} − P_k)/ℓ_k², the closest point
//   P_k + clamp(ξ_k, 0, 1)(P_{k+1} − P_k) (exactly P_k or P_{k+1} when clamped)
//   and its distance d_k; choose k* = argmin d_k, ties to the lowest k.
// The feature of the chain nearest to x is then
//   segment  if ξ_{k*} ∈ [0, 1]: signed distance s = (x − P_k)·n_k (the line gap);
//   vertex   if ξ_{k*} ∉ [0, 1] at an interior node v (x lies in the fan between
//            the normals of segments v−1 and v, and projects onto neither):
//            s = σ |x − P_v|, σ = sign((x − P_v)·(n_{v−1} + n_v)); σ = +1 at a
//            corner convex towards the slave side (x outside, never in contact
//            unless an offset rounds the corner), σ = −1 at a concave corner
//            (x has penetrated into the corner);
//   none     if ξ_{k*} ∉ [0, 1] at an end node of the chain (x lies beyond the
//            chain's end: the chain has no side there, never in contact) —
//            except within the caller's end tolerance τ ≥ 0: ξ ∈ [−τ, 0) on the
//            first segment or (1, 1 + τ] on the last counts as that segment (two
//            bodies ending in the same plane z = const, both held there, keep
//            their end nodes in contact whatever the round-off in ξ; τ = 0: none).
// s is the signed distance of x to the chain (positive on the normal side). It
// is continuous in x, and so is its gradient across the segment/vertex borders
// (there x − P_v = s n); the gradient jumps only where two segments are equally
// near (a penetrated node on the bisector of a concave corner), as in any
// node-to-segment method (Wriggers, Computational Contact Mechanics, 2nd ed.
// 2006, ch. 9). The gap is g_N = s − c with the caller's offset c (contact_law);
// the node is active iff g_N < 0 — at the current positions, with no hysteresis,
// so the active set is a function of the configuration alone. Large sliding is
// handled by searching afresh in every configuration: a node whose ξ leaves
// [0, 1] is handed to the neighbouring segment or to the corner between them.
//
// Cost: a linear scan, O(m) per slave node, O(S·m) for S nodes; a segment whose
// bounding box lies farther than the best distance found so far (or than the
// search radius) is rejected after a few comparisons, before its projection.
// For the angioplasty model (≈100 balloon nodes against ≈50–500 segments) that
// is ≤ 5·10⁴ box tests per search, negligible next to the element assembly.
// A node that has passed through a thin master body comes out on the near side
// of whatever is nearest: the search assumes penetrations smaller than the
// master's thickness and than half the distance between facing surfaces.
#include <Eigen/Dense>
#include <limits>
#include <vector>

namespace tunica {

/// The end tolerance τ for deformable master chains: a slave node beyond an end by at most this
/// fraction of the end segment still projects onto it (bodies ending in one plane z = const).
constexpr double kMasterEndTolerance = 1e-9;

/// Which feature of a master chain is nearest to a point.
enum class ChainFeature {
  none,     ///< nothing within the search radius, or beyond an end of the chain
  segment,  ///< the interior of a segment (ξ ∈ [0, 1])
  vertex,   ///< an interior node of the chain (the fan between two segments)
};

/// Where a point stands with respect to a master chain.
struct ChainProjection {
  ChainFeature feature = ChainFeature::none;
  /// The segment k (nodes k, k+1) of the contact element (slave, P_k, P_{k+1}):
  /// the nearest segment; for a vertex feature the segment that ends at the
  /// vertex (so the vertex is node k+1). −1 if feature is none.
  int segment = -1;
  int vertex = -1;  ///< the node index of a vertex feature, else −1
  double xi = 0;    ///< projection parameter ξ on `segment` (not clamped)
  double distance = std::numeric_limits<double>::infinity();  ///< |x − closest point| [length]
  double signed_distance = std::numeric_limits<double>::infinity();  ///< s: + on the normal side [length]

  /// The gap g_N = s − offset [length].
  double gap(double offset = 0) const { return signed_distance - offset; }
  /// The activation rule: a feature was found and g_N < 0.
  bool active(double offset = 0) const { return feature != ChainFeature::none && gap(offset) < 0; }
};

/// The unit normal n = (t_z, −t_r) of the segment a → b. Throws std::domain_error
/// if the segment has zero length.
Eigen::Vector2d segment_normal(const Eigen::Vector2d& a, const Eigen::Vector2d& b);

/// The feature of `chain` (2×m, m ≥ 2, columns (r, z)) nearest to x, within
/// `search_radius` (features farther away are ignored). Throws
/// std::invalid_argument if m < 2, std::domain_error if a segment has zero length.
/// `end_tolerance` τ: see the header comment (the ends of the chain).
ChainProjection project_on_chain(const Eigen::Vector2d& x, const Eigen::Ref<const Eigen::Matrix2Xd>& chain,
                                 double search_radius = std::numeric_limits<double>::infinity(),
                                 double end_tolerance = 0);

/// project_on_chain for every column of `slaves` (2×S): the search for a whole
/// slave surface, O(S·m).
std::vector<ChainProjection> search_chain(const Eigen::Ref<const Eigen::Matrix2Xd>& slaves,
                                          const Eigen::Ref<const Eigen::Matrix2Xd>& chain,
                                          double search_radius = std::numeric_limits<double>::infinity());

}  // namespace tunica
