#include "assembly/pressure_load_checks.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

#include "model/open_edges.hpp"
#include "model/volume_axis_check.hpp"

namespace tunica {

std::vector<UnheldEdges> unheld_open_edges(const Model& m, int part) {
  const auto open = open_edges(m, part);
  std::vector<char> held(m.num_nodes(), 0);
  for (const Boundary& b : m.boundaries)
    for (int n : m.node_sets[b.node_set].nodes) held[n] = 1;
  NodeChains chains;
  for (const auto& e : open) chains.join(e.first, e.second);
  std::map<int, UnheldEdges> by_chain;
  std::map<int, bool> any_held;
  for (const auto& e : open) {
    const int root = chains.find(e.first);
    UnheldEdges& c = by_chain[root];
    ++c.edges;
    c.centre += 0.5 * (m.X[e.first] + m.X[e.second]);
    if (c.node < 0) c.node = e.first;
    any_held[root] = any_held[root] || held[e.first] || held[e.second];
  }
  std::vector<UnheldEdges> out;
  for (auto& [root, c] : by_chain)
    if (!any_held[root]) {
      c.centre /= c.edges;
      out.push_back(c);
    }
  return out;
}

double missing_cap_volume(const Model& m, int part, const Eigen::Vector3d& p0, int* open_count) {
  // Edges of the corner polygons, counted over the part; an open edge is used once, with the
  // direction its element gives it.
  double longest = 0;
  const std::vector<std::pair<int, int>> open = open_edges(m, part, &longest);
  // The plane through p₀ and an edge; an edge whose plane a neighbouring open edge shares is
  // closed by that plane (a symmetry plane, an end through p₀).
  const auto plane = [&](const std::pair<int, int>& e) -> Eigen::Vector3d {
    const Eigen::Vector3d n = (m.X[e.first] - p0).cross(m.X[e.second] - p0);
    return n.norm() > 0 ? Eigen::Vector3d(n.normalized()) : Eigen::Vector3d::Zero();
  };
  std::map<int, std::vector<int>> at_node;
  for (int i = 0; i < static_cast<int>(open.size()); ++i) {
    at_node[open[i].first].push_back(i);
    at_node[open[i].second].push_back(i);
  }
  const double scale = std::max(longest, 1e-300);
  std::vector<char> needs_cap(open.size(), 1);
  for (int i = 0; i < static_cast<int>(open.size()); ++i) {
    const Eigen::Vector3d ni = plane(open[i]);
    if (ni.isZero()) {  // the edge is on a line through p₀: any plane through it passes p₀
      needs_cap[i] = 0;
      continue;
    }
    for (int node : {open[i].first, open[i].second})
      for (int j : at_node[node])
        if (j != i) {
          const Eigen::Vector3d nj = plane(open[j]);
          // Coplanar with p₀: the neighbour lies in this edge's plane (to 1e-6 of the longest edge).
          const double off = std::max(std::abs(ni.dot(m.X[open[j].first] - p0)), std::abs(ni.dot(m.X[open[j].second] - p0)));
          if (!nj.isZero() && off <= 1e-6 * scale) needs_cap[i] = 0;
        }
  }
  NodeChains chains;
  int counted = 0;
  for (int i = 0; i < static_cast<int>(open.size()); ++i)
    if (needs_cap[i]) {
      chains.join(open[i].first, open[i].second);
      ++counted;
    }
  if (open_count) *open_count = counted;
  // Per chain: Newell's normal and centroid give its plane; the cap is fanned from the point of
  // that plane nearest p₀, and its volume about p₀ is Σ det[c − p₀, x_b − p₀, x_a − p₀] / 6 over its
  // edges (a cap runs against its surface's edges to close it outward).
  std::map<int, std::vector<int>> by_chain;
  for (int i = 0; i < static_cast<int>(open.size()); ++i)
    if (needs_cap[i]) by_chain[chains.find(open[i].first)].push_back(i);
  double V = 0;
  for (const auto& [root, members] : by_chain) {
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero(), normal = Eigen::Vector3d::Zero();
    for (int i : members) centroid += 0.5 * (m.X[open[i].first] + m.X[open[i].second]);
    centroid /= static_cast<double>(members.size());
    for (int i : members) normal += (m.X[open[i].first] - centroid).cross(m.X[open[i].second] - centroid);
    Eigen::Vector3d c = centroid;
    if (normal.norm() > 0) {
      const Eigen::Vector3d n = normal.normalized();
      c = p0 + n * n.dot(centroid - p0);
    }
    for (int i : members) {
      const Eigen::Vector3d a = m.X[open[i].first] - p0, b = m.X[open[i].second] - p0;
      V += (c - p0).dot(b.cross(a)) / 6.0;
    }
  }
  return V;
}

bool volume_sign_is_orientation(const Model& m, int l) {
  const PressureLoad& load = m.loads[l];
  const Part& part = m.parts[load.part];
  if (part.is_solid()) return false;
  // Translational DOFs held per node (bit c for DOF c).
  const int translational = m.dofs_per_node();
  std::vector<int> held(m.num_nodes(), 0);
  for (const Boundary& b : m.boundaries)
    for (int n : m.node_sets[b.node_set].nodes)
      for (int c : b.dofs)
        if (c < translational) held[n] |= 1 << c;
  const auto clamped = [&](int n) { return held[n] == (1 << translational) - 1; };
  if (m.geometry == Geometry::axisymmetric) {
    if (part.nodes.empty()) return false;
    double size = 0;
    for (int n : part.nodes) size = std::max(size, m.X[n].head<2>().norm());
    for (int end : {part.nodes.front(), part.nodes.back()})
      if (m.X[end](0) > 1e-9 * size && clamped(end)) return false;
    return true;
  }
  const std::vector<std::pair<int, int>> open = open_edges(m, load.part);
  if (open.empty()) return true;
  if (load.volume.about_axis) return volume_axis_misfit(m, load.part, load.volume).empty();
  int missing = 0;
  missing_cap_volume(m, load.part, load.volume.point, &missing);
  if (missing > 0) return false;
  for (const auto& [a, b] : open)
    if (clamped(a) && clamped(b)) return false;
  return true;
}

// The fix depends on whether the load already flips the side: then the normals point out and
// `flip: true` is what turned the pressure inward.
std::string inward_load_cause(const PressureLoad& load) {
  return load.sign < 0 ? "the pressure acts against the elements' normals, which point out of the volume the surface "
                         "encloses, because the load has `flip: true`"
                       : "the normals point into the volume the surface encloses";
}

std::string inward_load_fix(const Model& m, const PressureLoad& load) {
  return load.sign < 0 ? std::string("remove `flip: true` from the load (or set `flip: false`)")
         : m.geometry == Geometry::axisymmetric
             ? "set `flip: true` on the load (or run the meridian the other way: swap the mesh's `from` and `to`, "
               "or `start_angle` and `end_angle`)"
             : "set `flip: true` on the load (or reverse the elements' node order in the mesh)";
}

std::vector<std::string> pressure_load_warnings(const System& system) {
  const Model& m = system.model();
  std::vector<std::string> out;
  const Eigen::VectorXd u0 = Eigen::VectorXd::Zero(system.num_dofs());
  const std::string unit = m.units.display_unit(Dimension::volume);
  for (int l = 0; l < static_cast<int>(m.loads.size()); ++l) {
    const PressureLoad& load = m.loads[l];
    const Part& part = m.parts[load.part];
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
    for (const ElementBlock& b : part.blocks)
      for (int n : b.nodes) {
        lo = lo.cwiseMin(m.X[n]);
        hi = hi.cwiseMax(m.X[n]);
      }
    const double size = (hi - lo).norm();
    double V = 0;
    try {
      V = system.volume(u0, l);
    } catch (const std::exception&) {
      continue;  // the mesh checks speak of an element that cannot be measured
    }
    const double tiny = 1e-9 * size * size * size;
    for (const UnheldEdges& c : unheld_open_edges(m, load.part)) {
      const long tag = c.node < static_cast<int>(m.node_tags.size()) && m.node_tags[c.node] ? m.node_tags[c.node] : c.node + 1;
      out.push_back(format_location(load.where, fmt::format(
          "load '{}': part '{}' has a free edge of {} element edge(s) around ({:.4g}, {:.4g}, {:.4g}) (through node {}) "
          "that no boundary condition holds: a hole or a gap in the mesh? The pressure pushes such an edge out "
          "unresisted by anything but the membrane; close the surface, or hold the edge in `boundary`.",
          load.name, part.name, c.edges, c.centre(0), c.centre(1), c.centre(2), tag)));
    }
    if (V < -tiny)
      out.push_back(format_location(load.where, fmt::format(
          "load '{}' pushes its surface (part '{}') inward: the volume on the side its pressure pushes away from is "
          "{:.6g} {} at the reference state, negative, so {}. A pressure inside a vessel or balloon pushes outward: "
          "{}; a pressure from outside is meant this way.",
          load.name, part.name, V, unit, inward_load_cause(load), inward_load_fix(m, load))));
    // The enclosed volume matters where it is reported or controlled.
    bool measured = false;
    for (const HistoryRequest& h : m.output.history) measured |= h.quantity == "volume" && h.load == l;
    for (const Step& st : m.steps) measured |= st.volume_control.load == l;
    if (measured && m.geometry == Geometry::three_d && !load.volume.about_axis) {
      int open = 0;
      const double cap = std::abs(missing_cap_volume(m, load.part, load.volume.point, &open));
      if (open > 0 && cap > 1e-3 * std::max(std::abs(V), tiny))
        out.push_back(format_location(load.where, fmt::format(
            "load '{}': the surface of part '{}' has {} open edge(s) that no plane through the volume point p₀ "
            "closes, so its enclosed volume ({:.6g} {}, measured about p₀) misses the caps that would close it "
            "(about {:.6g} {}): history's `volume` and a volume control would not be the lumen's. For a tube, give the load `volume_axis` "
            "(its axis; the ends are then closed by planes normal to it); for a surface cut by symmetry planes, "
            "put `volume_point` on them.",
            load.name, part.name, open, V, unit, cap, unit)));
    }
  }
  return out;
}

}  // namespace tunica
