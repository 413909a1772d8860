#include "model/rigid_motion_check.hpp"

#include <fmt/format.h>

#include <numeric>

#include "model/rigid_motion_fix.hpp"

namespace tunica {

namespace {

int find(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

const char* kAxis[3] = {"x", "y", "z"};

}  // namespace

std::vector<RigidMotion> free_rigid_motions(const Model& m, const std::vector<int>& nodes,
                                            const std::vector<unsigned>& held) {
  // A translation along axis k is free when no node holds k; a rotation about an axis parallel
  // to e_k when every node holding a DOF other than k lies on one such axis (a node on the axis
  // does not move). A motion held only to first order, like the rotation of a quarter tube about
  // the line where its symmetry planes' normals meet, is held by the stress it meets at second
  // order.
  std::vector<RigidMotion> out;
  double size = 0;
  for (int n : nodes) size = std::max(size, (m.X[n] - m.X[nodes.front()]).norm());
  if (nodes.empty() || !(size > 0)) return out;
  for (int k = 0; k < 3; ++k) {
    bool held_k = false;
    for (int n : nodes) held_k = held_k || (held[n] & (1u << k));
    if (!held_k) out.push_back({false, k, false, Eigen::Vector3d::Zero()});
  }
  for (int k = 0; k < 3; ++k) {
    const auto off_axis = [&](const Eigen::Vector3d& x) {
      Eigen::Vector3d y = x;
      y(k) = 0;
      return y;
    };
    bool free = true, any = false;
    Eigen::Vector3d through = Eigen::Vector3d::Zero();
    for (int n : nodes) {
      if (!(held[n] & ~(1u << k) & 7u)) continue;
      if (!any) {
        through = off_axis(m.X[n]);
        any = true;
      } else if ((off_axis(m.X[n]) - through).norm() > 1e-9 * size) {
        free = false;
        break;
      }
    }
    if (free) out.push_back({true, k, any, through});
  }
  return out;
}

std::vector<UnheldBody> unheld_rigid_motions(const Model& m, bool contact_holds) {
  const int parts = static_cast<int>(m.parts.size());
  // Bodies: parts joined by a shared node.
  std::vector<int> parent(parts), owner(m.num_nodes(), -1);
  std::iota(parent.begin(), parent.end(), 0);
  for (int p = 0; p < parts; ++p)
    for (int n : m.parts[p].nodes) {
      if (owner[n] >= 0) parent[find(parent, p)] = find(parent, owner[n]);
      else owner[n] = p;
    }
  std::vector<char> in_contact(parts, 0);
  const auto mark = [&](int node) {
    if (node >= 0 && node < m.num_nodes() && owner[node] >= 0) in_contact[find(parent, owner[node])] = 1;
  };
  for (const ContactPair& c : m.contacts) {
    for (int n : c.nodes) mark(n);
    for (int n : c.master) mark(n);
  }
  // Held DOFs per node (positions only: slopes are not rigid motions).
  const int dpn = m.dofs_per_node();
  std::vector<unsigned> held(m.num_nodes(), 0);
  for (const Boundary& b : m.boundaries)
    for (int n : m.node_sets[b.node_set].nodes)
      for (int d : b.dofs)
        if (d < dpn) held[n] |= 1u << d;

  std::vector<UnheldBody> out;
  // Without any boundary condition the deck may lack the section itself: say where they go.
  const std::string none =
      m.boundaries.empty() ? " (the deck has no boundary conditions yet: add them in a `boundary` section)" : "";
  for (int body = 0; body < parts; ++body) {
    if (find(parent, body) != body || (contact_holds && in_contact[body])) continue;
    std::vector<int> nodes, members;
    std::string names;
    for (int p = 0; p < parts; ++p)
      if (find(parent, p) == body) {
        members.push_back(p);
        names += (names.empty() ? "'" : ", '") + m.parts[p].name + "'";
        for (int n : m.parts[p].nodes)
          if (owner[n] == p) nodes.push_back(n);
      }
    if (nodes.empty()) continue;
    const bool one = names.find(',') == std::string::npos;
    if (m.geometry == Geometry::axisymmetric) {
      bool z = false;
      for (int n : nodes) z = z || (held[n] & 2u);
      if (!z)
        out.push_back({members, fmt::format("{} {}: no boundary condition holds z, so {} free to slide along the "
                                            "axis (a singular tangent): hold z of at least one node, e.g. {}{}",
                                            one ? "part" : "parts", names, one ? "it is" : "they are",
                                            axial_hold(m, nodes), none)});
      continue;
    }
    const std::vector<RigidMotion> free = free_rigid_motions(m, nodes, held);
    if (free.empty()) continue;
    std::string list;
    for (const RigidMotion& r : free)
      list += (list.empty() ? "" : ", ") +
              (!r.rotation  ? fmt::format("translation along {}", kAxis[r.k])
               : r.located ? fmt::format("rotation about the line parallel to {} through ({:.4g}, {:.4g}, {:.4g})",
                                         kAxis[r.k], r.through.x(), r.through.y(), r.through.z())
                           : fmt::format("rotation about {}", kAxis[r.k]));
    const std::string fix = rigid_motion_fix(m, nodes, held);
    out.push_back({members, fmt::format("{} {}: the boundary conditions leave {} free to move rigidly ({}), so the "
                                        "tangent is singular and the run fails or drifts by an arbitrary rigid motion: "
                                        "hold enough DOFs to stop {}{}{}",
                                        one ? "part" : "parts", names, one ? "it" : "them", list,
                                        free.size() > 1 ? "them" : "it", fix.empty() ? "" : ", e.g. " + fix, none)});
  }
  return out;
}

}  // namespace tunica
