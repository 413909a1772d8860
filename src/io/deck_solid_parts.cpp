#include "io/deck_solid_parts.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "io/deck_limits.hpp"
#include "mesh/solid_grid.hpp"

namespace tunica {

const ComponentSpec& solid_part_spec() {
  static const ComponentSpec s{
      "parts", "axisymmetric_solid",
      "An axisymmetric finite-strain solid (selected by `element: axisymmetric_solid`): 4-node "
      "quadrilaterals in the (r, z) plane (theory manual §10), e.g. the plaque of an angioplasty model. It gets "
      "the ordered node sets `<part>.inner`, `<part>.outer` (nodes in increasing z), `<part>.bottom`, "
      "`<part>.top` (increasing r) and `<part>.all`. Its material must be a solid material.",
      {required(one_of(text("element", "element type"),
                       {"axisymmetric_membrane", "membrane", "axisymmetric_solid", "axisymmetric_shell"})),
       required(text("material", "name of a solid material in `materials` (e.g. `type: neo_hookean_solid`)")),
       with_default(one_of(text("formulation",
                                "mean_dilatation: the Q1/P0 element (element-constant pressure, no volumetric "
                                "locking); displacement: the plain Q1 element (locks when nearly incompressible)"),
                           {"mean_dilatation", "displacement"}),
                    "mean_dilatation"),
       required(structured("mesh", "map", "`type: grid` and its keys (see Meshes)")),
       text("enter_step", "name of the step from which the part is assembled, stress free in its deck geometry "
                          "(default: from the start; see the user guide)")}};
  return s;
}

const ComponentSpec& solid_grid_spec() {
  static const ComponentSpec s{
      "parts.mesh", "grid",
      "Axisymmetric solid parts: a structured grid of 4-node quadrilaterals in the (r, z) plane between an "
      "inner and an outer meridian profile over z0 ≤ z ≤ z1, `elements_r` × `elements_z` elements, nodes "
      "equally spaced in z and, on each row, in r. A profile is a radius (`0.63 mm`), a polyline "
      "`[[r, z], ...]` (z strictly increasing, covering [z0, z1], interpolated linearly at the node rows) or a "
      "symmetric bump `{radius_ends, radius_centre, shape: cosine|circular}`: r = r_e + (r_c − r_e)·½(1 + "
      "cos(2π(z − z_c)/L)) or the circular arc through (r_e, z0), (r_c, z_c), (r_e, z1), z_c = (z0 + z1)/2, "
      "L = z1 − z0. The inner radius must stay positive and below the outer one.",
      {required(one_of(text("type", "mesh generator"), {"grid"})),
       required(number("z0", Dimension::length, "lower end z0")),
       required(number("z1", Dimension::length, "upper end z1 (> z0)")),
       required(structured("inner", "radius, list or map", "inner profile r_in(z)")),
       required(structured("outer", "radius, list or map", "outer profile r_out(z)")),
       required(at_most(at_least(integer("elements_r", "elements through the wall (radial)"), 1), 1e6)),
       required(at_most(at_least(integer("elements_z", "elements along z"), 1), 1e7))}};
  return s;
}

const ComponentSpec& profile_bump_spec() {
  static const ComponentSpec s{
      "parts.mesh.inner", "",
      "A symmetric bump profile (the `inner` or `outer` of a `grid` mesh given as a map), e.g. a centric "
      "stenosis: `inner: {radius_ends: 0.6235 mm, radius_centre: 0.39 mm, shape: cosine}`.",
      {required(positive(number("radius_ends", Dimension::length, "r_e at z0 and z1"))),
       required(positive(number("radius_centre", Dimension::length, "r_c at z_c = (z0 + z1)/2"))),
       with_default(one_of(text("shape", "cosine or circular arc"), {"cosine", "circular"}), "cosine")}};
  return s;
}

namespace {

RadiusProfile read_profile(const DeckNode& node, const UnitSystem& u) {
  RadiusProfile p;
  if (node.is_scalar()) {
    p.type = RadiusProfile::Type::constant;
    p.radius = read_quantity(node, Dimension::length, u);
  } else if (node.is_sequence()) {
    p.type = RadiusProfile::Type::polyline;
    for (const auto& item : node.items()) {
      if (!item.is_sequence() || item.items().size() != 2) item.fail("expected a point [r, z]");
      p.points.emplace_back(read_quantity(item.items()[0], Dimension::length, u),
                            read_quantity(item.items()[1], Dimension::length, u));
    }
  } else if (node.is_map()) {
    const Params q = read_params(node, profile_bump_spec(), u);
    p.type = q.text("shape") == "circular" ? RadiusProfile::Type::circular : RadiusProfile::Type::cosine;
    p.radius_ends = q.number("radius_ends");
    p.radius_centre = q.number("radius_centre");
  } else {
    node.fail("expected a radius, a list of points [r, z] or a map {radius_ends, radius_centre, shape}");
  }
  return p;
}

}  // namespace

void read_solid_part(const DeckNode& node, const Params& p, Part& part, Model& m) {
  part.formulation = p.text("formulation") == "displacement" ? SolidFormulation::displacement
                                                              : SolidFormulation::mean_dilatation;
  const DeckNode mesh = node.required("mesh");
  if (!mesh.is_map()) mesh.fail("expected a map with `type: grid`");
  const Params mp = read_params(mesh, solid_grid_spec(), m.units);
  SolidGridSpec spec;
  spec.z0 = mp.number("z0");
  spec.z1 = mp.number("z1");
  spec.elements_r = static_cast<int>(mp.integer("elements_r"));
  spec.elements_z = static_cast<int>(mp.integer("elements_z"));
  spec.inner = read_profile(mesh["inner"], m.units);
  spec.outer = read_profile(mesh["outer"], m.units);
  if (static_cast<double>(m.num_nodes()) + (spec.elements_r + 1.0) * (spec.elements_z + 1.0) > kMaxNodes)
    mp.fail("elements_z", fmt::format("the model would have more than {} nodes", kMaxNodes));
  SolidGrid g;
  try {
    g = solid_grid(spec);
  } catch (const std::invalid_argument& e) {
    mesh.fail(e.what());
  }
  const int first = m.num_nodes();
  for (std::size_t i = 0; i < g.nodes.size(); ++i) {
    m.X.push_back(Eigen::Vector3d(g.nodes[i](0), g.nodes[i](1), 0.0));
    part.nodes.push_back(first + static_cast<int>(i));
  }
  ElementBlock block;
  block.kind = ElementKind::solid4;
  for (int n : g.quads) block.nodes.push_back(first + n);
  part.blocks.push_back(std::move(block));
  const auto global = [&](const std::vector<int>& local) {
    std::vector<int> v;
    for (int n : local) v.push_back(first + n);
    return v;
  };
  const std::string origin = fmt::format("part '{}' (line {}) as one of its generated sets", part.name, mesh.where().line);
  m.node_sets.push_back({part.name + ".inner", global(g.inner), origin});
  m.node_sets.push_back({part.name + ".outer", global(g.outer), origin});
  m.node_sets.push_back({part.name + ".bottom", global(g.bottom), origin});
  m.node_sets.push_back({part.name + ".top", global(g.top), origin});
  m.node_sets.push_back({part.name + ".all", part.nodes, origin});
}

}  // namespace tunica
