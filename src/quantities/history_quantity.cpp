#include "quantities/history_quantity.hpp"

#include "elements/membrane_compression.hpp"

#include <algorithm>
#include <cctype>
#include <map>
#include <stdexcept>

namespace tunica {

namespace {

using Q = HistoryQuantity;

/// A quantity's name, target, dimension and meaning; the rest set by the caller.
Q quantity(std::string name, QuantityTarget target, Dimension dim, std::string doc) {
  Q q;
  q.name = std::move(name);
  q.target = target;
  q.dim = dim;
  q.doc = std::move(doc);
  return q;
}
using T = QuantityTarget;

/// The DOF of a node along the named component ("r", "x", "z", ...) of the model's DOF names.
int dof_of(const Model& m, int node, const std::string& dof) {
  const auto names = m.dof_names();
  const auto c = std::find(names.begin(), names.end(), dof) - names.begin();
  if (c >= static_cast<long>(names.size())) throw std::logic_error("no DOF " + dof + " in this model");
  return m.dofs_per_node() * node + static_cast<int>(c);
}

/// position_<dof>, displacement_<dof>, reaction_<dof> (theory manual §4: reactions are R on prescribed DOFs).
Q node_dof(const std::string& what, const std::string& dof, Dimension dim, std::string doc) {
  Q q = quantity(what + "_" + dof, T::node_set, dim, std::move(doc));
  if (dof == "r") q.geometry = Geometry::axisymmetric;
  if (dof == "x" || dof == "y") q.geometry = Geometry::three_d;
  if (what == "reaction") q.reduce = Reduce::sum;
  q.at = [what, dof](const QuantityState& s, int node) {
    const Model& m = s.system.model();
    const int d = dof_of(m, node, dof);
    if (what == "position") return m.X[node](d - m.dofs_per_node() * node) + s.u(d);
    if (what == "displacement") return s.u(d);
    return s.reactions(d);
  };
  return q;
}

/// slope_<r|z> (x′ = X′ + u′) and reaction_slope_<r|z> of shell nodes (theory manual §11).
Q node_slope(bool reaction, int c, Dimension dim, std::string doc) {
  Q q = quantity(std::string(reaction ? "reaction_" : "") + "slope_" + (c == 0 ? "r" : "z"), T::node_set, dim, std::move(doc));
  if (c == 0) q.geometry = Geometry::axisymmetric;
  q.shells_only = true;
  if (reaction) q.reduce = Reduce::sum;
  q.at = [reaction, c](const QuantityState& s, int node) {
    const Model& m = s.system.model();
    const int d = m.node_dof(node, m.dofs_per_node() + c);
    return reaction ? s.reactions(d) : m.slope_ref[node](c) + s.u(d);
  };
  return q;
}

/// A quantity of the Gauss points of membrane and shell parts.
Q membrane(std::string name, Dimension dim, std::string doc, std::function<double(const MembranePoint&)> f,
           bool shells_only = false) {
  Q q = quantity(std::move(name), T::part, dim, std::move(doc));
  q.membrane = std::move(f);
  q.shells_only = shells_only;
  return q;
}

/// A quantity of axisymmetric parts in cylindrical axes: membranes from their Cauchy tensor in the
/// meridian plane θ = 0 (x = r, y = hoop, z = z), solids from their points.
Q cylindrical(std::string name, Dimension dim, std::string doc, std::function<double(const Eigen::Matrix3d&)> on_membrane,
              std::function<double(const SolidPoint&)> on_solid) {
  Q q = quantity(std::move(name), T::part, dim, std::move(doc));
  q.geometry = Geometry::axisymmetric;
  q.membrane = [f = std::move(on_membrane)](const MembranePoint& p) { return f(p.cauchy); };
  q.solid = std::move(on_solid);
  return q;
}

Q contact(std::string name, Dimension dim, Reduce reduce, std::string doc, std::function<double(const ContactNodeState&)> f) {
  Q q = quantity(std::move(name), T::contact, dim, std::move(doc));
  q.reduce = reduce;
  q.contact = std::move(f);
  return q;
}

std::vector<Q> make_table() {
  const Dimension none = Dimension::dimensionless, stress = Dimension::pressure;
  std::vector<Q> t;
  {
    Q q = quantity("time", T::none, none, "analysis time: step number − 1 + fraction of the step done (always the third column of history.csv; a copy needs a `name`)");
    q.global = [](const QuantityState& s) { return s.time; };
    t.push_back(q);
  }
  {
    Q q = quantity("pressure", T::load, Dimension::pressure, "current magnitude of a pressure load");
    q.at = [](const QuantityState& s, int l) { return s.loads.pressure[l]; };
    t.push_back(q);
    Q v = quantity("volume", T::load, Dimension::volume, "enclosed volume of the load's surface (see `loads`)");
    v.at = [](const QuantityState& s, int l) { return s.loads.volume[l]; };
    t.push_back(v);
  }
  t.push_back(membrane("lambda_1", none, "stretch in direction 1 (axisymmetric: hoop, λθ = r/R), √C11",
                       [](const MembranePoint& p) { return p.lambda(0); }));
  t.push_back(membrane("lambda_2", none, "stretch in direction 2 (axisymmetric: meridian, λs = ℓ/L), √C22",
                       [](const MembranePoint& p) { return p.lambda(1); }));
  t.push_back(membrane("lambda_3", none, "thickness stretch λ3 = 1/√det C", [](const MembranePoint& p) { return p.lambda(2); }));
  t.push_back(membrane("E_1", none, "Green–Lagrange strain E11 = ½(C11 − 1)", [](const MembranePoint& p) { return p.E(0); }));
  t.push_back(membrane("E_2", none, "Green–Lagrange strain E22 = ½(C22 − 1)", [](const MembranePoint& p) { return p.E(1); }));
  t.push_back(membrane("E_12", none, "Green–Lagrange shear strain E12 = ½ C12 (0 in axisymmetry)",
                       [](const MembranePoint& p) { return p.E(2); }));
  t.push_back(membrane("S_1", stress, "2nd Piola–Kirchhoff stress S11", [](const MembranePoint& p) { return p.S(0); }));
  t.push_back(membrane("S_2", stress, "2nd Piola–Kirchhoff stress S22", [](const MembranePoint& p) { return p.S(1); }));
  t.push_back(membrane("S_12", stress, "2nd Piola–Kirchhoff shear stress S12", [](const MembranePoint& p) { return p.S(2); }));
  t.push_back(membrane("sigma_1", stress, "Cauchy stress along the convected direction 1 (no shear: λ1² S11)",
                       [](const MembranePoint& p) { return p.sigma(0); }));
  t.push_back(membrane("sigma_2", stress, "Cauchy stress along the convected direction 2 (no shear: λ2² S22)",
                       [](const MembranePoint& p) { return p.sigma(1); }));
  t.push_back(membrane("sigma_max", stress, "maximum in-plane principal Cauchy stress",
                       [](const MembranePoint& p) { return p.sigma_principal(0); }));
  t.push_back(membrane("sigma_min", stress, "minimum in-plane principal Cauchy stress",
                       [](const MembranePoint& p) { return p.sigma_principal(1); }));
  {
    Q q = quantity("compressed_fraction", T::part, none,
                   "fraction of the part's reference membrane volume (area, for a uniform thickness) whose minimum "
                   "in-plane principal Cauchy stress is negative (below −1 % of the part's largest principal "
                   "stress, so that the stress error of a coarse mesh is not compression): where a membrane would wrinkle (elements/membrane_compression.hpp); `reduce` does not apply");
    q.membrane_whole = [](const std::vector<MembranePoint>& pts) { return compressed_fraction(pts); };
    t.push_back(q);
  }
  t.push_back(membrane("thickness", Dimension::length, "current thickness h = λ3 H",
                       [](const MembranePoint& p) { return p.thickness; }));
  t.push_back(membrane("reference_thickness", Dimension::length,
                       "membranes: reference thickness H (the part's `thickness`, or with `thickness_at: imaged` "
                       "h λ₁λ₂ from the inverse step, theory manual (13.12))",
                       [](const MembranePoint& p) { return p.reference_thickness; }));
  {
    Q q = membrane("radius", Dimension::length, "current distance of the Gauss points from the z axis",
                   [](const MembranePoint& p) { return p.r; });
    q.solid = [](const SolidPoint& p) { return p.r; };
    t.push_back(q);
  }
  t.push_back(membrane("M_1", Dimension::force,
                       "axisymmetric shells: hoop bending moment per unit length ∫σ_θ η dη (positive: the side of n in tension)",
                       [](const MembranePoint& p) { return p.moment(0); }, true));
  t.push_back(membrane("M_2", Dimension::force, "axisymmetric shells: meridional bending moment per unit length ∫σ_s η dη",
                       [](const MembranePoint& p) { return p.moment(1); }, true));
  t.push_back(membrane("sigma_1_outer", stress,
                       "axisymmetric shells: hoop stress on the outer surface (side n), N/h + 6M/h² (σ_1 is N/h on shells)",
                       [](const MembranePoint& p) { return p.sigma_outer(0); }, true));
  t.push_back(membrane("sigma_1_inner", stress, "axisymmetric shells: hoop stress on the inner surface, N/h − 6M/h²",
                       [](const MembranePoint& p) { return p.sigma_inner(0); }, true));
  t.push_back(membrane("sigma_2_outer", stress, "axisymmetric shells: meridional stress on the outer surface, N/h + 6M/h²",
                       [](const MembranePoint& p) { return p.sigma_outer(1); }, true));
  t.push_back(membrane("sigma_2_inner", stress, "axisymmetric shells: meridional stress on the inner surface, N/h − 6M/h²",
                       [](const MembranePoint& p) { return p.sigma_inner(1); }, true));
  t.push_back(cylindrical("sigma_rr", stress,
                          "axisymmetric parts: Cauchy stress σ_rr in cylindrical axes (membranes: of σ = σ_ss t⊗t + σ_θθ "
                          "e_θ⊗e_θ, t the meridian tangent)",
                          [](const Eigen::Matrix3d& c) { return c(0, 0); }, [](const SolidPoint& p) { return p.sigma(0); }));
  t.push_back(cylindrical("sigma_thetatheta", stress, "axisymmetric parts: hoop Cauchy stress σ_θθ",
                          [](const Eigen::Matrix3d& c) { return c(1, 1); }, [](const SolidPoint& p) { return p.sigma(2); }));
  t.push_back(cylindrical("sigma_zz", stress, "axisymmetric parts: axial Cauchy stress σ_zz (a tube's meridional stress)",
                          [](const Eigen::Matrix3d& c) { return c(2, 2); }, [](const SolidPoint& p) { return p.sigma(1); }));
  t.push_back(cylindrical("sigma_rz", stress, "axisymmetric parts: Cauchy shear stress σ_rz",
                          [](const Eigen::Matrix3d& c) { return c(0, 2); }, [](const SolidPoint& p) { return p.sigma(3); }));
  t.push_back(cylindrical(
      "hydrostatic_pressure", stress,
      "axisymmetric parts: hydrostatic pressure −tr σ/3 (positive in compression; mean-dilatation solids: −U'(θ), constant per element)",
      [](const Eigen::Matrix3d& c) { return -c.trace() / 3.0; },
      [](const SolidPoint& p) { return -(p.sigma(0) + p.sigma(1) + p.sigma(2)) / 3.0; }));
  t.push_back(cylindrical("volume_ratio", none, "axisymmetric parts: J = det F (1 for the incompressible membranes)",
                          [](const Eigen::Matrix3d&) { return 1.0; }, [](const SolidPoint& p) { return p.J; }));
  t.push_back(node_dof("position", "r", Dimension::length, "axisymmetric: current r of the nodes"));
  t.push_back(node_dof("position", "x", Dimension::length, "3-D: current x of the nodes"));
  t.push_back(node_dof("position", "y", Dimension::length, "3-D: current y of the nodes"));
  t.push_back(node_dof("position", "z", Dimension::length, "current z of the nodes"));
  t.push_back(node_dof("displacement", "r", Dimension::length, "axisymmetric: displacement u_r of the nodes"));
  t.push_back(node_dof("displacement", "x", Dimension::length, "3-D: displacement u_x of the nodes"));
  t.push_back(node_dof("displacement", "y", Dimension::length, "3-D: displacement u_y of the nodes"));
  t.push_back(node_dof("displacement", "z", Dimension::length, "displacement u_z of the nodes"));
  t.push_back(node_dof("reaction", "r", Dimension::force, "axisymmetric: reaction on prescribed r DOFs (whole circumference)"));
  t.push_back(node_dof("reaction", "x", Dimension::force, "3-D: reaction force on prescribed x DOFs"));
  t.push_back(node_dof("reaction", "y", Dimension::force, "3-D: reaction force on prescribed y DOFs"));
  t.push_back(node_dof("reaction", "z", Dimension::force,
                       "reaction force on prescribed z DOFs (axisymmetric: whole circumference)"));
  t.push_back(node_slope(false, 0, none,
                         "axisymmetric shells: meridian slope r′ = ∂r/∂S of the nodes (S the reference arc length; the r "
                         "component of the unit tangent times the meridional stretch)"));
  t.push_back(node_slope(false, 1, none, "axisymmetric shells: meridian slope z′ = ∂z/∂S of the nodes"));
  t.push_back(node_slope(true, 0, Dimension::moment,
                         "axisymmetric shells: reaction conjugate to prescribed slope_r DOFs, the clamping moment on the "
                         "whole circumference (a clamped tube end of radius R: 2πR M_s; default reduce: sum)"));
  t.push_back(node_slope(true, 1, Dimension::moment,
                         "axisymmetric shells: reaction conjugate to prescribed slope_z DOFs (whole circumference; default "
                         "reduce: sum)"));
  t.push_back(contact("contact_pressure", Dimension::pressure, Reduce::max,
                      "contact pressure at the slave nodes of a contact pair: normal force ε⟨−g_N⟩ A_s over the current "
                      "tributary area; `passes: 2`, both passes' normal force on the node (default reduce: max)",
                      [](const ContactNodeState& c) { return c.pressure; }));
  t.push_back(contact("contact_force", Dimension::force, Reduce::sum,
                      "normal contact force ε⟨−g_N⟩ A_s of the slave nodes, whole circumference; `passes: 2`, plus the "
                      "reverse pass's force on them (default reduce: sum, the total of both passes)",
                      [](const ContactNodeState& c) { return c.force; }));
  t.push_back(contact("contact_penetration", Dimension::length, Reduce::max,
                      "penetration ⟨−g_N⟩ of the slave nodes into the master (0 off contact; g_N = distance − offset; "
                      "`passes: 2`: of the first pass; default reduce: max)",
                      [](const ContactNodeState& c) { return std::max(0.0, -c.point.gap); }));  // +0, never −0
  return t;
}

}  // namespace

const char* target_key(QuantityTarget t) {
  switch (t) {
    case QuantityTarget::part: return "part";
    case QuantityTarget::node_set: return "node_set";
    case QuantityTarget::load: return "load";
    case QuantityTarget::contact: return "contact";
    case QuantityTarget::none: break;
  }
  return "";
}

const std::vector<HistoryQuantity>& history_quantities() {
  static const std::vector<HistoryQuantity> table = make_table();
  return table;
}

const HistoryQuantity* find_history_quantity(const std::string& name) {
  static const std::map<std::string, const HistoryQuantity*> index = [] {
    std::map<std::string, const HistoryQuantity*> i;
    for (const auto& q : history_quantities()) i.emplace(q.name, &q);
    return i;
  }();
  const auto it = index.find(name);
  return it == index.end() ? nullptr : it->second;
}

namespace {

/// The direction a usual name of it stands for: 1 (circumferential), 2 (axial, meridional), 3
/// (thickness: only with `thickness`), 0 for none. `name` is in lower case.
int direction_of_word(const std::string& name, bool thickness) {
  static const std::map<std::string, int> words = {
      {"1", 1}, {"theta", 1}, {"th", 1}, {"t", 1}, {"\xce\xb8", 1}, {"circ", 1}, {"circumferential", 1},
      {"circumference", 1}, {"hoop", 1}, {"c", 1},
      {"2", 2}, {"z", 2}, {"axial", 2}, {"ax", 2}, {"long", 2}, {"longitudinal", 2}, {"meridional", 2},
      {"meridian", 2}, {"mer", 2}, {"s", 2},
      {"3", 3}, {"r", 3}, {"radial", 3}, {"rad", 3}, {"thickness", 3}, {"thick", 3}, {"n", 3}, {"normal", 3}};
  const auto it = words.find(name);
  if (it == words.end() || (it->second == 3 && !thickness)) return 0;
  return it->second;
}

/// The direction(s) of a suffix: 1, 2 or 3 for one direction (or one written twice: zz,
/// theta_theta), 12 for the two in-plane directions (theta_z, zt), 0 for none.
int directions_of_suffix(const std::string& suffix, bool thickness) {
  if (const int d = direction_of_word(suffix, thickness)) return d;
  for (std::size_t cut = 1; cut < suffix.size(); ++cut) {
    std::string a = suffix.substr(0, cut), b = suffix.substr(cut);
    if (b.front() == '_') b.erase(0, 1);
    if (a.empty() || b.empty()) continue;
    const int da = direction_of_word(a, thickness), db = direction_of_word(b, thickness);
    if (da == 0 || db == 0) continue;
    if (da == db) return da;
    if (da + db == 3) return 12;
  }
  return 0;
}

}  // namespace

std::string direction_name_suggestion(const std::string& name, Geometry geometry) {
  // The families of quantities with a direction in the part's frame, by the names people write for them.
  static const std::vector<std::pair<std::string, std::string>> families = {
      {"lambda", "lambda"}, {"stretch", "lambda"}, {"e", "E"},     {"strain", "E"},     {"s", "S"},
      {"pk2", "S"},         {"sigma", "sigma"},    {"cauchy", "sigma"}, {"stress", "sigma"}, {"m", "M"},
      {"moment", "M"}};
  std::string lower = name;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
  std::string surface;  // a shell's outer or inner surface, as sigma_1_outer
  for (const char* side : {"_outer", "_inner"})
    if (lower.size() > 6 && lower.compare(lower.size() - 6, 6, side) == 0) {
      surface = side;
      lower.erase(lower.size() - 6);
    }
  for (const auto& [prefix, family] : families) {
    if (lower.size() <= prefix.size() + 1 || lower.compare(0, prefix.size() + 1, prefix + "_") != 0) continue;
    const int d = directions_of_suffix(lower.substr(prefix.size() + 1), family == "lambda");
    if (d == 0) continue;
    const std::string meant = family + "_" + std::to_string(d) + surface;
    if (meant == name || !find_history_quantity(meant)) continue;
    const bool axi = geometry == Geometry::axisymmetric;
    std::string what;
    if (d == 1)
      what = axi ? "direction 1: the hoop (circumferential) direction"
                 : "direction 1 of the part's frame: circumferential in a cylindrical frame";
    else if (d == 2)
      what = axi ? "direction 2: the meridian, axial along a tube"
                 : "direction 2 of the part's frame: axial in a cylindrical frame";
    else if (d == 3)
      what = "direction 3: the thickness, radial in a tube";
    else
      what = axi ? "the shear of directions 1 and 2, hoop and meridian (0 in axisymmetry)"
                 : "the shear of directions 1 and 2 of the part's frame: circumferential and axial in a cylindrical "
                   "frame";
    return "; did you mean '" + meant + "' (" + what + ")?";
  }
  return "";
}

}  // namespace tunica
