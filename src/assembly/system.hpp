#pragma once
// The discrete system of a model: DOF numbering with prescribed DOFs removed,
// the sparsity pattern of the free-DOF tangent computed once (from the node
// adjacency of the elements and of the deformable contact pairs, see
// contact_assembly.hpp), each element's scatter positions into it and the
// colouring, all generic; and the assembly of the residual R = f_int − f_ext
// (all DOFs, so reactions can be read) and of K = ∂R/∂u (free DOFs only) as the
// sum of the contributions: one BlockContribution per block of elements, built by
// its element type (contributions/element_type.hpp), the held DOFs of parts that
// enter later, and the contact pairs. System does not dispatch on the element kind: it asks the
// kind's registered type for its nodes and unknowns per node.
//
// K is assembled in the split storage of a TangentLayout (linalg/tangent_layout.hpp), built once
// with the pattern, with CHOLMOD's symbolic analysis: the lower triangle, from which CHOLMOD's
// tril(P K Pᵀ) is gathered without a transpose, and the upper triangle beside it only where the
// consumer reads it (TangentMatrix's `upper`: the symmetry test of `auto`, UMFPACK, the
// symmetrized tangent, volume control's bordered system). The full matrix is expanded from the
// two only for a consumer that needs it (assemble_full, TangentMatrix::expand).
//
// Parts that enter in a later step (Part::enter_step, Model::part_active): while a
// part is inactive its elements, the pressure loads on it and its contact pairs are
// skipped, and each free DOF of a node that only inactive parts use is held at its
// reference position by R_i = k_i u_i, K_ii = k_i, with k_i the diagonal of the part's
// tangent at the reference state (a stiffness of the right size for the linear solver;
// u_i stays exactly 0, so the part enters stress free in its deck geometry).
//
// Parallel assembly: the elements of each block are cut into runs of consecutive
// elements, coloured once (greedy: no two runs of one colour share a node), and each
// colour is one OpenMP loop over its runs, each run's elements in order on one thread
// (contributions/element_loop.hpp): results are identical bit for bit whatever the
// number of threads.
#include <Eigen/Sparse>
#include <array>
#include <memory>
#include <vector>

#include "assembly/contact_assembly.hpp"
#include "contributions/element_type.hpp"
#include "elements/axisym_solid.hpp"
#include "elements/membrane_point.hpp"
#include "linalg/sparse_matrix.hpp"
#include "linalg/tangent_matrix.hpp"
#include "model/model.hpp"

namespace tunica {

/// Current values of the boundary and load amplitudes.
struct LoadState {
  std::vector<double> boundary;  ///< per Model::boundaries
  std::vector<double> pressure;  ///< per Model::loads
  std::vector<double> volume;    ///< per Model::loads: enclosed volume at the last converged state
  int step = 0;                  ///< 0-based step these amplitudes belong to: decides which parts are active
};

class System {
public:
  explicit System(const Model& model);

  const Model& model() const { return model_; }
  int num_dofs() const { return model_.num_dofs(); }
  int num_free() const { return num_free_; }
  /// Equation number of a DOF, −1 if prescribed.
  int equation(int dof) const { return eq_[dof]; }
  const std::vector<int>& prescribed_dofs() const { return prescribed_; }

  /// Sets the prescribed DOFs of u to the boundary values of `loads`.
  void apply_boundary(const LoadState& loads, Eigen::VectorXd& u) const;
  /// Full residual R (num_dofs) and, if K is given, the free-DOF tangent in the split storage of
  /// layout() (K's upper triangle if K stores one; a K of another layout, or a general one, is
  /// replaced by a tangent with both triangles).
  /// `force_scale`, if given, receives a yardstick for round-off in R: sqrt(Σ_e ‖f_int,e‖² +
  /// ‖f_ext,e‖² + (‖K_e‖ L_e)²), the forces that cancel in R and, when K is assembled, the
  /// stiffness × element size that bounds round-off of stresses computed near zero strain.
  /// Contact pairs add each active slave node's penalty force and tangent (contact_assembly.hpp:
  /// rigid pairs on the slave's DOFs, deformable pairs on the slave's and the master segment's),
  /// and ‖f_c‖² + (‖K_c‖ |x|)² to the yardstick (the gap is a difference of coordinates);
  /// `active_contacts`, if given, receives the number of active slave nodes (all pairs), and
  /// `active_set` whether each slave node is active (pairs in order, nodes in pair order).
  void assemble(const Eigen::VectorXd& u, const LoadState& loads, Eigen::VectorXd& R, TangentMatrix* K,
                double* force_scale = nullptr, int* active_contacts = nullptr,
                std::vector<char>* active_set = nullptr) const;
  /// assemble() with the full free-DOF tangent K (both triangles, compressed columns, the pattern of
  /// pattern()), for a consumer that reads K entry by entry.
  void assemble_full(const Eigen::VectorXd& u, const LoadState& loads, Eigen::VectorXd& R, SparseMatrix& K,
                     double* force_scale = nullptr, int* active_contacts = nullptr,
                     std::vector<char>* active_set = nullptr) const;
  /// The first Newton correction from a stress-free state (theory manual §7.2, (7.6)–(7.8);
  /// solver/tangent_hooks.hpp):
  /// adds to K (free DOFs) the normal-tension stiffness K₀ (elements/start_tension.hpp) of every
  /// 3-D membrane element of an active part under pressure p, with the tension
  ///     T₀ = |p| / max(|H_e|, 1/L)
  /// (twice Laplace's p/2H; H_e the element's mean curvature, model/surface_curvature.hpp; L the
  /// diagonal of the part's bounding box, which caps T₀ on flat regions), and returns K₀ d
  /// (all DOFs; d over all DOFs, or empty for none).
  Eigen::VectorXd add_start_stiffness(const LoadState& loads, const Eigen::VectorXd& d, TangentMatrix& K) const;
  /// The metric of a step without pressure (theory manual §7.3, (7.14); solver/tangent_hooks.hpp):
  /// adds to K the normal-tension stiffness K₀ of (7.7) at the uniform tension θ T̄ on every membrane
  /// element of an active part, T̄ = c μ₀ H (c = 0.1, system.cpp) (μ₀ the material's shear modulus at rest,
  /// H the part's thickness), and returns K₀ d (all DOFs; d over all DOFs, or empty for none).
  Eigen::VectorXd add_slack_stiffness(double theta, int step, const Eigen::VectorXd& d, TangentMatrix& K) const;
  /// K += factor × the curvature part ε A_s g_N ∂²g_N/∂u² of every active contact element at u
  /// (ContactAssembly::add_curvature): factor −1 turns the contact's share of an assembled tangent
  /// into its Gauss–Newton part (theory manual (9.10)).
  void add_contact_curvature(const Eigen::VectorXd& u, const LoadState& loads, double factor, TangentMatrix& K) const;
  /// Contact state of every slave node of contact pair `c` at u in step `step` (0-based), in the
  /// pair's node order; inactive while the pair waits for one of its parts to enter.
  std::vector<ContactNodeState> contact_states(const Eigen::VectorXd& u, int c, int step) const;
  /// External force per unit pressure of load `l` at u (all DOFs): ∂f_ext/∂p.
  Eigen::VectorXd pressure_load(const Eigen::VectorXd& u, int l) const;
  /// Enclosed volume of the surface of load `l` at u (theory manual (6.6); axisymmetric:
  /// V = π ∫ r² dz along the meridian, (6.7), on a shell's Hermite curve (11.5)) and, if
  /// `grad` is given, ∂V/∂u (all DOFs).
  double volume(const Eigen::VectorXd& u, int l, Eigen::VectorXd* grad = nullptr) const;
  /// True if `loads` belong to an inverse step (Step::inverse; theory manual §13): assemble() then
  /// gives the inverse problem's R and K (BlockContribution::assemble_inverse; K is not symmetric),
  /// u moving the reference nodes X = x̂ + u, the deck's positions x̂ the imaged ones.
  bool inverse(const LoadState& loads) const {
    return loads.step >= 0 && loads.step < static_cast<int>(model_.steps.size()) &&
           model_.steps[loads.step].moves_reference();
  }
  /// A zero matrix with the tangent's pattern (both triangles).
  const SparseMatrix& pattern() const { return layout_->pattern(); }
  /// Where the tangent's entries are stored (linalg/tangent_layout.hpp).
  const std::shared_ptr<const TangentLayout>& layout() const { return layout_; }
  /// A zero tangent in layout()'s split storage, with the upper triangle if `upper`.
  TangentMatrix tangent(bool upper) const { return TangentMatrix(layout_, upper); }
  /// Gauss-point states of every element of a membrane part, block by block, element by element
  /// (empty for a solid part), at u in step `step` (0-based): in an inverse step the reference is
  /// X = x̂ + u and the current state the imaged x̂ (the stress in the imaged state).
  std::vector<MembranePoint> points(const Eigen::VectorXd& u, int part, int step = 0) const;
  /// Gauss-point states of a solid part, 4 per element, element by element (empty for a membrane part).
  std::vector<SolidPoint> solid_points(const Eigen::VectorXd& u, int part) const;
  /// Stored strain energy of a part at u, Σ_e Π_e (membranes: Σ_g Ŵ w_g; solids: the element
  /// energies of elements/axisym_solid.hpp, whatever the part's activity).
  double part_energy(const Eigen::VectorXd& u, int part) const;
  /// True if the free DOF `dof` is held at its reference position in step `step` (its node belongs
  /// only to parts that have not entered yet).
  bool held(int dof, int step) const { return step < dof_enter_[dof]; }

private:
  /// Pressure on each part: the sum of the loads acting on it, with their sides.
  std::vector<double> part_pressures(const LoadState& loads) const;
  /// Holds the free DOFs of nodes of inactive parts: R_i += k_i u_i, K_ii += k_i.
  void assemble_held(int step, const Eigen::VectorXd& u, Eigen::VectorXd& R, TangentMatrix* K) const;
  /// k_i of the held DOFs: the diagonal of the tangent at u = 0 of the parts that enter later.
  void compute_hold_stiffness();

  const Model& model_;
  int dpn_ = 2;
  std::vector<int> eq_;
  std::vector<int> prescribed_;
  int num_free_ = 0;
  std::shared_ptr<const TangentLayout> layout_;
  std::vector<std::vector<std::unique_ptr<BlockContribution>>> blocks_;  ///< per part, per block
  std::vector<double> extent_;              ///< per part: the diagonal of its reference bounding box
  std::vector<double> slack_tension_;       ///< per part: T̄ of (7.14), 0 for parts without a membrane material
  /// Per DOF: the step from which it is free to move (the lowest enter_step of the parts using its node; 0 if none).
  std::vector<int> dof_enter_;
  /// Free DOFs that may be held: DOF, code of K_ii (TangentLayout::entry), k_i.
  struct HeldDof {
    int dof = -1, pos = -1;
    double k = 1;
  };
  std::vector<HeldDof> held_;
  /// The contact pairs' contributions (built after the pattern, which holds their couplings).
  std::unique_ptr<ContactAssembly> contact_;
};

/// The length of the runs of consecutive elements colour_elements colours, for a block of `elements`.
int colour_run_length(int elements);
/// Greedy colouring of runs of consecutive elements (colour_run_length each, the last one shorter)
/// so that no two runs of a colour share a node: sets layout.order, run_start and colour_start
/// (BlockLayout), the runs colour by colour, ascending within a colour, each run's elements ascending.
void colour_elements(const ElementBlock& block, int num_nodes, BlockLayout& layout);

/// Gauss points per element of a block of a part (System::points order).
inline int points_per_element(const Part& part, ElementKind k) { return element_type(k).points_per_element(part); }

}  // namespace tunica
