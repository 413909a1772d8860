#pragma once
// Contact contributions to the residual and tangent of a System (axisymmetric
// models; theory manual §9, (9.2)–(9.5)): each contact pair, node by node, serially in pair
// and slave-node order after the elements, so the sums are deterministic.
//
// Rigid pair: the slave node's force f (2) and 2×2 tangent (rigid_surface.hpp),
// on the slave's DOFs only — entries the element pattern already holds.
//
// Deformable pair, faceted master: the nearest feature of the current master
// chain (project_on_chain, contact_search.hpp) makes a 3-node contact element
// (slave, P_k, P_{k+1}); chain_contact (axisym_contact.hpp: node to segment,
// f = ε A_s g_N N, K = ε A_s [N⊗N − (g_N/ℓ)(T⊗D + D⊗T) − (g_N g/ℓ²) D⊗D]; node
// to vertex in a corner region) gives f (6) and K (6×6). Smooth master
// (default): the closest point on the Catmull–Rom curve (smooth_chain.hpp)
// makes a 5-node element (slave, P_{k−1} … P_{k+2}; ghost slots at the chain's
// ends have no DOFs) with f (10) and K (10×10). Either is scattered over the
// nodes' free DOFs (prescribed DOFs: R gets every row, as the reactions; K
// only free rows and columns, as for the elements).
//
// Sparsity: the pattern is fixed at set-up but the segment a slave node touches
// changes as it slides, so the pattern couples every slave node with every
// master node of the pair (S×M 2×2 blocks, both ways) and master nodes up to
// one (faceted) or three (smooth) apart. Cost: 8 S·M extra nonzeros (e.g. 100
// balloon nodes against 500 plaque nodes: 4·10⁵ entries, 3 MB, and the fill of
// a dense S×M coupling in the factorization) — meant for axisymmetric models of
// ≤ 10³ contact nodes.
#include <Eigen/Dense>
#include <array>
#include <vector>

#include "contact/axisym_contact.hpp"
#include "contact/smooth_chain.hpp"
#include "linalg/tangent_matrix.hpp"
#include "model/model.hpp"

namespace tunica {

/// The contact state of one slave node of a contact pair (Model::contacts).
struct ContactNodeState {
  int node = -1;
  ContactPoint point;    ///< gap, ε⟨−g_N⟩ (per reference area), normal, ...
  /// Normal force ε⟨−g_N⟩ A_s on the node (whole circumference); a two-pass pair's adds the reverse
  /// pass's normal force on the node as its master (theory manual §9.1, (9.9)).
  double force = 0;
  double pressure = 0;   ///< contact pressure on the current tributary area: force / a_s
  int master_segment = -1;  ///< deformable pairs: the segment k of the contact element (slave, P_k, P_{k+1}), else −1
};

class ContactAssembly {
public:
  /// Adds the node couplings of the deformable pairs' contact elements to `adjacent` (per node,
  /// its coupled nodes, unsorted): every slave with every master node, consecutive master nodes.
  static void add_couplings(const Model& m, std::vector<std::vector<int>>& adjacent);

  /// Codes of the rigid pairs' slave blocks in `layout` (TangentLayout::entry; equation numbers
  /// `eq`, −1: prescribed). Throws std::logic_error if the pattern lacks an entry.
  ContactAssembly(const Model& m, const std::vector<int>& eq, const TangentLayout& layout);

  /// R += f and, if K is given (a split tangent of the layout), K += ∂f/∂u for every active slave node;
  /// scale2 += ‖f‖² + (‖K_c‖ |x|)² (round-off yardstick: the gap is a difference of coordinates);
  /// active += the number of active slave nodes; `active_set`, if given, is set to whether each
  /// slave node (pairs in order, nodes in pair order) is active.
  /// Pairs touching a part that has not entered by `step` (0-based, Model::part_active) are skipped
  /// (their nodes inactive).
  void assemble(const Eigen::VectorXd& u, int step, Eigen::VectorXd& R, TangentMatrix* K, double& scale2,
                int& active, std::vector<char>* active_set = nullptr) const;
  /// K += factor · ε A_s g_N ∂²g_N/∂u² for every active slave node at u: the curvature part of each
  /// contact element's tangent (theory manual (9.3), (9.10)), the element's K less its Gauss–Newton
  /// part ε A_s ∂g_N/∂u ⊗ ∂g_N/∂u = f⊗f/(ε A_s g_N²). With factor −1 it leaves the Gauss–Newton
  /// tangent of the contact, positive semidefinite whatever the penetration.
  void add_curvature(const Eigen::VectorXd& u, int step, double factor, TangentMatrix& K) const;
  /// Whether pair `c` takes part in step `step`: every part holding one of its slave or master
  /// nodes has entered.
  bool pair_active(int c, int step) const { return step >= pair_enter_[c]; }

  /// Contact state of every slave node of pair `c` at u, in the pair's node order.
  /// Every slave node of pair c at u in step `step` (0-based); a pair waiting for a part to enter
  /// reports its nodes inactive, as the assembly treats it. A two-pass pair (ContactPair::reverse)
  /// reports the whole contact on its slave's nodes: `point` is its own pass's, `force` and
  /// `pressure` both passes'.
  std::vector<ContactNodeState> states(const Eigen::VectorXd& u, int c, int step) const;

private:
  /// `flags`, if given: one per slave node of pair c, set to 1 for the active ones.
  /// `curvature` ≠ 0: only factor `curvature` times the curvature part of each element goes to K (R,
  /// scale2, active and flags untouched).
  void assemble_rigid(int c, const Eigen::VectorXd& u, Eigen::VectorXd& R, TangentMatrix* K, double& scale2,
                      int& active, char* flags, double curvature) const;
  void assemble_deformable(int c, const Eigen::VectorXd& u, Eigen::VectorXd& R, TangentMatrix* K, double& scale2,
                           int& active, char* flags, double curvature) const;
  /// K += Ke over the free DOFs of a contact element's nodes (slave, up to four master nodes; −1: none).
  void scatter(const std::array<int, 5>& nodes, const ContactMatrix10& Ke, TangentMatrix& K) const;
  /// Current positions of a chain of nodes (columns (r, z)).
  Eigen::Matrix2Xd current_chain(const std::vector<int>& nodes, const Eigen::VectorXd& u) const;

  const Model& model_;
  std::vector<int> eq_;
  /// Per rigid pair (empty for deformable ones), per slave node: the codes of its 2×2 block
  /// (rr, rz, zr, zz) (TangentLayout::entry; −1: not free-free).
  std::vector<std::vector<std::array<int, 4>>> rigid_pos_;
  /// Per pair: the step from which it is active (the latest enter_step of the parts it touches).
  std::vector<int> pair_enter_;
};

}  // namespace tunica
