#include "io/deck.hpp"
#include "io/deck_fingerprint.hpp"

#include "contributions/element_type.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <set>
#include <sstream>

#include "core/article.hpp"
#include "core/bounded_file.hpp"
#include "core/printable.hpp"
#include "core/suggest.hpp"
#include "io/deck_contact.hpp"
#include "io/deck_limits.hpp"
#include "io/deck_meridian_parts.hpp"
#include "io/deck_names.hpp"
#include "io/deck_shell_parts.hpp"
#include "io/deck_solid_parts.hpp"
#include "io/deck_surface_parts.hpp"
#include "io/inverse_step_checks.hpp"
#include "io/material_aliases.hpp"
#include "io/unitless_values.hpp"
#include "io/unit_advice.hpp"
#include "io/yaml_syntax.hpp"
#include "model/axis_pole_check.hpp"
#include "model/boundary_motion_check.hpp"
#include "model/coincident_nodes_check.hpp"
#include "model/edge_frame_check.hpp"
#include "model/frame_axis_check.hpp"
#include "model/held_part_check.hpp"
#include "model/wall_thickness_check.hpp"
#include "model/symmetry_plane_check.hpp"
#include "model/node_label.hpp"
#include "model/rigid_motion_check.hpp"
#include "model/volume_axis_check.hpp"
#include "quantities/history_quantity.hpp"

namespace tunica {

namespace {

const ComponentSpec& units_spec() {
  static const ComponentSpec s{"units", "",
                               "The deck's unit system. Bare numbers are in these units; stress and "
                               "pressure are force/length², angles radians. Any value may carry its own "
                               "unit instead (`0.122 mm`, `200 mmHg`, `61.163 kPa`, `90 deg`).",
                               {required(text("length", "length unit, e.g. mm")),
                                required(text("force", "force unit, e.g. N"))}};
  return s;
}

const ComponentSpec& part_spec() {
  static const ComponentSpec s{
      "parts", "",
      "A body: its element type, material, reference thickness, mesh and (3-D) material frame. "
      "`axisymmetric_membrane` parts (2-node elements on a meridian in the (r, z) plane) get the node sets "
      "`<part>.start`, `<part>.end` and `<part>.all`; `axisymmetric_shell` parts likewise, with their own "
      "quadrature keys (see `parts` (type `axisymmetric_shell`)); `membrane` parts (3-node triangles, 4-node "
      "quadrilaterals and 6-node triangles in 3-D) get `<part>.all` and their generator's sets as `<part>.<set>`, or the "
      "physical curves and points of their Gmsh file; `axisymmetric_solid` parts have their own keys "
      "(see `parts` (type `axisymmetric_solid`)). A deck's parts are all axisymmetric (membranes and "
      "solids) or all 3-D. A part with `enter_step` takes part from that step on (see the user guide).",
      {required(one_of(text("element", "element type"),
                       {"axisymmetric_membrane", "membrane", "axisymmetric_solid", "axisymmetric_shell"})),
       required(text("material", "name of a material in `materials`")),
       required(positive(number("thickness", Dimension::length,
                                "wall thickness: the reference (load-free) H, or with `thickness_at: imaged` the h "
                                "measured in an inverse step's imaged state"))),
       with_default(one_of(text("thickness_at",
                                "membrane parts of a deck with an inverse step: `reference` (`thickness` is H) or "
                                "`imaged` (`thickness` is the wall thickness h of the deck's imaged geometry; each "
                                "Gauss point's reference thickness becomes H = h λ₁λ₂, which the steps after the "
                                "inverse step use; theory manual (13.12)–(13.14))"),
                           {"reference", "imaged"}),
                    "reference"),
       required(structured("mesh", "map or list",
                           "`type:` a generator (see Meshes) or `gmsh`, and its keys; axisymmetric parts: also a "
                           "list of `line` and `arc` pieces joined end to start (see Meshes)")),
       structured("frame", "map", "3-D parts: the material frame rule (see `parts.frame`)"),
       text("enter_step", "name of the step from which the part is assembled, stress free in its deck geometry "
                          "(default: from the start)")}};
  return s;
}

const ComponentSpec& node_set_spec() {
  static const ComponentSpec s{
      "node_sets", "",
      "A named set of nodes: the `nodes` of a `part` (`start`, `end` (axisymmetric), `all`, or a list of "
      "indices into the part's nodes: along the meridian, 0 = start; 3-D: in increasing global order).",
      {required(text("part", "name of a part")), required(structured("nodes", "text or list", "`start`, `end`, `all` or a list of node indices"))}};
  return s;
}

const ComponentSpec& boundary_spec() {
  static const ComponentSpec s{
      "boundary", "",
      "A prescribed displacement of some DOFs of a node set: 0 until a step sets it, then ramped "
      "linearly within the step to the value the step's `set` gives, and held after.",
      {required(text("node_set", "name of a node set")),
       required(structured("dofs", "list",
                           "at least one DOF among `r`, `z` (axisymmetric) or `x`, `y`, `z` (3-D), e.g. `[z]`; nodes of "
                           "`axisymmetric_shell` parts also `slope_r`, `slope_z`: the change of the meridian slope "
                           "∂r/∂S, ∂z/∂S (dimensionless; a boundary that mixes slopes and positions can only be 0)"))}};
  return s;
}

const ComponentSpec& load_spec() {
  static const ComponentSpec s{
      "loads", "pressure",
      "Follower pressure on the current surface of a part, with its consistent (nonsymmetric) load "
      "stiffness. Axisymmetric: positive pressure acts along n = (dz/ds, −dr/ds), s running along the "
      "meridian in node order: outwards for a tube meshed towards +z or a balloon meshed from the lower "
      "to the upper pole. 3-D: along the element normal g1 × g2 (outwards on the generated meshes). Its "
      "magnitude is 0 until a step sets it and is ramped like a boundary value, or it is the unknown of "
      "a volume-controlled step. The enclosed volume (history quantity `volume`) is ⅓∫(x − p₀)·n dA "
      "(closed surfaces, or closed by planes through p₀ such as symmetry planes) or, with "
      "`volume_axis`, ½∫(x − p₀)⊥·n dA about that axis through p₀ (tubes closed by end planes normal to "
      "the axis); axisymmetric: π∫r² dz.",
      {required(one_of(text("type", "load type"), {"pressure"})), required(text("part", "name of a part")),
       with_default(boolean("flip", "act along −n instead"), "false"),
       with_default(numbers("volume_point", Dimension::length, 3, "3-D: the point p₀ of the volume measure"),
                    "[0, 0, 0]"),
       numbers("volume_axis", Dimension::dimensionless, 3,
               "3-D: measure the volume about this axis through p₀; each open end of the surface must lie in a "
               "plane normal to it, or one whose middle it passes through, or one that holds it")}};
  return s;
}

const ComponentSpec& step_spec() {
  static const ComponentSpec s{
      "steps", "",
      "One load step: the targets it ramps to, in equal increments.",
      {with_default(text("name", "name shown in progress and output"), "step"),
       with_default(one_of(text("type",
                                "`forward`: the deck's geometry is the stress-free reference and the step solves "
                                "for the deformed positions. `inverse` (first step only): the deck's geometry is the "
                                "imaged, loaded configuration, held by the loads the step ramps to (e.g. the imaged "
                                "blood pressure), and the step solves for the zero-pressure reference geometry that "
                                "the loads deform into it (theory manual §13); positions, displacements and frames "
                                "of the step are of that reference geometry, stresses and stretches of the imaged "
                                "state; a part's `thickness` is the reference thickness. The steps after it are forward steps "
                                "on the reference it computed, starting from the imaged state at the loads it reached "
                                "(their displacements are from that reference)"),
                           {"forward", "inverse"}),
                    "forward"),
       with_default(one_of(text("method",
                                "inverse steps: how the zero-pressure reference X is found (theory manual §13). "
                                "`direct`: Newton on the inverse elements' equations for X (13.1), membrane parts "
                                "only. `fixed_point`: backward displacement (§13.1): from X₀ = the imaged positions x̂, "
                                "each iteration solves the ordinary forward problem from X_k to the step's loads (in "
                                "its `increments`, with cut-backs) and moves X_{k+1} = X_k − ω (x(X_k) − x̂), until "
                                "every node lands within `fixed_point_tolerance` of x̂; it costs a forward solve per "
                                "iteration and its rate is linear, faster for a stiffer membrane. Each iteration "
                                "is a row of fixed_point.csv. `prestress` (§13.2): no zero-pressure geometry; the "
                                "imaged geometry stays the reference and each Gauss point carries the prestretch that "
                                "balances the loads (the updated-prestrain method): forward solves from the imaged "
                                "geometry ramp the loads in the step's `increments`, each followed by an update of the "
                                "prestretch, and then hold them until a solve moves no node farther than "
                                "`fixed_point_tolerance`; each solve is a row of fixed_point.csv. The steps after it "
                                "start from the imaged geometry with that prestress (displacements from it); its "
                                "prescribed values must be 0"),
                           {"direct", "fixed_point", "prestress"}),
                    "direct"),
       with_default(positive(number("fixed_point_tolerance", Dimension::dimensionless,
                                    "`method: fixed_point`: stop when the largest nodal distance |x(X_k) − x̂| is at "
                                    "most this times the diagonal of the imaged geometry's bounding box; `method: "
                                    "prestress`: stop when a solve at the imaged loads moves no node farther (its "
                                    "default: 1e-4)")),
                    "1e-6"),
       with_default(at_most(at_least(integer("fixed_point_iterations",
                                             "`method: fixed_point`: the most iterations (forward solves); a run "
                                             "that has not reached `fixed_point_tolerance` after them stops (exit 3). "
                                             "`method: prestress`: the most solves at the imaged loads after the "
                                             "ramp (its default: 200)"),
                                     1),
                            1e6),
                    "50"),
       with_default(at_most(positive(number("relaxation", Dimension::dimensionless,
                                            "`method: fixed_point`: the factor ω of the update (13.16), or its first "
                                            "value under `acceleration: aitken`")),
                            2),
                    "1"),
       with_default(one_of(text("acceleration",
                                "`method: fixed_point`: `none` (ω fixed) or `aitken` (ω from Aitken's Δ² each "
                                "iteration, (13.17)); `method: prestress`: the same on the update of the prestretch "
                                "(13.24)"),
                           {"none", "aitken"}),
                    "aitken"),
       required(at_most(at_least(integer("increments", "number of equal increments"), 1), 1e6)),
       structured("set", "map", "boundary or load names → their values at the end of the step"),
       structured("volume_control", "map",
                  "`{load: <pressure load>, volume: <target>}`: that load's pressure becomes an unknown and "
                  "the enclosed volume of its surface is ramped from its value at the start of the step to "
                  "the target (follows a pressure maximum; axisymmetric and 3-D models). The load's volume must not "
                  "be negative at the reference state: volume control of a load that pushes its surface inward is an "
                  "error; a flat sheet (volume 0, the bulge test) starts from its flat state"),
       structured("solver", "map", "overrides of the top-level `solver` keys for this step")}};
  return s;
}

const ComponentSpec& history_spec() {
  static const ComponentSpec s{
      "output.history", "",
      "One column of history.csv, written after each converged increment. The column is `name` "
      "(default: the quantity) followed by `_<unit>` for dimensional quantities.",
      {required(text("quantity", "what to record (see the table of quantities)")),
       text("name", "column name without the unit suffix: any printable text but a comma or a double quote"),
       text("part", "part, for element quantities"),
       text("node_set", "node set, for node quantities"), text("load", "load, for `pressure`"),
       text("contact", "contact pair, for contact quantities"),
       one_of(text("reduce", "how several points combine (default: sum for reactions, mean otherwise)"),
              {"mean", "min", "max", "sum"}),
       text("unit", "output unit (default: the deck's unit of that dimension)")}};
  return s;
}

const ComponentSpec& output_spec() {
  static const ComponentSpec s{
      "output", "", "What a run writes besides newton.csv.",
      {structured("history", "list", "history columns (see `output.history`)"),
       with_default(boolean("vtk", "write ParaView files (.vtu frames, .pvd series)"), "true"),
       with_default(at_most(at_least(integer("vtk_segments", "axisymmetric: hoop subdivisions of the revolved surface"), 3), 1000),
                    "48"),
       with_default(at_most(at_least(integer("vtk_every", "a ParaView frame every N increments of a step, and always at "
                                                          "the reference state and the last increment of each step"),
                                     1),
                            1e6),
                    "1"),
       with_default(one_of(text("vtk_format",
                                "how the .vtu frames store their data: compressed = appended raw binary, zlib "
                                "(what VTK's own XML writers produce; smallest), binary = appended raw binary, "
                                "ascii = numbers as text (largest, readable in an editor)"),
                           {"compressed", "binary", "ascii"}),
                    "compressed"),
       with_default(at_most(at_least(number("checkpoint_every_s", Dimension::dimensionless,
                                            "wall-clock seconds between restart checkpoints (restart.txt, with every "
                                            "file synced to disk); 0: after every increment. A checkpoint is also "
                                            "taken at the end of each step and when the run stops"),
                                     0),
                            86400),
                    "1"),
       structured("vtk_fields", "list",
                  "the arrays each .vtu frame holds, by name without the unit suffix (e.g. [displacement, "
                  "sigma_max, thickness]; the names are listed in the user guide, §5); default: all")}};
  return s;
}

const std::vector<std::string> kTopKeys = {"title", "units", "materials", "parts", "node_sets",
                                           "boundary", "loads", "rigid_surfaces", "contact", "solver",
                                           "steps", "output"};

SolverSettings read_solver(const DeckNode& node, const UnitSystem& u, SolverSettings base) {
  if (!node.defined()) return base;
  node.expect_map_with_keys([] {
    std::vector<std::string> k;
    for (const auto& p : solver_settings_spec().params) k.push_back(p.name);
    return k;
  }());
  // Keys not given keep the base values: read only the present ones.
  for (const auto& entry : node.entries()) {
    const std::string& key = entry.first;
    const DeckNode& value = entry.second;
    ComponentSpec one = solver_settings_spec();
    one.params.erase(std::remove_if(one.params.begin(), one.params.end(), [&](const ParamSpec& p) { return p.name != key; }),
                     one.params.end());
    YAML::Node single;
    single[key] = value.yaml();
    const Params p = read_params(DeckNode(single, node.file(), node.path(), node.where()), one, u);
    set_solver_setting(base, key, p);
  }
  return base;
}

/// Two steps of one name (progress, messages and restart files name steps), and a material that no
/// part uses (a part meant to use it names another): warnings at the second name and at the material.
void warn_names_used_twice_or_never(const DeckNode& deck, Model& m) {
  std::map<std::string, int> seen;  // a step name given in the deck → the line it is given on
  for (const DeckNode& step : deck["steps"].items()) {
    if (!step.is_map() || !step.has("name")) continue;
    const DeckNode name = step["name"];
    const auto [it, fresh] = seen.try_emplace(name.as_string(), name.where().line);
    if (!fresh)
      m.warnings.push_back(format_location(
          name.where(), fmt::format("step name '{}' is also the name of the step on line {}: progress, messages and "
                                    "restart files name steps, so give each its own name",
                                    it->first, it->second)));
  }
  for (const auto& entry : deck["materials"].entries()) {
    const std::string& name = entry.first;
    const auto& node = entry.second;
    if (std::any_of(m.parts.begin(), m.parts.end(), [&](const Part& p) { return p.material_name == name; })) continue;
    std::string used;
    for (const Part& p : m.parts) used += fmt::format("{}'{}' uses '{}'", used.empty() ? "" : ", ", p.name, p.material_name);
    m.warnings.push_back(format_location(
        node.where(), fmt::format("material '{}' is used by no part ({}): if a part is meant to be of it, name it in "
                                  "that part's `material`",
                                  name, used)));
  }
}

/// A reaction of a node set none of whose nodes has that DOF prescribed is 0 at every increment
/// (reactions are R on prescribed DOFs, theory manual §4): a warning naming what the set's nodes hold.
void check_reaction_held(const Params& h, const HistoryRequest& r, Model& m) {
  const std::vector<std::string> dofs = m.dof_names();
  const std::string component = r.quantity.substr(std::string("reaction_").size());
  const auto at = std::find(dofs.begin(), dofs.end(), component);
  if (at == dofs.end()) return;
  const int c = static_cast<int>(at - dofs.begin());
  const std::vector<int>& nodes = m.node_sets[static_cast<std::size_t>(r.node_set)].nodes;
  const std::set<int> in_set(nodes.begin(), nodes.end());
  std::set<int> held;  // DOF components held at some node of the set
  std::string by;  // the boundaries on the set
  for (const Boundary& b : m.boundaries) {
    const std::vector<int>& bn = m.node_sets[static_cast<std::size_t>(b.node_set)].nodes;
    if (std::none_of(bn.begin(), bn.end(), [&](int n) { return in_set.count(n) > 0; })) continue;
    for (int d : b.dofs) held.insert(d);
    by += (by.empty() ? "" : ", ") + b.name;
  }
  if (held.count(c)) return;
  std::string list;
  for (int d : held) list += (list.empty() ? "" : ", ") + dofs[static_cast<std::size_t>(d)];
  m.warnings.push_back(format_location(
      h.where("node_set"),
         fmt::format("'{}' is the reaction on prescribed {} DOFs, and no boundary holds {} at any node of '{}' ({}): "
                     "the column would be 0 throughout. Name a set whose {} is held, or hold it with a boundary "
                     "(`{{node_set: {}, dofs: [{}]}}`)",
                     r.quantity, component, component, h.text("node_set"),
                     held.empty() ? std::string("no boundary holds any of its nodes")
                                  : fmt::format("the boundaries on it, {}, hold {}", by, list),
                     component, h.text("node_set"), component)));
}

/// A directional quantity (lambda_1, S_2, ...) of a 3-D part without `frame` whose elements' first
/// edges turn between neighbours (model/edge_frame_check.hpp) is warned about at its history entry.
void warn_edge_frame_quantity(const DeckNode& node, const HistoryRequest& r, Model& m) {
  static const std::set<std::string> directional = {"lambda_1", "lambda_2", "E_1", "E_2", "E_12",
                                                    "S_1", "S_2", "S_12", "sigma_1", "sigma_2"};
  if (m.geometry != Geometry::three_d || !directional.count(r.quantity)) return;
  const double turned = edge_frame_turned_fraction(m, r.part);
  if (!(turned > 0.05)) return;
  m.warnings.push_back(format_location(
      node.where(),
      fmt::format("'{}' is taken along the material directions of part '{}', which has no `frame`: its direction 1 follows each "
                  "element's first edge, and on this mesh it turns by more than {:g} deg between {:.0f} % of the "
                  "neighbouring elements, so the values mix directions (a mean of {} is {}). Give the part a frame (a vessel along z: `frame: {{type: cylindrical, axis: "
                  "[0, 0, 1]}}`), or record quantities that need none (sigma_max, sigma_min, lambda_3, thickness)",
                  r.quantity, m.parts[static_cast<std::size_t>(r.part)].name, kEdgeFrameTurnDeg, 100 * turned,
                  r.quantity,
                  r.quantity.back() == '2' && r.quantity.size() > 3 && r.quantity[r.quantity.size() - 2] == '1'
                      ? "not the shear between the hoop and axial directions"
                      : "neither the hoop nor the axial value")));
}

/// The name of step k (0-based) of the deck's `steps` list, "step" if it has none.
std::string step_name(const DeckNode& steps, std::size_t k) {
  const std::vector<DeckNode> items = steps.is_sequence() ? steps.items() : std::vector<DeckNode>{};
  if (k < items.size() && items[k].is_map() && items[k].has("name") && items[k]["name"].is_scalar())
    return items[k]["name"].as_string();
  return "step";
}

/// The 0-based index of the step named by `key` (enter_step), from the deck's `steps` list
/// (read before the steps themselves: parts come first). Unknown or ambiguous names are errors.
int step_index(const DeckNode& deck, const Params& p, const std::string& key) {
  const std::string& wanted = p.text(key);
  std::vector<int> found;
  std::string known;
  const DeckNode steps = deck["steps"];
  const std::size_t count = steps.is_sequence() ? steps.items().size() : 0;
  for (std::size_t k = 0; k < count; ++k) {
    const std::string n = step_name(steps, k);
    known += (known.empty() ? "" : ", ") + n;
    if (n == wanted) found.push_back(static_cast<int>(k));
  }
  if (found.empty()) p.fail(key, "unknown step '" + wanted + "' (the steps are: " + known + ")");
  if (found.size() > 1) p.fail(key, fmt::format("{} steps are named '{}': give them distinct names", found.size(), wanted));
  return found.front();
}

/// What a part without `mesh` is told to add: an example for its element.
std::string mesh_fix(const std::string& element) {
  if (element == "membrane")
    return "add the part's geometry, e.g. `mesh: {type: tube, radius: 1 mm, length: 5 mm, around: 16, along: 10}` "
           "(generated: tube, sphere or octant) or `mesh: {type: gmsh, file: wall.msh, surface: wall}` (a Gmsh mesh)";
  if (element == "axisymmetric_solid")
    return "add the part's geometry, e.g. `mesh: {type: grid, z0: 0 mm, z1: 5 mm, inner: 1 mm, outer: 1.2 mm, "
           "elements_r: 4, elements_z: 20}`";
  return "add the part's geometry, e.g. `mesh: {type: line, from: [1 mm, 0 mm], to: [1 mm, 10 mm], elements: 10}` (a "
         "straight meridian from [r, z] to [r, z]), or for a balloon `mesh: {type: arc, center: [0 mm, 0 mm], radius: "
         "5 mm, start_angle: -90 deg, end_angle: 90 deg, elements: 20}`";
}

void read_parts(const DeckNode& deck, Model& m, const ReadOptions& options) {
  const std::string material = m.materials.empty() ? "<material>" : m.materials.begin()->first;
  const DeckNode parts = deck.required(
      "parts", fmt::format(": add the bodies, e.g. `parts: {{wall: {{element: axisymmetric_membrane, material: {}, "
                           "thickness: 0.1 mm, mesh: {{type: line, from: [1 mm, 0 mm], to: [1 mm, 10 mm], elements: "
                           "10}}}}}}` (user guide §3)",
                           material));
  if (!parts.is_map() || parts.entries().empty()) parts.fail("expected a map of parts (name: {element, material, ...})");
  SurfaceMeshCache cache;
  cache.allow_scripts = options.allow_scripts;
  bool first = true;
  for (const auto& [name, node] : parts.entries()) {
    const std::string element =
        node.is_map() && node.has("element") && node["element"].is_scalar() ? node["element"].as_string() : "";
    const bool solid = element == "axisymmetric_solid", shell = element == "axisymmetric_shell";
    ComponentSpec spec = solid ? solid_part_spec() : shell ? shell_part_spec() : part_spec();
    for (ParamSpec& q : spec.params)
      if (q.name == "mesh") q.missing_fix = mesh_fix(element);
    const Params p = read_params(node, spec, m.units);
    Part part;
    part.name = name;
    part.element = p.text("element");
    if (!solid) part.thickness = p.number("thickness");
    if (p.has("thickness_at")) part.imaged_thickness = p.text("thickness_at") == "imaged";
    part.material_name = p.text("material");
    auto mat = m.materials.find(part.material_name);
    auto smat = m.solid_materials.find(part.material_name);
    if (mat == m.materials.end() && smat == m.solid_materials.end())
      {
      std::vector<std::string> known = keys_of(m.materials);
      for (const auto& k : keys_of(m.solid_materials)) known.push_back(k);
      p.fail("material", "undefined material '" + part.material_name + "' " +
                             known_names(part.material_name, known, "materials in `materials`"));
    }
    if (solid && smat == m.solid_materials.end())
      p.fail("material", "material '" + part.material_name + "' is a membrane material (type " + mat->second->type() +
                             "); an axisymmetric_solid part needs a solid material (e.g. type neo_hookean_solid)");
    if (!solid && mat == m.materials.end())
      p.fail("material", "material '" + part.material_name + "' is a solid material (type " + smat->second->type() +
                             "); a " + part.element + " part needs a membrane material");
    if (solid) part.solid_material = smat->second.get();
    else part.material = mat->second.get();
    if (p.has("enter_step")) part.enter_step = step_index(deck, p, "enter_step");
    const Geometry g = part.element == "membrane" ? Geometry::three_d : Geometry::axisymmetric;
    if (first) m.geometry = g;
    else if (g != m.geometry)
      p.fail("element", "axisymmetric and 3-D parts cannot be mixed in one deck (the first part is " +
                            m.parts.front().element + ")");
    first = false;
    std::vector<int> joints;  // where the pieces of a meridian join
    if (solid) {
      read_solid_part(node, p, part, m);
    } else if (g == Geometry::axisymmetric) {
      joints = read_meridian_part(node, part, m);
    } else {
      read_surface_part(node, part, m, cache);
    }
    if (shell) {
      part.blocks.front().kind = ElementKind::shell2;
      finish_shell_part(node, p, part, m, joints);
    }
    m.parts.push_back(std::move(part));
  }
  if (m.geometry == Geometry::three_d) finish_surface_parts(parts, m);
  m.number_slope_dofs();
}

void read_node_sets(const DeckNode& deck, Model& m) {
  if (!deck.has("node_sets")) return;
  for (const auto& [name, node] : deck["node_sets"].entries()) {
    if (const int earlier = m.find_node_set(name); earlier >= 0)
      node.fail(fmt::format("node set '{}' is already defined, by {}: give this one another name (here and where the "
                            "deck names it)",
                            name, m.node_sets[earlier].origin));
    const Params p = read_params(node, node_set_spec(), m.units);
    const int part = m.find_part(p.text("part"));
    if (part < 0) p.fail("part", "undefined part '" + p.text("part") + "' " + known_names(p.text("part"), names_of(m.parts), "parts"));
    const auto& pn = m.parts[part].nodes;
    NodeSet set{name, {}, fmt::format("node_sets.{} (line {})", name, node.where().line)};
    const DeckNode nodes = node.required("nodes");
    const bool axisym = m.geometry == Geometry::axisymmetric && !m.parts[part].is_solid();
    if (m.parts[part].is_solid() && nodes.is_scalar() && (nodes.as_string() == "start" || nodes.as_string() == "end"))
      nodes.fail("a solid part has no start or end: use its sets `" + p.text("part") + ".inner`, `.outer`, `.bottom`, `.top`");
    if (nodes.is_scalar()) {
      const std::string w = nodes.as_string();
      if (w == "start" && axisym) set.nodes = {pn.front()};
      else if (w == "end" && axisym) set.nodes = {pn.back()};
      else if (w == "all") set.nodes = pn;
      else nodes.fail(std::string("expected ") + (axisym ? "start, end, " : "") + "all or a list of node indices, got '" + w + "'");
    } else {
      // A node listed twice would be held, loaded or reported twice (a reaction summed twice): an
      // error, since the repeat is most often a mistyped index of another node.
      std::map<long, std::pair<int, SourceLocation>> listed;
      const std::vector<DeckNode> items = nodes.items();
      for (int k = 0; k < static_cast<int>(items.size()); ++k) {
        const DeckNode& item = items[k];
        // A name in the list (`[start, 60]`): the names stand alone; in a list, the index they stand for.
        if (item.is_scalar()) {
          const std::string w = item.as_string();
          const bool named = w == "start" || w == "end" || w == "all";
          if (named && w != "all" && axisym)
            item.fail(fmt::format("'{}' is a node set's name, which stands alone (`nodes: {}`), not an item of a list "
                                  "of indices: in the list, the part's {} node is {}",
                                  w, w, w, w == "start" ? 0 : static_cast<long>(pn.size()) - 1));
          if (named)
            item.fail(fmt::format("'{}' is a node set's name, which stands alone (`nodes: {}`), not an item of a list "
                                  "of indices ({} … {})",
                                  w, w, 0, pn.size() - 1));
        }
        const long i = item.as_integer();
        if (i < 0 || i >= static_cast<long>(pn.size()))
          item.fail(fmt::format("node index {} is outside the part (0 … {})", i, pn.size() - 1));
        if (const auto first = listed.find(i); first != listed.end())
          item.fail(fmt::format("node set '{}' lists node {} twice: first as nodes[{}] (line {}, column {}), again "
                                "here as nodes[{}]. List each node once; if another node was meant here, correct "
                                "this index",
                                name, i, first->second.first, first->second.second.line, first->second.second.column, k));
        listed.emplace(i, std::make_pair(k, item.where()));
        set.nodes.push_back(pn[i]);
      }
    }
    m.node_sets.push_back(std::move(set));
  }
}

int node_set_ref(const Params& p, const std::string& key, const Model& m) {
  const int s = m.find_node_set(p.text(key));
  if (s < 0) {
    // A set the part's generator makes only for other parameters (a tube's `x0`): say why.
    const auto absent = m.absent_node_sets.find(p.text(key));
    p.fail(key, "undefined node set '" + p.text(key) + "'" +
                    (absent != m.absent_node_sets.end() ? ": its part's mesh has none, since " + absent->second + " "
                                                        : std::string(" ")) +
                    known_names(p.text(key), names_of(m.node_sets), "node sets"));
  }
  return s;
}

void read_boundaries(const DeckNode& deck, Model& m) {
  if (!deck.has("boundary")) return;
  for (const auto& [name, node] : deck["boundary"].entries()) {
    const Params p = read_params(node, boundary_spec(), m.units);
    Boundary b{name, node_set_ref(p, "node_set", m), {}, node.where()};
    const DeckNode dofs = node.required("dofs");
    const std::vector<DeckNode> list = dofs.is_sequence() ? dofs.items() : std::vector<DeckNode>{dofs};
    std::vector<std::string> dof_names = m.dof_names();
    if (m.geometry == Geometry::axisymmetric) dof_names.insert(dof_names.end(), {"slope_r", "slope_z"});
    const std::string allowed = m.geometry == Geometry::axisymmetric
                                    ? "axisymmetric DOFs are r and z, and slope_r and slope_z on shells"
                                    : "3-D DOFs are x, y and z";
    // An empty list would hold nothing, and a step's `set` of the boundary would do nothing.
    if (list.empty())
      dofs.fail("the list of DOFs is empty, so the boundary would hold nothing: name the DOFs it holds (" + allowed +
                "), e.g. `dofs: [z]`");
    for (const auto& d : list) {
      const std::string s = d.as_string();
      auto it = std::find(dof_names.begin(), dof_names.end(), s);
      if (it == dof_names.end()) d.fail("unknown DOF '" + s + "' (" + allowed + ")");
      const int c = static_cast<int>(it - dof_names.begin());
      if (std::find(b.dofs.begin(), b.dofs.end(), c) != b.dofs.end()) {
        std::string others;
        for (int k = 0; k < m.dofs_per_node(); ++k)
          if (k != c && std::find(b.dofs.begin(), b.dofs.end(), k) == b.dofs.end())
            others += (others.empty() ? "" : ", ") + dof_names[k];
        d.fail("DOF '" + s + "' is listed twice in `dofs`: list each DOF once" +
               (others.empty() ? std::string() : " (or write the one meant; not listed: " + others + ")"));
      }
      if (c >= m.dofs_per_node())
        for (int n : m.node_sets[b.node_set].nodes)
          if (!m.has_slopes(n))
            d.fail("DOF '" + s + "': node set '" + p.text("node_set") +
                   "' has nodes without slopes (only nodes of axisymmetric_shell parts have slope_r and slope_z)");
      b.dofs.push_back(c);
    }
    m.boundaries.push_back(std::move(b));
  }
  // A DOF may be prescribed by one boundary only: name a node both hold, the DOF and both boundaries.
  std::map<long, std::size_t> owner;  // DOF -> the boundary that prescribes it
  std::vector<std::string> dof_names = m.dof_names();
  dof_names.insert(dof_names.end(), {"slope_r", "slope_z"});
  for (std::size_t k = 0; k < m.boundaries.size(); ++k) {
    const Boundary& b = m.boundaries[k];
    for (int d : b.dofs) {
      std::size_t other = k;
      std::vector<int> shared;  // the nodes whose DOF d boundary `other` prescribes too
      for (int n : m.node_sets[b.node_set].nodes) {
        const auto [it, fresh] = owner.emplace(static_cast<long>(m.node_dof(n, d)), k);
        if (fresh || it->second == k) continue;
        if (other == k) other = it->second;
        if (it->second == other) shared.push_back(n);
      }
      if (shared.empty()) continue;
      const Boundary& a = m.boundaries[other];
      throw InputError(
          b.where,
          fmt::format("boundary '{}' (line {}, node set '{}') and boundary '{}' (line {}, node set '{}') both prescribe "
                      "{} of {}{}: a DOF takes one prescribed value. Remove '{}' from the `dofs` of one of them, or "
                      "give one a node set without the shared node{}",
                      b.name, b.where.line, m.node_sets[b.node_set].name, a.name, a.where.line,
                      m.node_sets[a.node_set].name, dof_names[d], node_label(m, shared.front()),
                      shared.size() > 1 ? fmt::format(" (and {} more node(s) of both sets)", shared.size() - 1) : "",
                      dof_names[d], shared.size() > 1 ? "s" : ""));
    }
  }
}

void read_loads(const DeckNode& deck, Model& m) {
  if (!deck.has("loads")) return;
  for (const auto& [name, node] : deck["loads"].entries()) {
    for (const auto& b : m.boundaries)
      if (b.name == name) node.fail("name '" + name + "' is already used by a boundary");
    const Params p = read_params(node, load_spec(), m.units);
    const int part = m.find_part(p.text("part"));
    if (part < 0) p.fail("part", "undefined part '" + p.text("part") + "' " + known_names(p.text("part"), names_of(m.parts), "parts"));
    for (const auto& block : m.parts[part].blocks)  // a kind that carries no follower pressure (solids)
      if (const ElementType& type = element_type(block.kind); !type.pressure)
        p.fail("part", "part '" + p.text("part") + "' " +
                           (type.solid ? std::string("is a solid") : "has " + type.name + " elements, which carry no pressure") +
                           ": pressure loads act on membrane parts");
    PressureLoad load{name, part, p.boolean("flip") ? -1.0 : 1.0, {}, node.where()};
    const auto& vp = p.numbers("volume_point");
    load.volume.point = Eigen::Vector3d(vp[0], vp[1], vp[2]);
    if (p.has("volume_axis")) {
      const auto& a = p.numbers("volume_axis");
      load.volume.about_axis = true;
      load.volume.axis = Eigen::Vector3d(a[0], a[1], a[2]);
      if (!(load.volume.axis.norm() > 0)) p.fail("volume_axis", "the axis direction must not be zero");
      load.volume.axis.normalize();
    }
    if (m.geometry == Geometry::axisymmetric && (node.has("volume_point") || node.has("volume_axis")))
      p.fail(node.has("volume_point") ? "volume_point" : "volume_axis",
             "an axisymmetric volume is always measured about the z axis");
    if (const std::string why = volume_axis_misfit(m, part, load.volume); !why.empty()) p.fail("volume_axis", why);
    m.loads.push_back(std::move(load));
  }
}

/// The part entering latest (highest enter_step) among those a boundary or load named `target`
/// acts on (a boundary: the parts holding a node of its set), or −1 if all of them are there from the start.
int entering_part(const Model& m, const std::string& target) {
  int late = -1;
  const auto consider = [&](int p) {
    if (m.parts[p].enter_step > 0 && (late < 0 || m.parts[p].enter_step > m.parts[late].enter_step)) late = p;
  };
  for (const auto& l : m.loads)
    if (l.name == target) consider(l.part);
  for (const auto& b : m.boundaries)
    if (b.name == target)
      for (std::size_t p = 0; p < m.parts.size(); ++p)
        for (int n : m.node_sets[b.node_set].nodes)
          if (std::find(m.parts[p].nodes.begin(), m.parts[p].nodes.end(), n) != m.parts[p].nodes.end()) {
            consider(static_cast<int>(p));
            break;
          }
  return late;
}

/// What a deck without `steps` is told to add: a step that sets one of its loads or boundaries.
std::string steps_fix(const Model& m) {
  const std::string set = !m.loads.empty()        ? m.loads.front().name + ": 10 kPa"
                          : !m.boundaries.empty() ? m.boundaries.front().name + ": 1 mm"
                                                  : "<a boundary or load>: <its value>";
  return fmt::format(": add the load steps, solved in order, e.g. `steps: [{{name: load, increments: 10, set: {{{}}}}}]`; "
                     "a step ramps each boundary and load of its `set` to the value given, in `increments` equal "
                     "increments",
                     set);
}

void read_steps(const DeckNode& deck, Model& m, const SolverSettings& solver) {
  const DeckNode steps = deck.required("steps", steps_fix(m));
  if (!steps.is_sequence() || steps.items().empty()) steps.fail("expected a list of steps");
  for (const auto& node : steps.items()) {
    const Params p = read_params(node, step_spec(), m.units);
    Step s;
    s.name = p.text("name");
    s.inverse = p.text("type") == "inverse";
    if (p.text("method") == "fixed_point") s.inverse_method = Step::InverseMethod::fixed_point;
    if (p.text("method") == "prestress") s.inverse_method = Step::InverseMethod::prestress;
    s.fixed_point.tolerance = p.number("fixed_point_tolerance");
    s.fixed_point.max_iterations = static_cast<int>(p.integer("fixed_point_iterations"));
    s.fixed_point.relaxation = p.number("relaxation");
    s.fixed_point.aitken = p.text("acceleration") == "aitken";
    // The prestress method's own defaults (theory manual §13.2): its solves approach the imaged
    // geometry slowly along modes of little material stiffness, a distance of 1e-4 of the model's
    // size is far below what an image resolves, and each solve is one increment.
    if (s.inverse_method == Step::InverseMethod::prestress) {
      if (!node.has("fixed_point_tolerance")) s.fixed_point.tolerance = 1e-4;
      if (!node.has("fixed_point_iterations")) s.fixed_point.max_iterations = 200;
    }
    for (const char* key : {"method", "fixed_point_tolerance", "fixed_point_iterations", "relaxation", "acceleration"}) {
      if (!node.has(key)) continue;
      if (!s.inverse)
        node[key].fail(fmt::format("`{}` is a key of inverse steps (`type: inverse`), and step '{}' is a forward step",
                                   key, s.name));
      const bool iterative_key = std::string(key) == "fixed_point_tolerance" ||
                                 std::string(key) == "fixed_point_iterations" || std::string(key) == "acceleration";
      const bool fits = std::string(key) == "method" || s.inverse_method == Step::InverseMethod::fixed_point ||
                        (iterative_key && s.inverse_method == Step::InverseMethod::prestress);
      if (!fits)
        node[key].fail(fmt::format("`{}` is a key of the fixed-point method{}: add `method: fixed_point` to step '{}' "
                                   "({})",
                                   key, iterative_key ? " and the prestress method" : "", s.name,
                                   s.inverse_method == Step::InverseMethod::prestress
                                       ? "`method: prestress` takes `fixed_point_tolerance`, `fixed_point_iterations` "
                                         "and `acceleration` only"
                                       : "the default `method: direct` takes none"));
    }
    s.increments = static_cast<int>(p.integer("increments"));
    s.solver = read_solver(node["solver"], m.units, solver);
    if (node.has("set")) {
      for (const auto& entry : node["set"].entries()) {
        const std::string& target = entry.first;  // (a named variable: lambdas below capture it)
        const DeckNode& value = entry.second;
        const bool is_boundary = std::any_of(m.boundaries.begin(), m.boundaries.end(), [&](auto& b) { return b.name == target; });
        const bool is_load = std::any_of(m.loads.begin(), m.loads.end(), [&](auto& l) { return l.name == target; });
        if (!is_boundary && !is_load) {
          std::vector<std::string> known = names_of(m.boundaries);
          for (const auto& l : m.loads) known.push_back(l.name);
          value.fail("'" + target + "' is neither a boundary nor a load " + known_names(target, known, "boundaries and loads"));
        }
        if (const int late = entering_part(m, target); late >= 0 && static_cast<int>(m.steps.size()) < m.parts[late].enter_step)
          value.fail(fmt::format("'{}' acts on part '{}', which enters in step {} '{}': set it in that step or later",
                                 target, m.parts[late].name, m.parts[late].enter_step + 1,
                                 step_name(steps, m.parts[late].enter_step)));
        // A boundary on slopes only is dimensionless; one mixing slopes and positions can only hold them at 0.
        int slopes = 0, positions = 0;
        for (const auto& b : m.boundaries)
          if (b.name == target)
            for (int d : b.dofs) ++(d >= m.dofs_per_node() ? slopes : positions);
        const Dimension dim = !is_boundary ? Dimension::pressure : positions == 0 && slopes > 0 ? Dimension::dimensionless
                                                                                                : Dimension::length;
        // A pressure given to a boundary: most likely the load was meant, not a displacement.
        if (is_boundary && !is_load && value.is_scalar()) {
          double written = 0;
          std::string unit;
          if (split_quantity(value.as_string(), written, unit) && !unit.empty()) {
            bool pressure = true;
            try {
              m.units.check_unit(unit, Dimension::pressure);
            } catch (const std::invalid_argument&) {
              pressure = false;
            }
            if (pressure)
              value.fail(fmt::format("'{}' is a boundary, whose value is a prescribed {} (in {}), but '{}' is a pressure: "
                                     "a pressure is set on a load {}",
                                     target, dim == Dimension::length ? "position change" : "slope",
                                     dim == Dimension::length ? m.units.display_unit(Dimension::length) : "rad",
                                     value.as_string(), known_names("", names_of(m.loads), "loads")));
          }
        }
        s.targets[target] = read_quantity(value, dim, m.units);
        if (is_load && warn_if_unitless(value, Dimension::pressure, m, true)) {
          std::string where = format_location(value.where(), "");
          while (!where.empty() && (where.back() == ' ' || where.back() == ':')) where.pop_back();
          s.unitless_loads[target] = {where, value.as_string()};
        }
        if (slopes > 0 && positions > 0 && s.targets[target] != 0)
          value.fail("boundary '" + target + "' holds slopes and positions: it can only be 0 (give the slopes their "
                     "own boundary to prescribe them)");
      }
    }
    if (node.has("volume_control")) {
      const DeckNode vc = node["volume_control"];
      vc.expect_map_with_keys({"load", "volume"});
      const std::string load = vc.required("load").as_string();
      auto it = std::find_if(m.loads.begin(), m.loads.end(), [&](auto& l) { return l.name == load; });
      if (it == m.loads.end()) vc["load"].fail("undefined pressure load '" + load + "' " + known_names(load, names_of(m.loads), "loads"));
      if (s.targets.count(load)) vc["load"].fail("load '" + load + "' is also set in `set`: a volume-controlled pressure is an unknown");
      s.volume_control.load = static_cast<int>(it - m.loads.begin());
      if (const int late = m.loads[s.volume_control.load].part; static_cast<int>(m.steps.size()) < m.parts[late].enter_step)
        vc["load"].fail("load '" + load + "' acts on part '" + m.parts[late].name + "', which has not entered yet");
      s.volume_control.target = read_quantity(vc.required("volume"), Dimension::volume, m.units);
      s.volume_control.where = vc["volume"].where();
      if (!(s.volume_control.target > 0)) vc["volume"].fail("the target volume must be positive");
    }
    if (s.inverse) check_inverse_step(node, m, s);
    m.steps.push_back(std::move(s));
  }
}

/// A history column's `name` goes into the header of history.csv as it is: a comma would split
/// the column, a double quote or a line break corrupt the row for every CSV reader (pandas, the
/// csv module, ParaView) and every line-based tool. Such a name is refused rather than quoted:
/// RFC 4180 quotes would read back in pandas, but not in numpy.loadtxt, a spreadsheet's default
/// import or `cut -d,`, and a column name never needs them.
void check_column_name(const Params& h, const std::string& key) {
  const std::string& name = h.text(key);
  if (name.empty()) h.fail(key, "the column name is empty: leave `name` out for the quantity's own name, or give one");
  std::string bad, fixed;
  for (const char c : name) {
    const bool wrong = c == ',' || c == '"' || static_cast<unsigned char>(c) < 0x20 || c == 0x7f;
    if (wrong && bad.find(c) == std::string::npos) bad += c;
    fixed += wrong ? '_' : c;
  }
  if (bad.empty()) return;
  std::string which;
  for (const char c : bad)
    which += std::string(which.empty() ? "" : ", ") +
             (c == ',' ? "a comma" : c == '"' ? "a double quote" : c == '\n' ? "a line break" : "a control character");
  h.fail(key, fmt::format("'{}' holds {}, which would corrupt the header of history.csv (a comma splits the column; "
                          "a quote or a line break breaks the row): a column name may hold any printable character "
                          "but a comma and a double quote, e.g. `{}`",
                          printable(name), which, printable(fixed)));
}

void read_output(const DeckNode& deck, Model& m) {
  if (!deck.has("output")) return;
  const DeckNode out = deck["output"];
  const Params p = read_params(out, output_spec(), m.units);
  m.output.vtk = p.boolean("vtk");
  m.output.vtk_segments = static_cast<int>(p.integer("vtk_segments"));
  m.output.vtk_every = static_cast<int>(p.integer("vtk_every"));
  m.output.checkpoint_every_s = p.number("checkpoint_every_s");
  const std::string format = p.text("vtk_format");
  m.output.vtk_format = format == "ascii" ? VtkFormat::ascii : format == "binary" ? VtkFormat::binary : VtkFormat::compressed;
  if (out.has("vtk_fields")) {
    const DeckNode list = out["vtk_fields"];
    if (!list.is_sequence()) list.fail("expected a list of array names, e.g. [displacement, thickness]");
    const auto& names = vtk_field_names(m.geometry);
    for (const auto& item : list.items()) {
      if (!item.is_scalar()) item.fail("expected an array name");
      const std::string name = item.as_string();
      if (std::find(names.begin(), names.end(), name) == names.end()) {
        // A name with its unit suffix (sigma_hoop_N_per_mm2): the longest name it begins with.
        std::string base;
        for (const auto& n : names)
          if (name.rfind(n + "_", 0) == 0 && n.size() > base.size()) base = n;
        if (!base.empty())
          item.fail(fmt::format("'{}': write the name without its unit suffix, '{}' (the frames add the unit)", name, base));
        std::string known;
        for (const auto& n : names) known += (known.empty() ? "" : ", ") + n;
        item.fail(fmt::format("'{}' is not an array of {} model's frames (names without the unit suffix): {}{}", name,
                              m.geometry == Geometry::axisymmetric ? "an axisymmetric" : "a 3-D", known,
                              did_you_mean(name, names)));
      }
      if (name == "contact_pressure" && m.contacts.empty())
        item.fail("'contact_pressure' is written only for models with contact pairs, and this one has none");
      if (std::find(m.output.vtk_fields.begin(), m.output.vtk_fields.end(), name) != m.output.vtk_fields.end())
        item.fail("'" + name + "' is listed twice");
      m.output.vtk_fields.push_back(name);
    }
    if (m.output.vtk_fields.empty()) list.fail("the list is empty: leave vtk_fields out for every array, or set vtk: false");
  }
  if (!out.has("history")) return;
  std::set<std::string> columns = {"step", "increment", "time"};  // written first in every history.csv
  for (const auto& node : out["history"].items()) {
    const Params h = read_params(node, history_spec(), m.units);
    HistoryRequest r;
    r.quantity = h.text("quantity");
    const HistoryQuantity* q = find_history_quantity(r.quantity);
    if (!q) {
      std::string list;
      for (const auto& x : history_quantities()) list += (list.empty() ? "" : ", ") + x.name;
      // A direction written by its name (S_z) is the quantity of that direction, not the nearest spelling (S_1).
      std::string meant = direction_name_suggestion(r.quantity, m.geometry);
      if (meant.empty()) meant = did_you_mean(r.quantity, names_of(history_quantities()));
      h.fail("quantity", "unknown quantity '" + r.quantity + "' (known: " + list + ")" + meant);
    }
    r.dim = q->dim;
    const std::string target = target_key(q->target);
    if (q->target == QuantityTarget::node_set && q->geometry && *q->geometry != m.geometry)
      h.fail("quantity", m.geometry == Geometry::axisymmetric
                             ? "'" + r.quantity + "' is a 3-D quantity; axisymmetric nodes have r and z"
                             : "'" + r.quantity + "' is an axisymmetric quantity; 3-D nodes have x, y and z");
    for (const char* key : {"part", "node_set", "load", "contact"}) {
      if (h.has(key) && target != key) {
        // A node set given to a quantity of a part: the quantities of a node set's nodes.
        std::string of_nodes;
        if (std::string(key) == "node_set") {
          for (const auto& x : history_quantities())
            if (x.target == QuantityTarget::node_set && (!x.geometry || *x.geometry == m.geometry))
              of_nodes += (of_nodes.empty() ? "" : ", ") + x.name;
          of_nodes = fmt::format(
              "; the quantities of a node set's nodes are {}{}", of_nodes,
              r.quantity == "radius" && m.geometry == Geometry::axisymmetric
                  ? " (the radius of its nodes is `position_r`, with `reduce: mean|min|max`)"
                  : "");
        }
        h.fail(key, fmt::format("quantity '{}' takes {}{}", r.quantity,
                                target.empty() ? "no set" : with_article(target), of_nodes));
      }
    }
    if (!target.empty() && !h.has(target)) {
      // The names the key could take, so that the fix can be copied (a reverse pass is no pair).
      std::vector<std::string> names;
      if (target == "part") names = names_of(m.parts);
      else if (target == "node_set") names = names_of(m.node_sets);
      else if (target == "load") names = names_of(m.loads);
      else
        for (const ContactPair& c : m.contacts)
          if (!c.is_reverse_pass()) names.push_back(c.name);
      std::string list;
      for (std::size_t i = 0; i < names.size() && i < 12; ++i) list += (i ? ", " : "") + names[i];
      if (names.size() > 12) list += ", …";
      h.fail("quantity", fmt::format("quantity '{}' needs the key '{}'{}", r.quantity, target,
                                     names.empty() ? std::string()
                                                   : fmt::format(" (e.g. `{}: {}`; the deck's: {})", target,
                                                                 names.front(), list)));
    }
    if (q->target == QuantityTarget::part) {
      r.part = m.find_part(h.text("part"));
      if (r.part < 0) h.fail("part", "undefined part '" + h.text("part") + "' " + known_names(h.text("part"), names_of(m.parts), "parts"));
      if (q->geometry && *q->geometry != m.geometry)
        h.fail("quantity", "'" + r.quantity + "' is a quantity of axisymmetric parts");
      if (q->shells_only && !m.parts[r.part].is_shell())
        h.fail("quantity", "'" + r.quantity + "' is a quantity of axisymmetric_shell parts; part '" + h.text("part") +
                               "' is an " + m.parts[r.part].element + " part");
      if (!q->solid && m.parts[r.part].is_solid()) {
        std::string list;
        for (const auto& x : history_quantities())
          if (x.solid) list += (list.empty() ? "" : ", ") + x.name;
        h.fail("quantity", "'" + r.quantity + "' is a membrane quantity; part '" + h.text("part") +
                               "' is a solid (its quantities: " + list + ")");
      }
    } else if (q->target == QuantityTarget::node_set) {
      r.node_set = node_set_ref(h, "node_set", m);
      if (r.quantity.rfind("reaction_", 0) == 0) check_reaction_held(h, r, m);
      if (q->shells_only)
        for (int n : m.node_sets[r.node_set].nodes)
          if (!m.has_slopes(n))
            h.fail("node_set", fmt::format("'{}' is a quantity of axisymmetric_shell nodes; node {} of '{}' is on no "
                                           "shell part",
                                           r.quantity, n, h.text("node_set")));
    } else if (q->target == QuantityTarget::load) {
      const std::string& l = h.text("load");
      auto it = std::find_if(m.loads.begin(), m.loads.end(), [&](auto& x) { return x.name == l; });
      if (it == m.loads.end()) h.fail("load", "undefined load '" + l + "' " + known_names(l, names_of(m.loads), "loads"));
      r.load = static_cast<int>(it - m.loads.begin());
    } else if (q->target == QuantityTarget::contact) {
      const std::string& c = h.text("contact");
      // A pair's reverse pass (`passes: 2`) shares its name and is reported with it.
      auto it = std::find_if(m.contacts.begin(), m.contacts.end(),
                             [&](auto& x) { return x.name == c && !x.is_reverse_pass(); });
      if (it == m.contacts.end()) {
        std::vector<std::string> pairs;
        for (const auto& x : m.contacts)
          if (!x.is_reverse_pass()) pairs.push_back(x.name);
        // A rigid surface or a part given for the pair that uses it: name that pair.
        std::string using_it;
        for (const auto& x : m.contacts) {
          if (x.is_reverse_pass() || !using_it.empty()) continue;
          const bool rigid = x.rigid >= 0 && m.rigid_surfaces[x.rigid].name == c;
          const bool part = (x.part >= 0 && m.parts[x.part].name == c) || x.master_name == c;
          if (rigid || part)
            using_it = fmt::format(": '{}' is {}, not a contact pair; the pair that uses it is `contact: {}`", c,
                                   rigid ? "a rigid surface" : "a part in one", x.name);
        }
        if (!using_it.empty()) h.fail("contact", "undefined contact pair '" + c + "'" + using_it);
        h.fail("contact", "undefined contact pair '" + c + "' " + known_names(c, pairs, "contact pairs"));
      }
      r.contact = static_cast<int>(it - m.contacts.begin());
    }
    if (q->target == QuantityTarget::part) warn_edge_frame_quantity(node, r, m);
    r.reduce = q->reduce;
    // A value of the whole target (a load's pressure, a part's compressed fraction) has nothing to combine.
    const bool reducible = q->membrane || q->solid || q->contact || q->target == QuantityTarget::node_set;
    if (h.has("reduce") && !reducible)
      h.fail("reduce", fmt::format("quantity '{}' is one value of its {}, with nothing to combine: leave `reduce` out",
                                   r.quantity,
                                   q->target == QuantityTarget::none ? std::string("model")
                                                                     : std::string(target_key(q->target))));
    if (h.has("reduce")) {
      const std::string& s = h.text("reduce");
      r.reduce = s == "min" ? Reduce::min : s == "max" ? Reduce::max : s == "sum" ? Reduce::sum : Reduce::mean;
    }
    std::string suffix;
    if (r.dim != Dimension::dimensionless) {
      r.unit = h.has("unit") ? h.text("unit") : m.units.internal_unit(r.dim);
      try {
        m.units.check_unit(r.unit, r.dim);
      } catch (const std::invalid_argument& e) {
        // A unit of another dimension says so; an unknown one gets the common units of the
        // quantity's dimension, and the nearest (`kPa` for `kpa`: symbols are case-sensitive).
        const std::string why = e.what();
        h.fail("unit", why.rfind("unknown unit", 0) == 0
                           ? fmt::format("{} {}", why,
                                         known_names(r.unit, common_units(r.dim),
                                                     fmt::format("common units of {}", dimension_name(r.dim))))
                           : why);
      }
      suffix = unit_suffix(m.units, r.dim, h.has("unit") ? r.unit : "");
    } else if (h.has("unit")) {
      h.fail("unit", "quantity '" + r.quantity + "' is dimensionless");
    }
    if (h.has("name")) check_column_name(h, "name");
    r.column = (h.has("name") ? h.text("name") : r.quantity) + suffix;
    if (!columns.insert(r.column).second)
      node.fail("duplicate history column '" + r.column + "'" +
                (r.column == "time" || r.column == "step" || r.column == "increment"
                     ? std::string(" (step, increment and time are always the first three columns)")
                     : std::string(" (give one of them a `name`)")));
    m.output.history.push_back(r);
  }
}


/// What a file that is no deck looks like, from its first line (a mesh or surface given in the
/// deck's place), with where it goes instead; "" if nothing known.
std::string not_a_deck(const std::string& text) {
  std::size_t i = text.find_first_not_of(" \t\r\n");
  const std::string first = i == std::string::npos ? "" : text.substr(i, std::min(text.find('\n', i), text.size()) - i);
  const auto starts = [&](const char* s) { return first.rfind(s, 0) == 0; };
  std::string kind, where;
  if (starts("$MeshFormat")) {
    kind = "a Gmsh mesh (.msh)";
    where = "`mesh: {type: gmsh, file: wall.msh, surface: wall}`";
  } else if (starts("SetFactory") || starts("Point(") || starts("Point (") || starts("lc ") || starts("lc=") ||
             starts("//") || starts("Merge")) {
    kind = "a Gmsh script (.geo), it seems";
    where = "`mesh: {type: gmsh, file: wall.geo, surface: wall}` (run with `--allow-scripts`)";
  } else if (starts("solid ")) {
    kind = "an ASCII STL surface";
    where = "through a Gmsh script that merges it and names it, `Merge \"vessel.stl\"; Physical Surface(\"wall\") = "
            "{1};`, as `mesh: {type: gmsh, file: vessel.geo, surface: wall}` (run with `--allow-scripts`)";
  } else if (starts("<?xml") || starts("<VTKFile")) {
    kind = "a VTK XML file (a result or a surface)";
  } else if (starts("# vtk DataFile")) {
    kind = "a legacy VTK file";
  } else if (first == "ply") {
    kind = "a PLY surface";
    where = "through a Gmsh script that merges it and names it, `Merge \"vessel.ply\"; Physical Surface(\"wall\") = "
            "{1};`, as `mesh: {type: gmsh, file: vessel.geo, surface: wall}` (run with `--allow-scripts`)";
  } else if (starts("node,R_")) {
    kind = "a meridian CSV (a reference_<step>.csv)";
    where = "`mesh: {type: points, file: reference.csv}`";
  }
  if (kind.empty()) return "";
  return fmt::format(" (this file is {}, not a deck: give the YAML deck, {})", kind,
                     where.empty() ? "which names the part's mesh (user guide §3)"
                     : where.rfind("through", 0) == 0 ? "whose part reads it " + where
                                                      : "whose part names it in its mesh, " + where);
}

}  // namespace

std::vector<ComponentSpec> deck_sections() {
  return {units_spec(),     part_spec(),   solid_part_spec(), shell_part_spec(), frame_spec(),   node_set_spec(), boundary_spec(),
          load_spec(),      cylinder_spec(), polyline_spec(), contact_spec(), solver_settings_spec(),
          step_spec(),      output_spec(), history_spec()};
}

Model read_deck_text(const std::string& text, const std::string& file, const ReadOptions& options) {
  check_deck_limits(text, file);
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw yaml_syntax_error(e, text, file);
  }
  const DeckNode deck(root, file, "", {file, 1, 1, ""});
  if (!root.IsMap()) deck.fail("a deck is a YAML map with the sections units, materials, parts, steps, ..." +
                               not_a_deck(text));
  deck.expect_map_with_keys(kTopKeys);

  Model m;
  m.deck_file = file;
  if (deck.has("title")) m.title = deck["title"].as_string();
  {
    const Params u = read_params(deck.required("units", ": add the deck's unit system, e.g. `units: {length: mm, force: "
                                                        "N}`: bare numbers are then in mm and N, and stresses and "
                                                        "pressures in N/mm² = MPa"),
                                 units_spec(), m.units);
    try {
      m.units = UnitSystem(u.text("length"), "N");
    } catch (const std::invalid_argument& e) {
      u.fail("length", std::string(e.what()) + " (a length unit, e.g. mm, m, um)" +
                           did_you_mean(u.text("length"), {"m", "cm", "mm", "um", "nm"}));
    }
    try {
      m.units = UnitSystem(u.text("length"), u.text("force"));
    } catch (const std::invalid_argument& e) {
      const std::string f = u.text("force");
      const bool mass = f == "kg" || f == "g" || f == "mg" || f == "t" || f == "lb";
      u.fail("force", std::string(e.what()) + " (a force unit, e.g. N, mN, kN)" +
                          (mass ? "; '" + f + "' is a mass: forces are in newtons (1 kgf = 9.80665 N), e.g. `force: N`"
                                : did_you_mean(f, {"N", "mN", "kN", "uN"})));
    }
  }
  const DeckNode mats = deck.required(
      "materials", ": add the materials the parts name, e.g. `materials: {wall: {type: neo_hookean, mu: 100 kPa}}` (the "
                   "types and their constants are in the deck reference)");
  if (!mats.is_map() || mats.entries().empty()) mats.fail("expected a map of materials (name: {type: ..., ...})");
  for (const auto& [name, node] : mats.entries()) {
    if (!node.is_map()) node.fail("expected a map with `type` and the model's constants");
    const std::string type = node.required("type").as_string();
    auto t = material_types().find(type);
    auto st = solid_material_types().find(type);
    if (t == material_types().end() && st == solid_material_types().end()) {
      std::string list;
      for (const auto& [k, v] : material_types()) list += (list.empty() ? "" : ", ") + k;
      for (const auto& [k, v] : solid_material_types()) list += ", " + k;
      std::vector<std::string> known = keys_of(material_types());
      for (const auto& k : keys_of(solid_material_types())) known.push_back(k);
      node["type"].fail("unknown material type '" + type + "' (known: " + list + ")" + did_you_mean(type, known));
    }
    const ComponentSpec& spec = t != material_types().end() ? t->second.spec : st->second.spec;
    // A constant in another code's spelling (C10, E, ν): what it is here.
    for (const auto& entry : node.entries()) {
      const std::string& key = entry.first;
      const DeckNode& value = entry.second;
      const bool known = key == "type" || std::any_of(spec.params.begin(), spec.params.end(),
                                                      [&](const ParamSpec& q) { return q.name == key; });
      if (known) continue;
      if (const std::string hint = foreign_constant_hint(type, key); !hint.empty()) {
        std::string allowed = "type";
        for (const ParamSpec& q : spec.params) allowed += ", " + q.name;
        value.fail(fmt::format("unknown key '{}' (allowed here: {}): {}", key, allowed, hint));
      }
    }
    const Params p = read_params(node, spec, m.units, {"type"});
    if (t != material_types().end())
      m.materials[name] = t->second.make(p);
    else
      m.solid_materials[name] = st->second.make(p);
    warn_unitless_values(node, spec, m);
  }
  read_parts(deck, m, options);
  read_node_sets(deck, m);
  read_boundaries(deck, m);
  read_loads(deck, m);
  read_rigid_surfaces(deck, m);
  read_contacts(deck, m);
  const SolverSettings solver = read_solver(deck["solver"], m.units, SolverSettings{});
  read_steps(deck, m, solver);
  // An imaged thickness is one of an inverse step's imaged geometry (theory manual (13.12)).
  if (std::none_of(m.steps.begin(), m.steps.end(), [](const Step& s) { return s.inverse; }))
    for (const Part& part : m.parts)
      if (part.imaged_thickness)
        deck["parts"][part.name]["thickness_at"].fail(
            "`thickness_at: imaged` gives the wall thickness of an inverse step's imaged geometry, and this deck has no "
            "inverse step: its geometry is the reference, so give the reference thickness H as `thickness` (without "
            "`thickness_at`), or add a step of `type: inverse` first");
  read_output(deck, m);
  warn_names_used_twice_or_never(deck, m);
  // A body free to move is said at `boundary`, where the fix goes; without that section, at the
  // first step the body takes part in, where its tangent is singular.
  for (const UnheldBody& w : unheld_rigid_motions(m)) {
    SourceLocation at = deck.where();
    if (deck.has("boundary")) {
      at = deck["boundary"].where();
    } else if (const std::vector<DeckNode> steps = deck["steps"].items(); !steps.empty()) {
      int first = static_cast<int>(steps.size()) - 1;
      for (int p : w.parts) first = std::min(first, m.parts[p].enter_step);
      at = steps[first].where();
    }
    m.warnings.push_back(format_location(at, w.message));
  }
  // A frame that does not fit its surface: at the part's `frame`.
  for (const FrameMisfit& f : frame_axis_warnings(m))
    m.warnings.push_back(format_location(deck["parts"][m.parts[f.part].name]["frame"].where(), f.message));
  // A wall thicker than its part (a mesh in another length unit), or thick against its curvature:
  // at the part's `thickness`.
  for (const ThicknessMisfit& t : wall_thickness_misfits(m)) {
    const DeckNode thickness = deck["parts"][m.parts[t.part].name]["thickness"];
    if (t.impossible) thickness.fail(t.message);
    m.warnings.push_back(format_location(thickness.where(), t.message));
  }
  // Two parts that touch at nodes they do not share: at the second part.
  for (const CoincidentNodes& w : coincident_node_warnings(m))
    m.warnings.push_back(format_location(deck["parts"][m.parts[w.part_b].name].where(), w.message));
  // An axisymmetric membrane's pole whose r is free: at the part.
  for (const PoleMisfit& w : free_pole_warnings(m))
    m.warnings.push_back(format_location(deck["parts"][m.parts[w.part].name].where(), w.message));
  // A part that its boundaries hold at every node in every DOF: at the boundary holding most of it.
  for (const HeldPart& w : held_part_warnings(m))
    m.warnings.push_back(format_location(m.boundaries[w.boundary].where, w.message));
  // A boundary value that moves nodes past the model's far side or across the axis: at the value.
  for (const MotionMisfit& w : boundary_motion_warnings(m)) {
    const std::vector<DeckNode> steps = deck["steps"].items();
    const SourceLocation at = w.step < static_cast<int>(steps.size())
                                  ? steps[w.step]["set"][m.boundaries[w.boundary].name].where()
                                  : m.boundaries[w.boundary].where;
    m.warnings.push_back(format_location(at, w.message));
  }
  // A symmetry boundary that holds another DOF than the plane its nodes lie on: at the boundary.
  for (const SymmetryMisfit& s : symmetry_name_warnings(m))
    m.warnings.push_back(format_location(m.boundaries[s.boundary].where, s.message));
  m.fingerprint = deck_fingerprint(deck, m, &m.fingerprint_places);
  return m;
}

Model read_deck(const std::string& path, const ReadOptions& options) {
  return read_deck_text(read_file_bounded(path, kMaxDeckBytes, "deck"), path, options);
}

}  // namespace tunica
