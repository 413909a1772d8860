#include "model/volume_axis_check.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "model/open_edges.hpp"

namespace tunica {

namespace {

/// One chain of open edges that is not in a plane through the axis, and its cap.
struct Loop {
  std::vector<int> edges;                            ///< indices into the open edges
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  ///< mean of its edges' midpoints
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  ///< unit normal of its mean plane (Newell), or 0
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();  ///< of its cap's area (the centre if it has none)
  double radius = 0;                                 ///< largest distance of a node from the centre
  double out_of_plane = 0;                           ///< largest distance of a node from the mean plane
  int node = -1;
};

/// y⊥ = y − (a·y) a.
Eigen::Vector3d across(const Eigen::Vector3d& y, const Eigen::Vector3d& a) { return y - a.dot(y) * a; }

/// The cap of `loop` fanned from the point where the axis meets the loop's plane (its centre
/// if the axis is parallel to it), each triangle run against the surface's edge: its area and
/// its share ½∫cap y⊥·n dA, exact for each flat triangle (the integrand is linear).
std::pair<double, double> cap_share(const Model& m, const std::vector<std::pair<int, int>>& open, const Loop& loop,
                                    const Eigen::Vector3d& p0, const Eigen::Vector3d& a) {
  Eigen::Vector3d c = loop.centre;
  if (!loop.normal.isZero() && std::abs(loop.normal.dot(a)) > 1e-3)
    c = p0 + a * (loop.normal.dot(loop.centre - p0) / loop.normal.dot(a));
  Eigen::Vector3d area = Eigen::Vector3d::Zero();
  double share = 0;
  for (int i : loop.edges) {
    const Eigen::Vector3d& xa = m.X[open[i].first];
    const Eigen::Vector3d& xb = m.X[open[i].second];
    const Eigen::Vector3d dA = 0.5 * (xb - c).cross(xa - c);
    area += dA;
    share += 0.5 * dA.dot(across((c + xa + xb) / 3 - p0, a));
  }
  return {area.norm(), share};
}

bool fits(double area, double share, const Loop& loop) { return std::abs(share) <= 1e-3 * area * loop.radius; }

std::string vec(const Eigen::Vector3d& v) {
  const auto r = [](double x) { return std::abs(x) < 5e-4 ? 0.0 : x; };
  return fmt::format("[{:.4g}, {:.4g}, {:.4g}]", r(v.x()), r(v.y()), r(v.z()));
}

/// "(x, y, z)", components below 10⁻⁹ of `scale` written as 0 (round-off about an axis).
std::string point(const Eigen::Vector3d& v, double scale) {
  const auto r = [&](double x) { return std::abs(x) <= 1e-9 * scale ? 0.0 : x; };
  return fmt::format("({:.4g}, {:.4g}, {:.4g})", r(v.x()), r(v.y()), r(v.z()));
}

/// The index of v's largest component made positive.
Eigen::Vector3d canonical(Eigen::Vector3d v) {
  int k = 0;
  v.cwiseAbs().maxCoeff(&k);
  return v(k) < 0 ? Eigen::Vector3d(-v) : v;
}

/// The open edge loops that the measure about the axis a through p₀ caps, and the first whose cap
/// has a share (−1 if none).
struct Analysis {
  std::vector<Loop> loops;
  int failing = -1;
  double share = 0;
};

Analysis analyse(const Model& m, const std::vector<std::pair<int, int>>& open, double tol, const Eigen::Vector3d& p0,
                 const Eigen::Vector3d& a) {
  // Edges in a plane that holds the axis (a symmetry plane through it) need no cap: y⊥·n = 0 on
  // it. As for the volume about a point, a neighbouring open edge must share the plane, so that
  // a lone edge that happens to point at the axis is not taken for one.
  const auto plane_normal = [&](const std::pair<int, int>& e) -> Eigen::Vector3d {
    const Eigen::Vector3d ya = across(m.X[e.first] - p0, a), yb = across(m.X[e.second] - p0, a);
    const Eigen::Vector3d& off = ya.norm() >= yb.norm() ? ya : yb;  // the node farther from the axis
    return off.norm() > tol ? Eigen::Vector3d(a.cross(off).normalized()) : Eigen::Vector3d::Zero();
  };
  const auto in_plane = [&](const Eigen::Vector3d& n, const std::pair<int, int>& e) {
    return std::abs(n.dot(m.X[e.first] - p0)) <= tol && std::abs(n.dot(m.X[e.second] - p0)) <= tol;
  };
  std::map<int, std::vector<int>> at_node;
  for (int i = 0; i < static_cast<int>(open.size()); ++i) {
    at_node[open[i].first].push_back(i);
    at_node[open[i].second].push_back(i);
  }
  std::vector<char> capped(open.size(), 1);
  for (int i = 0; i < static_cast<int>(open.size()); ++i) {
    const Eigen::Vector3d n = plane_normal(open[i]);
    if (n.isZero()) {  // on the axis: in every plane that holds it
      capped[i] = 0;
      continue;
    }
    if (!in_plane(n, open[i])) continue;
    for (int node : {open[i].first, open[i].second})
      for (int j : at_node[node])
        if (j != i && in_plane(n, open[j])) capped[i] = 0;
  }
  NodeChains chains;
  for (int i = 0; i < static_cast<int>(open.size()); ++i)
    if (capped[i]) chains.join(open[i].first, open[i].second);
  std::map<int, Loop> by_root;
  for (int i = 0; i < static_cast<int>(open.size()); ++i)
    if (capped[i]) by_root[chains.find(open[i].first)].edges.push_back(i);
  Analysis out;
  for (auto& [root, loop] : by_root) {
    for (int i : loop.edges) loop.centre += 0.5 * (m.X[open[i].first] + m.X[open[i].second]);
    loop.centre /= static_cast<double>(loop.edges.size());
    Eigen::Vector3d newell = Eigen::Vector3d::Zero();
    for (int i : loop.edges) newell += (m.X[open[i].first] - loop.centre).cross(m.X[open[i].second] - loop.centre);
    if (newell.norm() > 0) loop.normal = newell.normalized();
    for (int i : loop.edges)
      for (int n : {open[i].first, open[i].second}) {
        loop.radius = std::max(loop.radius, (m.X[n] - loop.centre).norm());
        if (!loop.normal.isZero())
          loop.out_of_plane = std::max(loop.out_of_plane, std::abs(loop.normal.dot(m.X[n] - loop.centre)));
      }
    // The cap's area centroid, from the fan about the centre (the mean of the edges' midpoints is
    // not it on an unevenly spaced loop).
    double w = 0;
    for (int i : loop.edges) {
      const Eigen::Vector3d& xa = m.X[open[i].first];
      const Eigen::Vector3d& xb = m.X[open[i].second];
      const double wi = loop.normal.dot((xa - loop.centre).cross(xb - loop.centre));
      loop.centroid += wi * (loop.centre + xa + xb) / 3;
      w += wi;
    }
    loop.centroid = std::abs(w) > 0 ? Eigen::Vector3d(loop.centroid / w) : loop.centre;
    loop.node = open[loop.edges.front()].first;
    out.loops.push_back(std::move(loop));
  }
  for (int k = 0; k < static_cast<int>(out.loops.size()) && out.failing < 0; ++k) {
    const auto [area, share] = cap_share(m, open, out.loops[k], p0, a);
    if (!fits(area, share, out.loops[k])) out.failing = k, out.share = share;
  }
  return out;
}

/// The direction the part's element normals are most nearly perpendicular to (the least
/// eigenvector of Σ A n nᵀ over its elements' corner polygons): a tube's axis.
Eigen::Vector3d tube_axis(const Model& m, int part) {
  Eigen::Matrix3d normals = Eigen::Matrix3d::Zero();
  for (const ElementBlock& b : m.parts[part].blocks) {
    const int c = corner_nodes(b.kind);
    for (int e = 0; e < b.size(); ++e) {
      const int* n = b.element(e);
      const Eigen::Vector3d av = c == 4 ? 0.5 * (m.X[n[2]] - m.X[n[0]]).cross(m.X[n[3]] - m.X[n[1]])
                                        : 0.5 * (m.X[n[1]] - m.X[n[0]]).cross(m.X[n[2]] - m.X[n[0]]);
      if (av.norm() > 0) normals += av * av.transpose() / av.norm();
    }
  }
  return canonical(Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(normals).eigenvectors().col(0));
}

}  // namespace

std::string volume_axis_misfit(const Model& m, int part, const VolumeMeasure& how) {
  if (!how.about_axis) return "";
  double longest = 0;
  const std::vector<std::pair<int, int>> open = open_edges(m, part, &longest);
  if (open.empty()) return "";
  const Eigen::Vector3d a = how.axis.normalized(), p0 = how.point;
  const double tol = 1e-6 * longest;
  const Analysis here = analyse(m, open, tol, p0, a);
  if (here.failing < 0) return "";
  const Loop& l = here.loops[here.failing];
  const auto all_fit = [&](const Eigen::Vector3d& q, const Eigen::Vector3d& axis) {
    return analyse(m, open, tol, q, axis).failing < 0;
  };
  const std::string length = m.units.display_unit(Dimension::length);
  const long tag = l.node < static_cast<int>(m.node_tags.size()) && m.node_tags[l.node] ? m.node_tags[l.node] : l.node + 1;
  std::string s = fmt::format(
      "the axis {} through p₀ = {} does not fit the open edge loop of {} edge(s) around {} (through node {}): the "
      "volume about an axis, ½∫(x − p₀)⊥·n dA, is the enclosed volume only where each open end is closed by a "
      "plane normal to the axis, or one whose middle the axis passes through (a plane holding the axis, such as a "
      "symmetry plane, closes it too), and this loop's cap would add {:.6g} {} that it leaves out",
      vec(a), point(p0, l.radius), l.edges.size(), point(l.centre, l.radius), tag, std::abs(here.share),
      m.units.display_unit(Dimension::volume));
  const bool plane = !l.normal.isZero() && l.out_of_plane <= 1e-3 * l.radius;
  if (!plane)
    s += fmt::format(". The loop does not lie in a plane (its nodes stand up to {:.4g} {} off its mean plane, radius "
                     "{:.4g} {})",
                     l.out_of_plane, length, l.radius, length);
  const auto r = [&](double x) { return std::abs(x) <= 1e-9 * l.radius ? 0.0 : x; };
  const auto at = [&](const Eigen::Vector3d& q) {
    return fmt::format("[{:.6g} {}, {:.6g} {}, {:.6g} {}]", r(q.x()), length, r(q.y()), length, r(q.z()), length);
  };
  // The likely fixes, each only if it fits every open end: the tube's axis (the direction its
  // normals are perpendicular to) or the normal of the loop's plane, through p₀; the line through
  // the middles of a tube's two ends; the axis through the loop's middle.
  const Eigen::Vector3d tube = tube_axis(m, part);
  if (all_fit(p0, tube))
    return s + fmt::format(". The surface's normals are most nearly perpendicular to {} (a tube's axis), which fits: "
                           "`volume_axis: {}`",
                           vec(tube), vec(tube));
  if (plane && all_fit(p0, canonical(l.normal)))
    return s + fmt::format(". The loop's plane is normal to {}, which fits: `volume_axis: {}`", vec(canonical(l.normal)),
                           vec(canonical(l.normal)));
  const std::vector<Loop>& loops = here.loops;
  if (loops.size() == 2) {
    const Eigen::Vector3d d = loops[1].centroid - loops[0].centroid;
    if (d.norm() > 0 && all_fit(loops[0].centroid, d.normalized()))
      return s + fmt::format(". The line through the middles of the two open ends fits both: `volume_axis: {}, "
                             "volume_point: {}`",
                             vec(canonical(d.normalized())), at(loops[0].centroid));
  }
  if (all_fit(l.centroid, a))
    return s + fmt::format(". The axis moved through the loop's middle fits: `volume_point: {}`", at(l.centroid));
  return s + ". No one axis fits every open end: cut the surface's open ends by planes normal to one axis, give a "
             "surface cut by symmetry planes a `volume_point` on the line where they meet, or close the surface";
}

}  // namespace tunica
