#pragma once
// The element interface (docs/architecture.md, "Add an element"). An element type
// declares what the generic assembly needs of a kind of element — its nodes, its
// unknowns per node, its Gauss points, its VTK cell — and builds, for one block of
// a part, the BlockContribution that computes the block's local residuals and
// tangents, follower pressure, enclosed volume, start stiffness, Gauss-point states
// and energy. System (assembly/system.hpp) numbers the DOFs, builds the sparsity
// pattern, colours the elements and computes the scatter positions once, generically,
// and hands each block its BlockLayout; it never looks at the element kind.
//
// Element types register themselves by kind and name (register_element_type), as
// materials do; a kind is implemented by a kernel (contributions/element_loop.hpp)
// in one file of this folder.
#include <algorithm>
#include <cmath>
#include <Eigen/Dense>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "elements/axisym_solid.hpp"
#include "elements/membrane_point.hpp"
#include "linalg/tangent_matrix.hpp"
#include "model/model.hpp"

namespace tunica {

/// What System computes once for a block, generically: the scatter codes and the colouring.
struct BlockLayout {
  /// Per element, (n·d)² codes, row by row: where K_e(a, b) is added, TangentLayout::entry of
  /// (row of a, row of b) (linalg/tangent_layout.hpp: an index into the split storage, its lower
  /// triangle first; −1: not free-free).
  std::vector<int> scatter;
  int slots = 0;  ///< the tangent's slots S (TangentLayout::slots): codes from S are the upper triangle's
  /// The colouring: runs of consecutive elements, no two runs of a colour sharing a node, so that the
  /// runs of a colour can be assembled in parallel and each run's elements in order, one after the other.
  std::vector<int> order;         ///< element indices, run by run, the runs colour by colour
  std::vector<int> run_start;     ///< run k is order[run_start[k] … run_start[k+1])
  std::vector<int> colour_start;  ///< colour c is runs colour_start[c] … colour_start[c+1] − 1
};

/// Everything a block contribution is built from.
struct BlockContext {
  const Model& model;
  const Part& part;
  const ElementBlock& block;
  int first_element = 0;        ///< index within the part of the block's first element
  BlockLayout layout;
  std::vector<double> curvature;  ///< membranes: per element, the mean curvature H_e (model/surface_curvature.hpp, meridian_curvature.hpp)
};

/// The tension T₀,e of the normal-tension stiffness K₀ (theory manual (7.7)) on an element of mean
/// curvature H_e: Laplace's estimate |p| / max(|H_e|, cap) (7.8) for a pressure (−|p| gives −K₀,
/// the inverse problem's (13.8)), or, when `uniform` is not 0, that tension on every element (the
/// slack step's metric, (7.14)).
struct StartTension {
  double abs_pressure = 0;
  double cap = 0;
  double uniform = 0;
  double at(double mean_curvature) const {
    return uniform != 0 ? uniform : abs_pressure / std::max(std::abs(mean_curvature), cap);
  }
};

/// The contributions of one block of elements to R, K and the outputs. Element DOFs are
/// node-major: unknown a of an element is unknown a % d of its node a / d (d unknowns per node).
class BlockContribution {
public:
  virtual ~BlockContribution() = default;
  /// R += f_int − f_p, K += K_int − ∂f_p/∂u (free DOFs, through the layout's scatter positions) with
  /// the follower pressure `pressure` on the elements' surface (theory manual §6); returns the
  /// round-off yardstick Σ_e ‖f_int,e‖² + ‖f_p,e‖² (+ ‖K_e‖² L_e² when K is assembled), summed in
  /// element order whatever the number of threads, into scale2.
  virtual void assemble(const Eigen::VectorXd& u, double pressure, Eigen::VectorXd& R, TangentMatrix* K,
                        double& scale2) const = 0;
  /// The inverse problem's R and K (theory manual §13): the unknowns u move the reference nodes,
  /// X = x̂ + u, the imaged nodes x̂ being the model's (deck) positions; R += f_int(X, x̂) − f_p(x̂),
  /// K += ∂f_int/∂X (not symmetric; no load stiffness: the follower pressure acts on the known
  /// imaged surface); scale2 as assemble(). std::logic_error for a kind without an inverse element
  /// (ElementType::inverse false; the deck reader refuses it first).
  virtual void assemble_inverse(const Eigen::VectorXd& u, double pressure, Eigen::VectorXd& R, TangentMatrix* K,
                                double& scale2) const;
  /// The Gauss-point states of the inverse problem at u: reference X = x̂ + u, current x̂ (the stress
  /// in the imaged state); none by default.
  virtual void inverse_points(const Eigen::VectorXd& u, std::vector<MembranePoint>& out) const;
  /// g += ∂f_ext/∂p, the external force per unit pressure of sign `sign` (all DOFs).
  virtual void pressure_load(const Eigen::VectorXd& u, double sign, Eigen::VectorXd& g) const = 0;
  /// V += V_e element by element, the enclosed volume of the elements' surface (theory manual
  /// (6.6), (6.7)), and grad += ∂V/∂u if given.
  virtual void add_volume(const Eigen::VectorXd& u, const VolumeMeasure& how, double& V, Eigen::VectorXd* grad) const = 0;
  /// diag += the diagonal of the tangent at the reference state u = 0 (all DOFs).
  virtual void reference_diagonal(Eigen::VectorXd& diag) const = 0;
  /// The normal-tension stiffness K₀ (theory manual (7.6)–(7.7)) at the tension `t` gives each
  /// element: K += K₀ and Kd += K₀ d (d all DOFs, or empty). None by default.
  virtual void start_stiffness(const StartTension& t, const Eigen::VectorXd& d, Eigen::VectorXd& Kd,
                               TangentMatrix& K) const;
  /// Appends the Gauss-point states of every element (membranes and shells; none for solids).
  virtual void membrane_points(const Eigen::VectorXd& u, std::vector<MembranePoint>& out) const;
  /// Appends the Gauss-point states of every element (solids; none for membranes).
  virtual void solid_points(const Eigen::VectorXd& u, std::vector<SolidPoint>& out) const;
  /// energy += the stored strain energy, element by element (solids: Π_e; membranes and shells:
  /// Ŵ w_g point by point).
  virtual void add_energy(const Eigen::VectorXd& u, double& energy) const = 0;
};

/// A kind of element, registered by kind and name.
struct ElementType {
  ElementKind kind{};
  std::string name;            ///< as in messages and docs
  int nodes = 0;               ///< nodes per element
  int unknowns_per_node = 0;   ///< element unknowns per node (node-major element DOFs)
  bool solid = false;          ///< Gauss-point states are SolidPoint (else MembranePoint)
  bool pressure = false;       ///< carries follower pressure and encloses a volume (pressure loads may act on it)
  bool inverse = false;        ///< has the inverse element (BlockContribution::assemble_inverse; theory manual §13)
  std::uint8_t vtk_cell = 0;   ///< VTK cell type (vtkCellType.h) as its nodes lie
  std::uint8_t vtk_revolved_cell = 0;  ///< axisymmetric: the cell it sweeps when revolved; 0 for 3-D kinds
  /// Gauss points per element of a part (System::points order).
  std::function<int(const Part&)> points_per_element;
  /// The block's contribution. Throws BadElement (elements/membrane3d.hpp) naming the element if
  /// its reference data cannot be built.
  std::function<std::unique_ptr<BlockContribution>(BlockContext)> make;
  /// Checks the block's reference geometry as make() would, without a layout (reading a deck);
  /// empty if the kind has no reference data to check.
  std::function<void(const Model&, const Part&, const ElementBlock&, int first_element)> check;
};

/// Registers an element type (at static initialisation); std::logic_error if its kind is taken.
void register_element_type(ElementType type);
/// The element type of a kind; std::logic_error for a kind without one.
const ElementType& element_type(ElementKind kind);
/// Every registered element type, by kind.
std::vector<const ElementType*> element_types();

/// The VTK cell type of an element as its nodes lie; std::logic_error for a kind without one.
std::uint8_t vtk_cell_type(ElementKind k);
/// The VTK cell type an axisymmetric element sweeps when revolved; std::logic_error for the 3-D kinds.
std::uint8_t vtk_revolved_cell_type(ElementKind k);

}  // namespace tunica
