#include "mesh/mesh_checks.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <deque>
#include <unordered_map>

namespace tunica {

namespace {

/// Element e of the surface as a list of node indices (triangles first, then quads), and
/// how messages name elements and nodes: by the tags of the mesh file where the mesh has
/// them, else by 0-based index.
struct ElementView {
  const SurfaceMesh& m;
  const SurfaceMesh::Surface& s;
  int count() const { return static_cast<int>(s.triangles.size() + s.quads.size()); }
  std::vector<int> nodes(int e) const {
    const int nt = static_cast<int>(s.triangles.size());
    if (e < nt) return {s.triangles[e].begin(), s.triangles[e].end()};
    return {s.quads[e - nt].begin(), s.quads[e - nt].end()};
  }
  /// The line of element e in the mesh file, or 0.
  int line(int e) const {
    const int nt = static_cast<int>(s.triangles.size());
    if (e < nt) return static_cast<int>(s.triangle_lines.size()) == nt ? s.triangle_lines[e] : 0;
    return s.quad_lines.size() == s.quads.size() ? s.quad_lines[e - nt] : 0;
  }
  std::string name(int e) const {
    const int nt = static_cast<int>(s.triangles.size());
    const char* tri = s.triangle_midsides.empty() ? "a triangle" : "a 6-node triangle";
    const std::string at = line(e) > 0 ? fmt::format(", line {}", line(e)) : "";
    if (e < nt && static_cast<int>(s.triangle_tags.size()) == nt)
      return fmt::format("element {} ({}{})", s.triangle_tags[e], tri, at);
    if (e >= nt && s.quad_tags.size() == s.quads.size())
      return fmt::format("element {} (a quadrilateral{})", s.quad_tags[e - nt], at);
    return e < nt ? fmt::format("element {} (triangle {})", e, e)
                  : fmt::format("element {} (quadrilateral {})", e, e - nt);
  }
  /// "element 17 (line 22)", or "element 3" for a mesh without tags: how a fix names it.
  std::string label(int e) const {
    const int nt = static_cast<int>(s.triangles.size());
    const bool tagged = e < nt ? static_cast<int>(s.triangle_tags.size()) == nt : s.quad_tags.size() == s.quads.size();
    const long tag = !tagged ? e : e < nt ? s.triangle_tags[e] : s.quad_tags[e - nt];
    return line(e) > 0 ? fmt::format("element {} (line {})", tag, line(e)) : fmt::format("element {}", tag);
  }
  long node(int k) const {
    return k >= 0 && static_cast<std::size_t>(k) < m.node_tags.size() ? m.node_tags[k] : k;
  }
  std::string list(const std::vector<int>& v) const {
    std::string out;
    for (int k : v) out += (out.empty() ? "" : ", ") + std::to_string(node(k));
    return "[" + out + "]";
  }
};

/// An element that names a node twice (at positions a < b of `nodes`), and the fix. Two
/// neighbouring corners are an edge that has collapsed: what a mesh generator leaves where it
/// merged the two ends of a very short edge.
std::string repeated_node(const ElementView& ev, int e, const std::vector<int>& nodes, std::size_t a, std::size_t b,
                          bool corners) {
  const bool edge = corners && (b == a + 1 || (a == 0 && b + 1 == nodes.size()));
  return fmt::format("{} has the repeated node {}; its nodes are {}: {}remove {} from the mesh file, or remesh the "
                     "surface{}",
                     ev.name(e), ev.node(nodes[a]), ev.list(nodes),
                     edge ? "an edge of it has collapsed onto one node, so it has no area (a mesh generator leaves "
                            "this where it merged the two ends of a very short edge, e.g. at a curve of the geometry "
                            "much shorter than the mesh size); "
                          : "an element must name each node once; ",
                     ev.label(e), edge ? " (without the very short curve, or finer there)" : "");
}

/// The corners of an element in the opposite order, the first kept: [a, b, c] -> [a, c, b].
std::vector<int> reversed_corners(std::vector<int> v) {
  std::reverse(v.begin() + 1, v.end());
  return v;
}

/// One traversal of an edge by an element: the element, and whether it goes from the
/// lower to the higher node index.
struct Use {
  int element;
  bool forward;
};

}  // namespace

std::string check_surface(const SurfaceMesh& mesh, const SurfaceMesh::Surface& s) {
  const ElementView ev{mesh, s};
  const std::string where = "surface '" + s.name + "': ";
  const long num_nodes = static_cast<long>(mesh.nodes.size());
  const int ne = ev.count();
  if (ne == 0) return where + "no elements";

  // 1. Node indices in range and not repeated within an element.
  for (int e = 0; e < ne; ++e) {
    const auto v = ev.nodes(e);
    for (int k : v)
      if (k < 0 || k >= num_nodes)
        return where + fmt::format("{} has node index {} outside the mesh (nodes 0 to {}); its nodes are {}",
                                   ev.name(e), k, num_nodes - 1, ev.list(v));
    for (std::size_t a = 0; a < v.size(); ++a)
      for (std::size_t b = a + 1; b < v.size(); ++b)
        if (v[a] == v[b])
          return where + repeated_node(ev, e, v, a, b, true);
  }

  // 1b. Quadratic triangles: their mid-edge nodes in range, distinct from the corners and from each other
  // (checked with the corners above), not a corner of any element, and shared: two triangles on one
  // corner-to-corner edge name the same mid-edge node (else the surface is not conforming: a gap opens
  // along the edge, or the nodes are listed in the wrong order).
  if (!s.triangle_midsides.empty()) {
    if (s.triangle_midsides.size() != s.triangles.size())
      return where + fmt::format("{} quadratic triangles have mid-edge nodes, {} have corners",
                                 s.triangle_midsides.size(), s.triangles.size());
    std::vector<char> corner(static_cast<std::size_t>(num_nodes), 0);
    for (int e = 0; e < ne; ++e)
      for (int k : ev.nodes(e)) corner[k] = 1;
    std::unordered_map<long long, std::pair<int, int>> mid_of;  // edge → (mid-edge node, element)
    for (int e = 0; e < static_cast<int>(s.triangles.size()); ++e) {
      const auto& c = s.triangles[e];
      const auto& mid = s.triangle_midsides[e];
      std::vector<int> all(c.begin(), c.end());
      all.insert(all.end(), mid.begin(), mid.end());
      for (int k : mid)
        if (k < 0 || k >= num_nodes)
          return where + fmt::format("{} has node index {} outside the mesh (nodes 0 to {})", ev.name(e), k, num_nodes - 1);
      for (std::size_t a = 0; a < all.size(); ++a)
        for (std::size_t b = a + 1; b < all.size(); ++b)
          if (all[a] == all[b])
            return where + repeated_node(ev, e, all, a, b, false);
      for (int a = 0; a < 3; ++a) {
        if (corner[mid[a]])
          return where + fmt::format("{}: its mid-edge node {} (between nodes {} and {}) is a corner of an element; "
                                     "its nodes are {} (corners first, then the mid-edge nodes of edges 1–2, 2–3, 3–1)",
                                     ev.name(e), ev.node(mid[a]), ev.node(c[a]), ev.node(c[(a + 1) % 3]), ev.list(all));
        // Near the middle of its edge: within half the edge's length of the chord's midpoint (a curved
        // edge of Gmsh's bulges by about L²/8R; a node listed for another edge is farther).
        const Eigen::Vector3d& p0 = mesh.nodes[c[a]];
        const Eigen::Vector3d& p1 = mesh.nodes[c[(a + 1) % 3]];
        const double off = (mesh.nodes[mid[a]] - 0.5 * (p0 + p1)).norm(), length = (p1 - p0).norm();
        if (!(off <= 0.5 * length))
          return where + fmt::format("{}: its mid-edge node {} is {:.3g} edge lengths from the middle of the edge "
                                     "between nodes {} and {} (at most 0.5): are its nodes listed as corners first, "
                                     "then the mid-edge nodes of edges 1–2, 2–3, 3–1? Its nodes are {}",
                                     ev.name(e), ev.node(mid[a]), length > 0 ? off / length : off, ev.node(c[a]),
                                     ev.node(c[(a + 1) % 3]), ev.list(all));
        const int lo = std::min(c[a], c[(a + 1) % 3]), hi = std::max(c[a], c[(a + 1) % 3]);
        const long long key = static_cast<long long>(lo) * num_nodes + hi;
        const auto [it, fresh] = mid_of.emplace(key, std::make_pair(mid[a], e));
        if (!fresh && it->second.first != mid[a])
          return where + fmt::format("{} and {} share the edge between nodes {} and {} but not its mid-edge node ({} and "
                                     "{}): the quadratic mesh is not conforming (a gap would open along the edge, or a "
                                     "triangle lists its mid-edge nodes in the wrong order: corners first, then the "
                                     "mid-edge nodes of edges 1–2, 2–3, 3–1)",
                                     ev.name(it->second.second), ev.name(e), ev.node(lo), ev.node(hi),
                                     ev.node(it->second.first), ev.node(mid[a]));
      }
    }
  }

  // 2. Degenerate elements. The area vector of a polygon x_0 … x_{m−1} is
  // ½ Σ (x_k − x_0) × (x_{k+1} − x_0) (for a triangle ½ (x1 − x0) × (x2 − x0); for a quad ½ d1 × d2 with the
  // diagonals d1, d2). The element is degenerate if its area is ≤ 1e-12 × (longest edge)².
  // A quadrilateral is also refused if one of its corners is flat or re-entrant (corner
  // triangle area along the element normal ≤ 1e-12 L²): the bilinear map then has a
  // Jacobian that vanishes or changes sign.
  for (int e = 0; e < ne; ++e) {
    const auto v = ev.nodes(e);
    const int m = static_cast<int>(v.size());
    Eigen::Vector3d area = Eigen::Vector3d::Zero();
    double longest2 = 0;
    for (int k = 0; k < m; ++k) {
      const Eigen::Vector3d a = mesh.nodes[v[k]] - mesh.nodes[v[0]];  // relative to x_0: no cancellation
      const Eigen::Vector3d b = mesh.nodes[v[(k + 1) % m]] - mesh.nodes[v[0]];
      area += 0.5 * a.cross(b);
      longest2 = std::max(longest2, (b - a).squaredNorm());
    }
    const double tol = 1e-12 * longest2;
    if (!(area.norm() > tol))  // also catches NaN coordinates
      return where + fmt::format("{} is degenerate (area {:.3g}, longest edge {:.3g}); its nodes are {}: an element "
                                 "must have an area; remove it or move its nodes apart (in Gmsh: remesh the surface)",
                                 ev.name(e), area.norm(), std::sqrt(longest2), ev.list(v));
    if (m == 4) {
      const Eigen::Vector3d normal = area.normalized();
      for (int k = 0; k < 4; ++k) {
        const Eigen::Vector3d& x = mesh.nodes[v[k]];
        const double corner =
            0.5 * (mesh.nodes[v[(k + 1) % 4]] - x).cross(mesh.nodes[v[(k + 3) % 4]] - x).dot(normal);
        if (!(corner > tol))
          return where + fmt::format("{} is degenerate: its corner at node {} is flat or re-entrant (not a convex "
                                     "quadrilateral); its nodes are {}",
                                     ev.name(e), ev.node(v[k]), ev.list(v));
      }
    }
  }

  // 3. Edges: map (lower node, higher node) → the elements using it, with the direction.
  std::unordered_map<long, std::vector<Use>> edges;
  edges.reserve(static_cast<std::size_t>(2 * ne));
  auto key = [&](int a, int b) { return static_cast<long>(std::min(a, b)) * num_nodes + std::max(a, b); };
  for (int e = 0; e < ne; ++e) {
    const auto v = ev.nodes(e);
    const int m = static_cast<int>(v.size());
    for (int k = 0; k < m; ++k) {
      const int a = v[k], b = v[(k + 1) % m];
      auto& uses = edges[key(a, b)];
      uses.push_back({e, a < b});
      if (uses.size() > 2) {
        std::string list;
        for (const auto& u : uses) list += (list.empty() ? "" : ", ") + ev.name(u.element);
        return where + fmt::format("the edge between nodes {} and {} is shared by more than two elements ({}): "
                                   "the surface is not a manifold",
                                   ev.node(std::min(a, b)), ev.node(std::max(a, b)), list);
      }
    }
  }

  // 4. Consistent orientation. Two elements sharing an edge are consistently oriented
  // if they traverse it in opposite directions. A breadth-first walk over each connected
  // patch gives every element its orientation relative to the patch's first element
  // (flip[e]: reversed); the elements in the minority are reported as inverted (with a
  // tie, those reversed relative to the first element). A conflict during the walk means
  // the surface cannot be oriented at all (a Möbius strip).
  std::vector<int> flip(ne, -1);
  std::vector<std::vector<int>> adjacency(ne);
  for (const auto& [k, uses] : edges)
    if (uses.size() == 2) {
      adjacency[uses[0].element].push_back(uses[1].element);
      adjacency[uses[1].element].push_back(uses[0].element);
    }
  auto same_direction = [&](int e, int f, int& a, int& b) {  // do e and f traverse a shared edge alike?
    const auto ve = ev.nodes(e);
    const auto vf = ev.nodes(f);
    for (std::size_t i = 0; i < ve.size(); ++i) {
      const int p = ve[i], q = ve[(i + 1) % ve.size()];
      for (std::size_t j = 0; j < vf.size(); ++j) {
        const int r = vf[j], t = vf[(j + 1) % vf.size()];
        if (p == r && q == t) return a = p, b = q, true;
        if (p == t && q == r) return a = p, b = q, false;
      }
    }
    return a = b = -1, false;
  };
  for (int seed = 0; seed < ne; ++seed) {
    if (flip[seed] >= 0) continue;
    std::vector<int> patch{seed};
    flip[seed] = 0;
    std::deque<int> queue{seed};
    while (!queue.empty()) {
      const int e = queue.front();
      queue.pop_front();
      for (int f : adjacency[e]) {
        int a, b;
        const int want = flip[e] ^ (same_direction(e, f, a, b) ? 1 : 0);
        if (flip[f] < 0) {
          flip[f] = want;
          patch.push_back(f);
          queue.push_back(f);
        } else if (flip[f] != want) {
          return where + fmt::format("the surface cannot be oriented consistently (a Möbius-like patch): {} and {} "
                                     "across the edge between nodes {} and {}",
                                     ev.name(e), ev.name(f), ev.node(a), ev.node(b));
        }
      }
    }
    long reversed = 0;
    for (int e : patch) reversed += flip[e];
    const int bad = 2 * reversed <= static_cast<long>(patch.size()) ? 1 : 0;  // the minority's flag
    std::vector<int> inverted;
    for (int e : patch)
      if (flip[e] == bad) inverted.push_back(e);
    if (inverted.empty()) continue;
    std::sort(inverted.begin(), inverted.end());
    const int e = inverted.front();
    int neighbour = -1, a = -1, b = -1;
    for (int f : adjacency[e])
      if (flip[f] != bad) {
        neighbour = f;
        same_direction(e, f, a, b);
        break;
      }
    std::string across = neighbour >= 0 ? fmt::format(" (it traverses the edge from node {} to node {} in the same "
                                                      "direction as its neighbour {})",
                                                      ev.node(a), ev.node(b), ev.name(neighbour))
                                        : "";
    return where + fmt::format("{} is inverted: its normal is opposite to its neighbours'{}, so the orientation "
                               "is not consistent ({} of {} connected elements inverted; nodes {}): list its corner "
                               "nodes in the opposite order ({}){}, or reverse a whole inverted patch in Gmsh "
                               "(ReverseMesh Surface{{tag}};)",
                               ev.name(e), across, inverted.size(), patch.size(), ev.list(ev.nodes(e)),
                               ev.list(reversed_corners(ev.nodes(e))),
                               s.triangle_midsides.empty() ? "" : " with the mid-edge nodes to match");
  }
  return "";
}

}  // namespace tunica
