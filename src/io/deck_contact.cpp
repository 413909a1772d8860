#include "io/deck_contact.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>

#include "contact/axisym_contact.hpp"
#include "io/deck_names.hpp"
#include "io/rigid_contact_side.hpp"
#include "io/unitless_values.hpp"
#include "contact/contact_search.hpp"

namespace tunica {

const ComponentSpec& cylinder_spec() {
  static const ComponentSpec s{
      "rigid_surfaces", "cylinder",
      "Axisymmetric models: a rigid cylinder r = R_c about the z axis, unbounded in z, fixed. The slave "
      "nodes of a `contact` pair are kept outside it (r ≥ R_c, e.g. a balloon on a catheter) or inside it "
      "(r ≤ R_c, e.g. a rigid tube around an artery). A slave that starts behind it (on the other side) is an "
      "error.",
      {required(one_of(text("type", "surface type"), {"cylinder", "polyline"})),
       required(positive(number("radius", Dimension::length, "radius R_c"))),
       required(one_of(text("side", "the side where the slave nodes belong"), {"outside", "inside"}))}};
  return s;
}

const ComponentSpec& polyline_spec() {
  static const ComponentSpec s{
      "rigid_surfaces", "polyline",
      "Axisymmetric models: a rigid open polyline in the (r, z) meridian plane (a surface of revolution), "
      "fixed. Its contact normal is the direction of travel turned clockwise: order the points so that "
      "the slave nodes lie on the right of the direction of travel (e.g. from larger to smaller r for a "
      "plane z = const with the slave above it). Beyond the ends of the chain there is no contact. A slave that "
      "starts behind it (on the left of the direction of travel) is an error.",
      {required(one_of(text("type", "surface type"), {"cylinder", "polyline"})),
       required(structured("points", "list", "at least 2 points `[r, z]` (lengths), e.g. `[[2 mm, 0], [0.5 mm, 0]]`"))}};
  return s;
}

const ComponentSpec& contact_spec() {
  static const ComponentSpec s{
      "contact", "",
      "Axisymmetric models: frictionless penalty contact of the nodes of a slave (an axisymmetric membrane "
      "part or a node set) with a rigid surface (`rigid`) or a deformable master (`master`: a membrane part, "
      "its meridian in node order, or an ordered node set, a chain of nodes in the listed order; exactly one "
      "of `rigid` and `master`). Each slave node s stands for its tributary reference area A_s = 2π R_s "
      "(L_left + L_right)/2 (a node on the axis, a pole: its consistent area 2π L R_next/6 per element, as a pressure load weighs it; rigid pairs: on the slave part's meridian; deformable pairs: on the slave chain "
      "itself, the part's meridian or the node set in its order) and has the energy ½ ε ⟨−g_N⟩² A_s, g_N = "
      "(signed distance to the surface) − offset; it is active when g_N < 0 (with `smoothing` δ: g_N < δ/2). A deformable master's normal is "
      "its direction of travel turned clockwise (a chain running towards +z faces +r): the slave must be on "
      "that side, or give `master_orientation: reversed` (a slave node behind the master at the reference state is an error). Slave nodes push on the master surface at "
      "their closest point (one pass: master nodes may enter the slave; `passes: 2` adds the reverse pass): by default the C¹ curve through the master's "
      "nodes (`master_surface: smooth`), or its straight segments (`faceted`). The contact pressure "
      "ε⟨−g_N⟩ is per reference area; the outputs `contact_pressure` divide the normal force ε⟨−g_N⟩ A_s by "
      "the current tributary area (`passes: 2`: both passes' normal force on the slave's nodes).",
      {required(text("slave", "name of an axisymmetric membrane part, or of a node set")),
       text("rigid", "name of a surface in `rigid_surfaces` (or give `master`)"),
       text("master", "name of an axisymmetric membrane part or of a node set: the deformable master chain "
                      "(or give `rigid`)"),
       with_default(one_of(text("master_orientation",
                                "`as_given`: the chain's order sets the normal (direction turned clockwise); "
                                "`reversed`: the opposite side"),
                           {"as_given", "reversed"}),
                    "as_given"),
       with_default(one_of(text("master_surface",
                                "deformable master: `smooth`, the C¹ curve through its nodes (chord-weighted "
                                "Catmull–Rom; no facet corners, so a flexible slave's contact pressure does not "
                                "scatter with the penalty on meshes that do not match); `faceted`, its straight "
                                "segments (node to segment)"),
                           {"smooth", "faceted"}),
                    "smooth"),
       required(positive(number("penalty", Dimension::penalty,
                                "penalty ε: contact pressure per unit penetration (the penetration is p_c/ε)"))),
       with_default(at_most(at_least(integer("passes",
                                             "deformable pairs: 1, one-pass (the slave's nodes push on the master); 2, "
                                             "two-pass: also the master's nodes push on the slave (the reverse pass, "
                                             "formed internally), each pass with half the penalty, for a slave that "
                                             "becomes the coarser mesh in contact; the outputs report the whole "
                                             "contact on the slave's nodes"),
                                     1),
                            2),
                    "1"),
       at_least(number("smoothing", Dimension::length,
                                    "δ: width of the blend that makes the contact pressure C¹ across the touch: p = "
                                    "ε (δ/2 − g_N)²/(2δ) for |g_N| < δ/2, ε⟨−g_N⟩ beyond (theory manual (9.2)). 0: "
                                    "the plain law. Where nodes at the edge of the contact zone, whose pressure is "
                                    "about zero, enter and leave at every Newton iteration (a compliant balloon "
                                    "spreading along a vessel), about 10⁻³ of the slave's element length settles "
                                    "them; the contact pressure differs from the plain law's only where it is below "
                                    "ε δ/2. Not given: the plain law until an increment fails at its smallest size "
                                    "with a chattering active set, then 10⁻³ of the slave's mean element length for "
                                    "the rest of the run (the progress log says so)"),
                             0.0),
       with_default(at_least(number("offset", Dimension::length,
                                    "c: contact starts at the distance c from the surface (e.g. half a thickness; "
                                    "two membranes: the sum of their half thicknesses)"),
                             0.0),
                    "0")}};
  return s;
}

void read_rigid_surfaces(const DeckNode& deck, Model& m) {
  if (!deck.has("rigid_surfaces")) return;
  const DeckNode sec = deck["rigid_surfaces"];
  if (m.geometry != Geometry::axisymmetric)
    sec.fail("rigid surfaces and contact need an axisymmetric model (parts with element: axisymmetric_membrane)");
  if (!sec.is_map()) sec.fail("expected a map of rigid surfaces (name: {type: cylinder|polyline, ...})");
  for (const auto& [name, node] : sec.entries()) {
    if (!node.is_map()) node.fail("expected a map with `type: cylinder` or `type: polyline`");
    const std::string type = node.required("type").as_string();
    RigidSurface r;
    r.name = name;
    r.where = node.where();
    if (type == "cylinder") {
      const Params p = read_params(node, cylinder_spec(), m.units);
      r.type = RigidSurface::Type::cylinder;
      r.cylinder.radius = p.number("radius");
      r.cylinder.side = p.text("side") == "inside" ? CylinderSide::inside : CylinderSide::outside;
    } else if (type == "polyline") {
      read_params(node, polyline_spec(), m.units);
      r.type = RigidSurface::Type::polyline;
      const DeckNode pts = node["points"];
      if (!pts.is_sequence()) pts.fail("expected a list of points [r, z]");
      const auto items = pts.items();
      if (items.size() < 2) pts.fail(fmt::format("a polyline needs at least 2 points, got {}", items.size()));
      r.polyline.points.resize(2, static_cast<Eigen::Index>(items.size()));
      for (std::size_t i = 0; i < items.size(); ++i) {
        if (!items[i].is_sequence() || items[i].items().size() != 2) items[i].fail("expected a point [r, z]");
        for (int c = 0; c < 2; ++c)
          r.polyline.points(c, static_cast<Eigen::Index>(i)) = read_quantity(items[i].items()[c], Dimension::length, m.units);
        if (i > 0 && (r.polyline.points.col(i) - r.polyline.points.col(i - 1)).norm() == 0)
          items[i].fail("a polyline point repeats the previous one (a segment of zero length)");
      }
    } else {
      node["type"].fail("unknown rigid surface type '" + type + "' (known: cylinder, polyline)" +
                        did_you_mean(type, {"cylinder", "polyline"}));
    }
    m.rigid_surfaces.push_back(std::move(r));
  }
}

namespace {

/// Reference positions (R, Z) of a chain of nodes.
Eigen::Matrix2Xd reference_chain(const Model& m, const std::vector<int>& nodes) {
  Eigen::Matrix2Xd chain(2, static_cast<Eigen::Index>(nodes.size()));
  for (std::size_t i = 0; i < nodes.size(); ++i) chain.col(static_cast<Eigen::Index>(i)) = m.X[nodes[i]].head<2>();
  return chain;
}

/// "(the parts and node sets are: ...)" for an undefined slave or master.
std::string part_or_set_names(const std::string& name, const Model& m) {
  std::vector<std::string> known = names_of(m.parts);
  for (const auto& s : m.node_sets) known.push_back(s.name);
  return known_names(name, known, "parts and node sets");
}

/// The slave of a rigid pair: a part (all its nodes) or a node set within one part, in meridian
/// order, with the tributary areas of the part's meridian.
void read_rigid_slave(const Params& p, ContactPair& c, const Model& m) {
  const std::string& slave = p.text("slave");
  std::vector<int> wanted;
  c.part = m.find_part(slave);
  if (c.part < 0) {
    const int s = m.find_node_set(slave);
    if (s < 0) p.fail("slave", "undefined part or node set '" + slave + "' " + part_or_set_names(slave, m));
    wanted = m.node_sets[s].nodes;
    if (wanted.empty()) p.fail("slave", "node set '" + slave + "' is empty");
    for (std::size_t k = 0; k < m.parts.size() && c.part < 0; ++k)
      if (std::find(m.parts[k].nodes.begin(), m.parts[k].nodes.end(), wanted.front()) != m.parts[k].nodes.end())
        c.part = static_cast<int>(k);
  }
  if (m.parts[c.part].is_solid())
    p.fail("slave", "the slave of a rigid contact pair must be (on) an axisymmetric membrane part; '" + slave +
                        "' is (on) a solid part");
  const Part& part = m.parts[c.part];
  if (wanted.empty()) wanted = part.nodes;
  const Eigen::VectorXd areas = slave_tributary_areas(reference_chain(m, part.nodes));
  for (int n : wanted)
    if (std::find(part.nodes.begin(), part.nodes.end(), n) == part.nodes.end())
      p.fail("slave", "the nodes of node set '" + slave + "' are not all on one part");
  c.area_chain = part.nodes;
  for (std::size_t i = 0; i < part.nodes.size(); ++i)  // meridian order, no duplicates
    if (std::find(wanted.begin(), wanted.end(), part.nodes[i]) != wanted.end()) {
      c.nodes.push_back(part.nodes[i]);
      c.areas.push_back(areas(static_cast<Eigen::Index>(i)));
      c.area_index.push_back(static_cast<int>(i));
    }
}

/// A chain of nodes named by `key` (`slave` or `master` of a deformable pair): a membrane part's
/// meridian or a node set in its order; ≥ 2 nodes, no node twice, no segment of zero length.
std::vector<int> read_chain(const Params& p, const std::string& key, const Model& m, int* part_index) {
  const std::string& name = p.text(key);
  std::vector<int> chain;
  const int part = m.find_part(name);
  if (part_index) *part_index = part;
  if (part >= 0) {
    if (m.parts[part].element != "axisymmetric_membrane" && !m.parts[part].is_shell())
      p.fail(key, "part '" + name + "' is not an axisymmetric membrane or shell (its nodes are no chain): name an ordered node set "
                  "along its boundary");
    chain = m.parts[part].nodes;
  } else {
    const int s = m.find_node_set(name);
    if (s < 0) p.fail(key, "undefined part or node set '" + name + "' " + part_or_set_names(name, m));
    chain = m.node_sets[s].nodes;
  }
  if (chain.size() < 2)
    p.fail(key, fmt::format("the {} chain '{}' has {} node{}; it needs at least 2 (a chain of segments)", key, name,
                            chain.size(), chain.size() == 1 ? "" : "s"));
  for (std::size_t i = 0; i + 1 < chain.size(); ++i)
    if ((m.X[chain[i + 1]] - m.X[chain[i]]).norm() == 0)
      p.fail(key, fmt::format("segment {} of the {} chain '{}' has zero length (its nodes {} and {} coincide)", i, key,
                              name, i, i + 1));
  std::vector<std::pair<int, int>> sorted;  // (node, position): O(n log n) for long chains
  for (std::size_t i = 0; i < chain.size(); ++i) sorted.emplace_back(chain[i], static_cast<int>(i));
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t i = 0; i + 1 < sorted.size(); ++i)
    if (sorted[i].first == sorted[i + 1].first)
      p.fail(key, fmt::format("the {} chain '{}' lists a node twice (at positions {} and {})", key, name,
                              sorted[i].second, sorted[i + 1].second));
  return chain;
}

/// The first index of `nodes` (global numbers) to lie behind `chain` at the reference
/// state (signed distance < 0 to its nearest feature; contact_search.hpp), with that distance; −1 if none.
std::pair<int, double> first_behind(const Model& m, const std::vector<int>& nodes, const std::vector<int>& chain) {
  const Eigen::Matrix2Xd master = reference_chain(m, chain);
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    const ChainProjection w = project_on_chain(m.X[nodes[k]].head<2>(), master,
                                               std::numeric_limits<double>::infinity(), kMasterEndTolerance);
    if (w.feature != ChainFeature::none && w.signed_distance < 0) return {static_cast<int>(k), w.signed_distance};
  }
  return {-1, 0.0};
}

/// Tributary areas of a slave chain on the chain itself, in its order.
void set_chain_areas(ContactPair& c, const Model& m) {
  c.area_chain = c.nodes;
  const Eigen::VectorXd areas = slave_tributary_areas(reference_chain(m, c.nodes));
  for (std::size_t i = 0; i < c.nodes.size(); ++i) {
    c.areas.push_back(areas(static_cast<Eigen::Index>(i)));
    c.area_index.push_back(static_cast<int>(i));
  }
}

/// The reverse pass of the deformable pair `c` (`passes: 2`; theory manual §9.1, (9.9)): the
/// master's chain becomes the slave, with its own tributary areas, and the slave's chain the
/// master, ordered so that its normal faces the former master — the opposite of the master's normal
/// where the slave's nodes project on it at the reference state. Each pass gets half the penalty.
ContactPair reverse_pass(const Params& p, ContactPair& c, int master_part, const Model& m) {
  ContactPair r;
  r.name = c.name;
  r.where = c.where;
  r.part = master_part;
  r.nodes = c.master;
  r.master = c.nodes;
  r.master_name = p.text("slave");
  r.master_surface = c.master_surface;
  c.law.penalty *= 0.5;
  r.law = c.law;
  r.auto_smoothing = c.auto_smoothing;
  set_chain_areas(r, m);
  // Orientation: Σ over the slave's nodes that face a master feature of n_slave·n_master (the
  // slave chain's normal in its order, (t_z, −t_r) with t the chord of its neighbours) < 0 keeps it.
  const Eigen::Matrix2Xd master = reference_chain(m, c.master), slave = reference_chain(m, c.nodes);
  const Eigen::Index ns = slave.cols();
  double facing = 0;
  for (Eigen::Index k = 0; k < ns; ++k) {
    const ChainProjection w = project_on_chain(slave.col(k), master, std::numeric_limits<double>::infinity(),
                                               kMasterEndTolerance);
    if (w.feature == ChainFeature::none) continue;
    const Eigen::Vector2d nm = segment_normal(master.col(w.segment), master.col(w.segment + 1));
    const Eigen::Vector2d t = slave.col(std::min(k + 1, ns - 1)) - slave.col(std::max<Eigen::Index>(k - 1, 0));
    facing += Eigen::Vector2d(t(1), -t(0)).normalized().dot(nm);
  }
  if (facing == 0)
    p.fail("passes", "`passes: 2`: no node of the slave '" + p.text("slave") + "' faces the master '" + c.master_name +
                         "' at the reference state, so the side of the reverse pass (the master's nodes against the "
                         "slave) cannot be told; use `passes: 1`");
  if (facing > 0) std::reverse(r.master.begin(), r.master.end());
  if (const auto [k, s] = first_behind(m, r.nodes, r.master); k >= 0)
    p.fail("passes", fmt::format("`passes: 2`: master node {} of '{}' lies behind the slave '{}' (signed distance {:g} "
                                 "{} at the reference state), so the reverse pass would push it through the slave: "
                                 "name as master only the nodes that face the slave, or use `passes: 1`",
                                 k, c.master_name, p.text("slave"), s, m.units.display_unit(Dimension::length)));
  return r;
}

/// The slave and master of a deformable pair.
void read_deformable_pair(const DeckNode& node, const Params& p, ContactPair& c, const Model& m, int* master_part) {
  c.nodes = read_chain(p, "slave", m, &c.part);
  c.master = read_chain(p, "master", m, master_part);
  c.master_name = p.text("master");
  if (p.text("slave") == c.master_name)
    p.fail("master", "the master is the slave '" + c.master_name + "' (self-contact is not supported)");
  std::vector<int> slaves = c.nodes;
  std::sort(slaves.begin(), slaves.end());
  for (std::size_t i = 0; i < c.master.size(); ++i)
    if (std::binary_search(slaves.begin(), slaves.end(), c.master[i]))
      p.fail("master", fmt::format("the master '{}' and the slave '{}' share a node (master node {}); self-contact is "
                                   "not supported",
                                   c.master_name, p.text("slave"), i));
  if (p.text("master_orientation") == "reversed") std::reverse(c.master.begin(), c.master.end());
  // The side: at the reference state no slave node may lie behind the master (signed distance
  // s < 0 to the nearest feature): it would count as penetrated by s − c from the first iteration
  // and be pushed through the master. Almost always the orientation is the wrong way round.
  if (const auto [k, s] = first_behind(m, c.nodes, c.master); k >= 0)
    p.fail(node.has("master_orientation") ? "master_orientation" : "master",
           fmt::format("slave node {} of '{}' lies behind the master '{}' (signed distance {:g} {} at the reference "
                       "state; the normal is the master's direction turned clockwise): reverse "
                       "`master_orientation`, or name only the slave nodes that face the master",
                       k, p.text("slave"), c.master_name, s, m.units.display_unit(Dimension::length)));
  const Eigen::Matrix2Xd master = reference_chain(m, c.master);
  std::vector<int> order(c.nodes.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = static_cast<int>(k);
  check_contact_offset(
      p, c, m,
      [&](const Eigen::Vector2d& x, double& s) {
        const ChainProjection w =
            project_on_chain(x, master, std::numeric_limits<double>::infinity(), kMasterEndTolerance);
        s = w.signed_distance;
        return w.feature != ChainFeature::none;
      },
      c.nodes, order);
  set_chain_areas(c, m);
}

/// The smoothing width of pair `c` (theory manual (9.2)), refused beyond a tenth of its slave
/// chain's mean reference element length: the blend would press nodes from δ/2 away and change the
/// contact pressure wherever it is below εδ/2.
double read_smoothing(const Params& p, const ContactPair& c, const Model& m) {
  const double delta = p.has("smoothing") ? p.number("smoothing") : 0.0;
  if (!(delta > 0) || c.area_chain.size() < 2) return delta;
  double length = 0;
  for (std::size_t i = 0; i + 1 < c.area_chain.size(); ++i)
    length += (m.X[c.area_chain[i + 1]] - m.X[c.area_chain[i]]).norm();
  length /= static_cast<double>(c.area_chain.size() - 1);
  if (delta <= 0.1 * length) return delta;
  const std::string lu = m.units.display_unit(Dimension::length);
  const auto in = [&](double v) { return m.units.from_internal(v, lu, Dimension::length); };
  p.fail("smoothing",
         fmt::format("contact pair '{}': the smoothing, {:.4g} {}, is more than a tenth of the slave's mean element "
                     "length ({:.4g} {}): its nodes would be pressed from δ/2 = {:.4g} {} off the surface, and the "
                     "contact pressure would differ from the penalty law's wherever it is below εδ/2 = {:.4g} kPa. "
                     "Give about 10⁻³ of the element length, `smoothing: {:.2g} {}` (is the unit the deck's?)",
                     c.name, in(delta), lu, in(length), lu, in(0.5 * delta), lu,
                     m.units.from_internal(0.5 * c.law.penalty * delta, "kPa", Dimension::pressure), in(1e-3 * length),
                     lu));
  return delta;
}

}  // namespace

void read_contacts(const DeckNode& deck, Model& m) {
  if (!deck.has("contact")) return;
  const DeckNode sec = deck["contact"];
  if (m.geometry != Geometry::axisymmetric)
    sec.fail("rigid surfaces and contact need an axisymmetric model (parts with element: axisymmetric_membrane)");
  if (!sec.is_map())
    sec.fail("expected a map of contact pairs (name: {slave: ..., rigid: ... or master: ..., penalty: ...})");
  for (const auto& [name, node] : sec.entries()) {
    const Params p = read_params(node, contact_spec(), m.units);
    warn_unitless_values(node, contact_spec(), m);
    ContactPair c;
    c.name = name;
    c.where = node.where();
    c.law.penalty = p.number("penalty");
    c.law.offset = p.number("offset");
    c.auto_smoothing = !node.has("smoothing");
    const bool rigid = node.has("rigid"), master = node.has("master");
    if (rigid && master)
      p.fail("master", "a contact pair has either `rigid: <surface>` or `master: <part or node set>`, not both");
    if (!rigid && !master)
      node.fail("a contact pair needs `rigid: <surface>` (a rigid tool) or `master: <part or node set>` (a deformable "
                "master)");
    if (rigid) {
      if (node.has("master_surface"))
        p.fail("master_surface", "only a deformable `master` has a surface choice (a rigid polyline is its segments)");
      if (node.has("master_orientation"))
        p.fail("master_orientation", "only a deformable `master` has an orientation (a rigid polyline's is its point order)");
      if (p.integer("passes") != 1)
        p.fail("passes", "a rigid pair has one pass: a rigid surface has no nodes to push back on the slave (`passes: 2` "
                         "needs a deformable `master`)");
      const std::string& r = p.text("rigid");
      auto it = std::find_if(m.rigid_surfaces.begin(), m.rigid_surfaces.end(), [&](auto& x) { return x.name == r; });
      if (it == m.rigid_surfaces.end())
        p.fail("rigid", "undefined rigid surface '" + r + "' " + known_names(r, names_of(m.rigid_surfaces), "rigid surfaces"));
      c.rigid = static_cast<int>(it - m.rigid_surfaces.begin());
      read_rigid_slave(p, c, m);
      c.law.smoothing = read_smoothing(p, c, m);
      check_rigid_side(p, c, m);
      const RigidSurface& surface = m.rigid_surfaces[c.rigid];
      check_contact_offset(
          p, c, m, [&](const Eigen::Vector2d& x, double& s) { return rigid_signed_distance(surface, x, s); },
          m.parts[c.part].nodes, c.area_index);
    } else {
      int master_part = -1;
      read_deformable_pair(node, p, c, m, &master_part);
      c.law.smoothing = read_smoothing(p, c, m);
      c.master_surface = p.text("master_surface") == "faceted" ? ContactPair::MasterSurface::faceted
                                                                : ContactPair::MasterSurface::smooth;
      if (p.integer("passes") == 2) {
        ContactPair r = reverse_pass(p, c, master_part, m);
        c.reverse = static_cast<int>(m.contacts.size()) + 1;
        r.reverse_of = static_cast<int>(m.contacts.size());
        m.contacts.push_back(std::move(c));
        m.contacts.push_back(std::move(r));
        continue;
      }
    }
    m.contacts.push_back(std::move(c));
  }
}

}  // namespace tunica
