#pragma once
// The analysis model built from a deck: nodes, parts (element type, material,
// thickness, connectivity), node sets, prescribed displacements, loads, steps
// and output requests. A model is either axisymmetric (two DOFs per node,
// (u_r, u_z); positions (r, z, 0)) or three-dimensional (three DOFs per node,
// (u_x, u_y, u_z)).
//
// DOF map. DOF c of node n is d = dofs_per_node() n + c for the positions. The
// nodes of axisymmetric shell parts (elements/axisym_shell.hpp) carry two more
// unknowns, the changes of the meridian slope (u′_r, u′_z) = x′ − X′ (′ = ∂/∂S,
// reference arc length), numbered after all position DOFs:
// d = slope_dof[n] + c − 2 for c = 2 (slope_r), 3 (slope_z). Code that reads
// positions keeps d = 2n + c; code that handles every unknown of a node uses
// node_dof(n, c) for c < node_dof_count(n).
#include <Eigen/Dense>
#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "contact/rigid_surface.hpp"
#include "core/errors.hpp"
#include "params/units.hpp"
#include "loads/surface_pressure.hpp"
#include "elements/axisym_solid.hpp"
#include "materials/membrane_material.hpp"
#include "materials/solid_material.hpp"
#include "model/solver_settings.hpp"

namespace tunica {

enum class Geometry { axisymmetric, three_d };

/// Element kinds: the 2-node axisymmetric membrane, the 3-node triangle and the 4-node quadrilateral
/// membrane, and the 4-node axisymmetric solid (a quadrilateral in the (r, z) plane, elements/axisym_solid.hpp).
/// shell2: the 2-node axisymmetric Kirchhoff–Love shell (elements/axisym_shell.hpp), 4 unknowns per node.
/// tri6: the 6-node quadratic triangle membrane (elements/tri6_shape.hpp; corners, then the mid-edge
/// nodes of edges 0–1, 1–2, 2–0, as Gmsh's type 9).
enum class ElementKind { axisym2, tri3, quad4, solid4, shell2, tri6 };
// The switches below have no default: a kind left out is a compiler warning (-Wswitch), and the
// element registry checks its declaration against nodes_per_element (contributions/element_type.cpp).
constexpr int nodes_per_element(ElementKind k) {
  switch (k) {
    case ElementKind::axisym2:
    case ElementKind::shell2: return 2;
    case ElementKind::tri3: return 3;
    case ElementKind::quad4:
    case ElementKind::solid4: return 4;
    case ElementKind::tri6: return 6;
  }
  return 0;
}
/// True for the 3-D membrane kinds: surface elements in space.
constexpr bool is_surface_kind(ElementKind k) {
  switch (k) {
    case ElementKind::tri3:
    case ElementKind::quad4:
    case ElementKind::tri6: return true;
    case ElementKind::axisym2:
    case ElementKind::shell2:
    case ElementKind::solid4: return false;
  }
  return false;
}
/// The corner nodes of an element, the first ones of its node order: the vertices of its
/// straight-sided shape (a higher-order element lists its other nodes after them).
constexpr int corner_nodes(ElementKind k) {
  switch (k) {
    case ElementKind::tri6: return 3;
    case ElementKind::axisym2:
    case ElementKind::shell2:
    case ElementKind::tri3:
    case ElementKind::quad4:
    case ElementKind::solid4: return nodes_per_element(k);
  }
  return 0;
}
/// Elements of one kind in a part: connectivity, element e = nodes [n e, n (e + 1)).
struct ElementBlock {
  ElementKind kind = ElementKind::axisym2;
  std::vector<int> nodes;                  ///< global node numbers, nodes_per_element(kind) per element
  std::vector<Eigen::Vector3d> direction;  ///< per-element direction 1 from the mesh file (frame `mesh`), else empty
  std::vector<long> tags;                  ///< per-element tags as written in the mesh file, else empty
  std::string file;                        ///< the mesh file the elements come from, else empty
  int size() const { return static_cast<int>(nodes.size()) / nodes_per_element(kind); }
  const int* element(int e) const { return nodes.data() + nodes_per_element(kind) * e; }
};

/// How a 3-D part's material direction 1 is chosen at each Gauss point (projected on the tangent plane).
struct FrameRule {
  enum class Type { edge, cylindrical, vector, mesh } type = Type::edge;
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();   ///< cylindrical: axis direction (unit)
  Eigen::Vector3d point = Eigen::Vector3d::Zero();   ///< cylindrical: a point on the axis
  Eigen::Vector3d vector = Eigen::Vector3d::UnitX(); ///< vector: direction 1 before projection
  std::string view;                                  ///< mesh: the element-data view name
};

struct Part {
  std::string name;
  std::string element;                     ///< element type name
  const MembraneMaterial* material = nullptr;  ///< membrane parts (null for solid parts)
  const SolidMaterial* solid_material = nullptr;  ///< solid parts (element `axisymmetric_solid`)
  SolidFormulation formulation = SolidFormulation::mean_dilatation;  ///< solid parts
  std::string material_name;
  double thickness = 0;                    ///< reference thickness H (membranes and shells); with
                                           ///< imaged_thickness, the wall thickness h of the imaged state
  /// `imaged_thickness`: `thickness` is h, measured in the inverse step's imaged state, and each Gauss
  /// point's reference thickness is H = h λ₁λ₂ (theory manual (13.12)), unknown until the inverse step
  /// has converged.
  bool imaged_thickness = false;
  /// With imaged_thickness: h at each Gauss point (element-major, in block order, as System::points)
  /// in place of the uniform `thickness`, e.g. a measured thickness map; empty: h = `thickness`.
  /// Not a deck key.
  std::vector<double> imaged_point_thickness;
  /// The reference thickness H of each Gauss point (element-major, in block order, as System::points),
  /// set when the reference of an imaged_thickness part is adopted after its inverse step ((13.14));
  /// empty: H = `thickness` everywhere.
  std::vector<double> point_thickness;
  /// The prestretch P of each membrane Gauss point (element-major, in block order, as System::points),
  /// set by a prestress step (theory manual §13.2): P maps the point's stress-free tangent plane onto
  /// the mesh's, in the coordinates of the material frame (e₁, e₂), so that the stretch from the
  /// stress-free state is F P, C = Pᵀ FᵀF P (13.20); axisymmetric: diag(P_θ, P_s) (13.23). Empty: none (P = I).
  std::vector<Eigen::Matrix2d> point_prestretch;
  int shell_meridian_points = 3;           ///< shells: Gauss points along each element's meridian
  int shell_thickness_points = 5;          ///< shells: Gauss points through the thickness
  std::vector<ElementBlock> blocks;        ///< axisymmetric membrane: one axisym2 block; solid: one solid4
                                           ///< block; 3-D: triangles and/or quads
  std::vector<int> nodes;                  ///< global node numbers (axisymmetric membrane: in meridian order;
                                           ///< solid: the grid's nodes, row by row from the bottom)
  FrameRule frame;                         ///< 3-D parts
  /// Axisymmetric shell parts: reference unit meridian tangent per node of `nodes`
  /// (mesh/meridian_tangents.hpp), in the direction of node order.
  std::vector<Eigen::Vector2d> tangents;
  bool is_shell() const { return element == "axisymmetric_shell"; }
  /// 0-based index of the step from which the part is assembled (`enter_step`; 0: from the start).
  /// Before it the part takes no part: its elements, the loads on it and its contact pairs are
  /// skipped and the nodes only it uses are held at their reference positions (see Model::part_active).
  int enter_step = 0;
  bool is_solid() const { return solid_material != nullptr; }
  int num_elements() const {
    int n = 0;
    for (const auto& b : blocks) n += b.size();
    return n;
  }
};

struct NodeSet {
  std::string name;
  std::vector<int> nodes;
  /// Where it is defined, for messages: "part 'tube' (line 6) as one of its generated sets",
  /// "physical curve 3 of wall.msh (the mesh of part 'wall', line 9)", "node_sets.ends (line 12)".
  std::string origin;
};

/// Prescribed displacement of some DOFs of a node set; its value is ramped
/// linearly within a step towards the target the step sets (0 until set).
struct Boundary {
  std::string name;
  int node_set = -1;
  std::vector<int> dofs;  ///< 0 = r, 1 = z (3-D: x, y, z); axisymmetric shell nodes: 2 = slope_r, 3 = slope_z
  SourceLocation where;
};

/// Follower pressure on the surface of a part; its magnitude is ramped like a boundary value.
/// The enclosed volume of its surface (see surface_pressure.hpp) is an output and may be controlled.
struct PressureLoad {
  std::string name;
  int part = -1;
  double sign = 1;  ///< −1 when the deck flips the side it acts on
  VolumeMeasure volume;  ///< how the enclosed volume is measured (3-D; axisymmetric: about the z axis)
  SourceLocation where;
};

/// A rigid tool in the (r, z) meridian plane (axisymmetric models): a cylinder r = R_c or an
/// open polyline (contact/rigid_surface.hpp), fixed.
struct RigidSurface {
  std::string name;
  enum class Type { cylinder, polyline } type = Type::cylinder;
  RigidCylinder cylinder;
  RigidPolyline polyline;
  SourceLocation where;
};

/// Frictionless penalty contact of the nodes of an axisymmetric membrane or an ordered node set
/// (slave) with a rigid surface or with a deformable master chain of nodes:
/// Π = ½ ε ⟨−g_N⟩² A_s per slave node (contact/axisym_contact.hpp).
struct ContactPair {
  std::string name;
  int rigid = -1;               ///< index into Model::rigid_surfaces; −1: a deformable master (`master`)
  int part = -1;                ///< the slave part, if the slave is a part or a node set of one
  std::vector<int> nodes;       ///< slave nodes (global numbers; rigid: meridian order, deformable: chain order)
  std::vector<double> areas;    ///< their tributary reference areas A_s (slave_tributary_areas on `area_chain`)
  /// The chain whose tributary areas the slave nodes carry: rigid pairs, the slave part's meridian;
  /// deformable pairs, the slave chain itself (the part's meridian or the node set in its order).
  std::vector<int> area_chain;
  std::vector<int> area_index;  ///< per slave node, its index in `area_chain`
  /// Deformable master: its chain of nodes (≥ 2, no repeats), in the order that sets the normal
  /// n = (t_z, −t_r) (contact/contact_search.hpp), i.e. after `master_orientation: reversed`.
  std::vector<int> master;
  std::string master_name;      ///< the part or node set named by `master`
  /// Deformable master: contact with its chain of straight segments (node to segment,
  /// contact/axisym_contact.hpp) or with the C¹ curve through its nodes (contact/smooth_chain.hpp).
  enum class MasterSurface { faceted, smooth } master_surface = MasterSurface::smooth;
  ContactLaw law;
  /// The deck gives the pair no `smoothing`: where an increment fails at its smallest size with a
  /// chattering active set, the analysis smooths the law itself (theory manual (9.2),
  /// solver/contact_chatter.hpp). `smoothing: 0` keeps the plain law.
  bool auto_smoothing = true;
  SourceLocation where;
  /// Two-pass contact of a deformable pair (`passes: 2`, theory manual §9.1, (9.9)): each pass has
  /// half the pair's penalty, and the reverse pass (slave and master swapped) follows the pair in
  /// Model::contacts as an ordinary pair. `reverse`: that entry's index, else −1.
  int reverse = -1;
  /// This entry is the reverse pass of pair `reverse_of` (made by the deck reader, never named in a
  /// deck or an output: its forces are reported with that pair's), else −1.
  int reverse_of = -1;
  bool deformable() const { return rigid < 0; }
  bool is_reverse_pass() const { return reverse_of >= 0; }
};

/// Volume control of a step: the pressure of `load` becomes an unknown and the
/// enclosed volume is ramped from its value at the start of the step to `target`.
struct VolumeControl {
  int load = -1;
  double target = 0;
  SourceLocation where;  ///< the step's `volume_control.volume`
};

/// Newton and increment-control settings.
struct Step {
  std::string name;
  /// An inverse step (theory manual §13): the deck's geometry is the imaged, loaded configuration
  /// and the unknowns move the reference nodes, X = x̂ + u, so that the loads at their values
  /// are carried in x̂ (the zero-pressure geometry). Else a forward step.
  bool inverse = false;
  /// How an inverse step finds X (theory manual §13): `direct`, Newton on the inverse residual of the
  /// inverse elements (13.1)–(13.8); `fixed_point`, the backward-displacement iteration of §13.1,
  /// X_{k+1} = X_k − ω_k (x(X_k) − x̂) with a forward solve from X_k per iteration (13.15);
  /// `prestress`, the imaged geometry stays the reference and carries a prestretch per Gauss point
  /// (the updated-prestrain method of §13.2, (13.20)–(13.24)), with no zero-pressure X.
  enum class InverseMethod { direct, fixed_point, prestress } inverse_method = InverseMethod::direct;
  /// An inverse step that computes a zero-pressure reference X (direct, fixed point): its unknowns
  /// move the reference, and the steps after it continue on X (13.10). A prestress step does not.
  bool moves_reference() const { return inverse && inverse_method != InverseMethod::prestress; }
  /// The fixed point's settings (inverse_method == fixed_point; tolerance and max_iterations also
  /// those of the prestress method's iterations at the imaged loads).
  struct FixedPoint {
    double tolerance = 1e-8;   ///< stop at max_n |x(X_k) − x̂| ≤ tolerance × the imaged bounding-box diagonal
    int max_iterations = 50;   ///< fixed-point iterations at most
    double relaxation = 1.0;   ///< ω (the first ω under Aitken acceleration)
    bool aitken = false;       ///< ω_k by Aitken's Δ² (13.17)
  } fixed_point;
  int increments = 1;
  std::map<std::string, double> targets;  ///< boundary or load name → value at the end of the step
  /// Load name → where its target was written without a unit ("deck.yaml:27:19: key
  /// 'steps[0].set.lumen'", the reader warned about it) and the number as written.
  std::map<std::string, std::pair<std::string, std::string>> unitless_loads;
  VolumeControl volume_control;           ///< load < 0: none
  SolverSettings solver;
};

enum class Reduce { mean, min, max, sum };

/// One history column.
struct HistoryRequest {
  std::string column;   ///< name with unit suffix
  std::string quantity;
  int part = -1, node_set = -1, load = -1, contact = -1;
  Reduce reduce = Reduce::mean;
  std::string unit;     ///< output unit ("" = dimensionless)
  Dimension dim = Dimension::dimensionless;
};

/// How the DataArrays of a .vtu frame are stored: text, or appended raw bytes (uncompressed, or
/// zlib-compressed as VTK's vtkZLibDataCompressor reads them).
enum class VtkFormat { ascii, binary, compressed };

struct OutputSettings {
  std::vector<HistoryRequest> history;
  bool vtk = true;
  int vtk_segments = 48;  ///< hoop subdivisions of the revolved surface (axisymmetric)
  int vtk_every = 1;      ///< a frame every this many increments of a step (and at each step's end)
  VtkFormat vtk_format = VtkFormat::compressed;
  std::vector<std::string> vtk_fields;  ///< the arrays a frame holds, by vtk_field_names; empty: all
  double checkpoint_every_s = 1.0;       ///< wall-clock seconds between restart checkpoints (0: every increment)
};

/// The arrays a .vtu frame of a model of geometry `g` can hold, by name without the unit
/// suffix (`S_hoop`, not `S_hoop_N_per_mm2`), in the order the writer writes them
/// (output/vtk_writer.cpp); `output.vtk_fields` selects among them.
const std::vector<std::string>& vtk_field_names(Geometry g);

/// One item of what a run's converged states depend on, for the restart check: a deck key as
/// the deck reference spells it ("materials.wall.mu", "steps[1].set.lumen") with its value as
/// written, or a part's or node set's mesh data with a digest of it. `step` ≥ 0: a key of that
/// step (0-based), which the converged states depend on once the run has reached the step.
struct FingerprintEntry {
  std::string key;
  std::string value;
  int step = -1;
  bool operator==(const FingerprintEntry&) const = default;
};

struct Model {
  std::string deck_file;
  std::string title;
  UnitSystem units;
  Geometry geometry = Geometry::axisymmetric;
  std::vector<Eigen::Vector3d> X;  ///< reference node positions (axisymmetric: (r, z, 0))
  /// Per node, its tag in the mesh file it was read from (0: a generated node); may be
  /// shorter than X (nodes past its end are generated). For messages only.
  std::vector<long> node_tags;
  /// Per node: the DOF index of its slope unknown u′_r (u′_z follows), −1 if the node is on no
  /// shell part; empty if the model has no shell part (see the DOF map above).
  std::vector<int> slope_dof;
  /// Per node: its reference unit meridian tangent X′ = (R′, Z′) (shell nodes; zero elsewhere).
  std::vector<Eigen::Vector2d> slope_ref;
  int num_slope_nodes = 0;
  /// Shared, so that a copy of the model (the reference an inverse step computes,
  /// Analysis::adopt_reference) keeps the parts' material pointers valid; never changed after reading.
  std::map<std::string, std::shared_ptr<MembraneMaterial>> materials;
  std::map<std::string, std::shared_ptr<SolidMaterial>> solid_materials;  ///< same `materials` section, solid types
  std::vector<Part> parts;
  std::vector<NodeSet> node_sets;
  /// Node sets a mesh generator makes for other parameters but not for these, by full name
  /// (`wall.x0`), each with why: for the message of a deck that names one.
  std::map<std::string, std::string> absent_node_sets;
  std::vector<Boundary> boundaries;
  std::vector<PressureLoad> loads;
  std::vector<RigidSurface> rigid_surfaces;
  std::vector<ContactPair> contacts;
  std::vector<Step> steps;
  OutputSettings output;
  /// What the deck reader found valid but likely not meant, each "file:line:column: key 'k': what".
  std::vector<std::string> warnings;
  /// What the converged states depend on (io/deck_fingerprint.hpp), in deck order.
  std::vector<FingerprintEntry> fingerprint;
  /// Where each key of the fingerprint stands in the deck (1-based line and column), and each
  /// map and list that holds them: a restart refused for a changed key names its line, for a
  /// removed one the line of the map that held it. Not part of restart.txt.
  std::map<std::string, std::pair<int, int>> fingerprint_places;

  int num_nodes() const { return static_cast<int>(X.size()); }
  int dofs_per_node() const { return geometry == Geometry::axisymmetric ? 2 : 3; }
  int num_dofs() const { return dofs_per_node() * num_nodes() + 2 * num_slope_nodes; }
  bool has_slopes(int node) const { return !slope_dof.empty() && slope_dof[node] >= 0; }
  /// Number of unknowns of a node: dofs_per_node(), + 2 on shell nodes.
  int node_dof_count(int node) const { return dofs_per_node() + (has_slopes(node) ? 2 : 0); }
  /// DOF index of unknown c of a node (c < node_dof_count(node); see the DOF map above).
  int node_dof(int node, int c) const {
    return c < dofs_per_node() ? dofs_per_node() * node + c : slope_dof[node] + c - dofs_per_node();
  }
  /// Gives the nodes of the shell parts their slope DOFs and reference slopes
  /// (Part::tangents; after all parts are read).
  void number_slope_dofs();
  /// DOF names in node order: {"r", "z"} or {"x", "y", "z"}.
  std::vector<std::string> dof_names() const {
    return geometry == Geometry::axisymmetric ? std::vector<std::string>{"r", "z"} : std::vector<std::string>{"x", "y", "z"};
  }
  int find_node_set(const std::string& name) const;
  int find_part(const std::string& name) const;
  /// True if part `part` takes part in step `step` (0-based; the reference state counts as step 0):
  /// step ≥ its enter_step. Elements, pressure loads and contact pairs of an inactive part are not
  /// assembled; contact code should skip a pair whose slave or master part is inactive.
  bool part_active(int part, int step) const { return step >= parts[part].enter_step; }
};

}  // namespace tunica
