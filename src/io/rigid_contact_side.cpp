#include "io/rigid_contact_side.hpp"

#include <fmt/format.h>

#include <cmath>

#include "contact/contact_search.hpp"

namespace tunica {

namespace {

/// The signed distance of the reference point x to the surface, positive on the slave's side
/// (theory manual (9.1) with c = 0); false where a polyline has no side (beyond its ends).
bool signed_distance(const RigidSurface& r, const Eigen::Vector2d& x, double& s) {
  if (r.type == RigidSurface::Type::cylinder) {
    s = (r.cylinder.side == CylinderSide::outside ? 1.0 : -1.0) * (x(0) - r.cylinder.radius);
    return true;
  }
  const ChainProjection w = project_on_chain(x, r.polyline.points);
  s = w.signed_distance;
  return w.feature != ChainFeature::none;
}

/// The reference length of the elements at node i of a meridian: the mean of its segments.
double element_length(const Model& m, const std::vector<int>& chain, std::size_t i) {
  double sum = 0;
  int count = 0;
  if (i > 0) sum += (m.X[chain[i]] - m.X[chain[i - 1]]).norm(), ++count;
  if (i + 1 < chain.size()) sum += (m.X[chain[i + 1]] - m.X[chain[i]]).norm(), ++count;
  return count > 0 ? sum / count : 0.0;
}

/// The polyline's points in the reverse order, as a deck writes them (up to 6 points).
std::string reversed_points(const RigidPolyline& line, const std::string& unit) {
  const Eigen::Index n = line.points.cols();
  const auto point = [&](Eigen::Index k) {
    return fmt::format("[{:g} {}, {:g} {}]", line.points(0, k), unit, line.points(1, k), unit);
  };
  if (n > 6) return fmt::format("from {} back to {}", point(n - 1), point(0));
  std::string out;
  for (Eigen::Index k = n - 1; k >= 0; --k) out += (out.empty() ? "" : ", ") + point(k);
  return "`points: [" + out + "]`";
}

}  // namespace

bool rigid_signed_distance(const RigidSurface& r, const Eigen::Vector2d& x, double& s) { return signed_distance(r, x, s); }

void check_contact_offset(const Params& p, const ContactPair& c, const Model& m,
                          const std::function<bool(const Eigen::Vector2d&, double&)>& distance,
                          const std::vector<int>& chain, const std::vector<int>& index) {
  const double offset = c.law.offset;
  if (!(offset > 0)) return;
  int worst = -1;
  double worst_depth = 0, worst_gap = 0, worst_length = 0;
  for (std::size_t k = 0; k < c.nodes.size() && k < index.size(); ++k) {
    double s = 0;
    if (!distance(m.X[c.nodes[k]].head<2>(), s)) continue;
    const double h = element_length(m, chain, static_cast<std::size_t>(index[k]));
    if (s < -kBehind * h) continue;  // behind the surface: the side's own error
    const double depth = offset - s;
    if (depth > kDeepBehind * h && depth > worst_depth) worst = static_cast<int>(k), worst_depth = depth, worst_gap = s,
                                                           worst_length = h;
  }
  if (worst < 0) return;
  const std::string unit = m.units.display_unit(Dimension::length);
  const Eigen::Vector3d& x = m.X[c.nodes[worst]];
  p.fail("offset", fmt::format(
      "contact pair '{}': the offset, {:.4g} {}, is larger than the gap the slave starts with: slave node {} (at r = "
      "{:.4g} {}, z = {:.4g} {}; its elements are {:.4g} {} long) starts {:.4g} {} from the surface, so it counts as "
      "penetrated by {:.4g} {} from the first iteration (g_N = gap − offset) and the penalty would push the membrane "
      "away by that in the first increment. The offset is the distance the surfaces keep (e.g. half the sum of the "
      "thicknesses): give one below the smallest starting gap, or start the slave that much farther from the surface",
      c.name, offset, unit, index[worst], x(0), unit, x(1), unit, worst_length, unit, worst_gap, unit, worst_depth,
      unit));
}

void check_rigid_side(const Params& p, const ContactPair& c, const Model& m) {
  const RigidSurface& r = m.rigid_surfaces[c.rigid];
  const std::vector<int>& chain = m.parts[c.part].nodes;
  int facing = 0, behind = 0, deepest = -1;
  double depth = 0, deepest_length = 0;
  bool deep = false;
  for (std::size_t k = 0; k < c.nodes.size(); ++k) {
    double s = 0;
    if (!signed_distance(r, m.X[c.nodes[k]].head<2>(), s)) continue;
    ++facing;
    const double h = element_length(m, chain, static_cast<std::size_t>(c.area_index[k]));
    if (!(s < -kBehind * h)) continue;
    ++behind;
    deep = deep || -s > kDeepBehind * h;
    if (-s > depth) depth = -s, deepest = static_cast<int>(k), deepest_length = h;
  }
  if (deepest < 0 || (!deep && 2 * behind <= facing)) return;
  const std::string unit = m.units.display_unit(Dimension::length);
  const Eigen::Vector3d& x = m.X[c.nodes[deepest]];
  const std::string slave = p.text("slave");
  const std::string what = fmt::format(
      "contact pair '{}': {} of the {} slave nodes of '{}' that face the rigid surface '{}' lie behind it at the "
      "reference state, the deepest by {:.4g} {} (node {} of part '{}', at r = {:.4g} {}, z = {:.4g} {}; its elements "
      "are {:.4g} {} long), so they count as penetrated from the first iteration and the penalty would push the "
      "membrane through the surface in the first increment",
      c.name, behind, facing, slave, r.name, depth, unit, c.area_index[deepest], m.parts[c.part].name, x(0), unit,
      x(1), unit, deepest_length, unit);
  std::string fix;
  if (r.type == RigidSurface::Type::cylinder) {
    const bool outside = r.cylinder.side == CylinderSide::outside;
    fix = fmt::format("`side: {}` keeps the slave at r {} {:.4g} {}: if it belongs {} the cylinder, write `side: {}` "
                      "in rigid_surfaces.{} (line {})",
                      outside ? "outside" : "inside", outside ? "≥" : "≤", r.cylinder.radius, unit,
                      outside ? "inside" : "outside", outside ? "inside" : "outside", r.name, r.where.line);
  } else {
    fix = fmt::format("A polyline's contact side is on the right of its direction of travel (the normal is the "
                      "direction turned clockwise): if the slave belongs on the other side, list the points of "
                      "rigid_surfaces.{} (line {}) in the reverse order, {}",
                      r.name, r.where.line, reversed_points(r.polyline, unit));
  }
  p.fail("rigid", what + ". " + fix + "; otherwise place the slave and the surface so that they start apart (or name "
                                      "as slave only the nodes on the surface's contact side)");
}

}  // namespace tunica
