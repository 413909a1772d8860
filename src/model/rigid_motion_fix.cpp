#include "model/rigid_motion_fix.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "model/rigid_motion_check.hpp"

namespace tunica {

namespace {

const char* kAxis[3] = {"x", "y", "z"};

/// A proposed hold: DOF `dof` of the nodes of node set `set`, or of the one node `node`.
struct Hold {
  int set = -1;
  int node = -1;
  int dof = 0;
  bool leaves_inflation = false;  ///< see the header
};

struct Body {
  const Model& m;
  const std::vector<int>& nodes;
  Eigen::Vector3d middle = Eigen::Vector3d::Zero();
  double tol = 0;
};

/// The distinct coordinates x_j of the body's nodes held in DOF j.
std::vector<double> held_at(const Body& b, const std::vector<unsigned>& held, int j) {
  std::vector<double> v;
  for (int n : b.nodes)
    if (held[n] & (1u << j)) {
      const double x = b.m.X[n](j);
      if (std::none_of(v.begin(), v.end(), [&](double y) { return std::abs(x - y) <= b.tol; })) v.push_back(x);
    }
  return v;
}

/// True if holding DOF j at coordinate x_j = v keeps every node held in j at one coordinate.
bool leaves_inflation(const Body& b, const std::vector<unsigned>& held, int j, double v) {
  const std::vector<double> at = held_at(b, held, j);
  return at.empty() || (at.size() == 1 && std::abs(at.front() - v) <= b.tol);
}

void apply(const Body& b, const Hold& h, std::vector<unsigned>& held) {
  if (h.set >= 0)
    for (int n : b.m.node_sets[h.set].nodes) held[n] |= 1u << h.dof;
  else if (h.node >= 0)
    held[static_cast<std::size_t>(h.node)] |= 1u << h.dof;
}

/// One node whose DOF stops `r`, preferring one that leaves an inflation free: for a translation
/// along k, a node nearest the middle plane x_k; for a rotation about a line parallel to e_k, the
/// node farthest from the line in direction i among those at the held coordinate x_j (or the
/// middle), held in j.
Hold node_hold(const Body& b, const RigidMotion& r, const std::vector<unsigned>& held) {
  const Model& m = b.m;
  Hold best;
  if (!r.rotation) {
    double d = 0;
    for (int n : b.nodes)
      if (best.node < 0 || std::abs(m.X[n](r.k) - b.middle(r.k)) < d) {
        best = {-1, n, r.k, true};
        d = std::abs(m.X[n](r.k) - b.middle(r.k));
      }
    return best;
  }
  const Eigen::Vector3d p = r.located ? r.through : b.middle;
  double far = 0;
  for (int pass = 0; pass < 2 && best.node < 0; ++pass)  // pass 1: any node, if none leaves an inflation free
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        if (i == j || i == r.k || j == r.k) continue;
        const std::vector<double> at = held_at(b, held, j);
        const double target = at.empty() ? b.middle(j) : at.front();
        for (int n : b.nodes) {
          const double d = std::abs(m.X[n](i) - p(i));
          if (pass == 0 && at.size() <= 1 && std::abs(m.X[n](j) - target) > b.tol) continue;
          if (d > b.tol && d > far) {
            far = d;
            best = {-1, n, j, pass == 0 && at.size() <= 1};
          }
        }
      }
  return best;
}

/// True if the set `name` (after its part's prefix) is `x0`, `y0` or `z0` for the plane x_j = 0.
bool plane_named(const std::string& name, int j, double v, double tol) {
  const std::string own = name.substr(name.rfind('.') + 1);
  return std::abs(v) <= tol && own.size() == 2 && own[0] == kAxis[j][0] && own[1] == '0';
}

std::string join(const std::vector<std::string>& items) {
  std::string s;
  for (std::size_t k = 0; k < items.size(); ++k)
    s += (k == 0 ? "" : k + 1 == items.size() ? " and " : ", ") + items[k];
  return s;
}

/// Node `n` as the deck names it: its index in the first part that has it.
std::string node_text(const Model& m, int n) {
  for (const Part& part : m.parts) {
    const auto it = std::find(part.nodes.begin(), part.nodes.end(), n);
    if (it == part.nodes.end()) continue;
    const long index = it - part.nodes.begin();
    return fmt::format("node {} of part '{}', at ({:.4g}, {:.4g}, {:.4g}) (as a node set: `{{part: {}, nodes: [{}]}}`)",
                       index, part.name, m.X[n].x(), m.X[n].y(), m.X[n].z(), part.name, index);
  }
  return fmt::format("node {}", n + 1);
}

}  // namespace

std::string rigid_motion_fix(const Model& m, const std::vector<int>& nodes, const std::vector<unsigned>& held_now) {
  if (nodes.empty()) return "";
  Eigen::Vector3d lo = m.X[nodes.front()], hi = lo;
  for (int n : nodes) {
    lo = lo.cwiseMin(m.X[n]);
    hi = hi.cwiseMax(m.X[n]);
  }
  Body b{m, nodes, (lo + hi) / 2, 1e-6 * (hi - lo).norm()};
  std::vector<char> in_body(m.num_nodes(), 0);
  for (int n : nodes) in_body[n] = 1;
  // The body's node sets that lie in a coordinate plane x_j = v: candidates for holding DOF j.
  struct Candidate {
    int set, j;
    double v;
  };
  std::vector<Candidate> candidates;
  for (int s = 0; s < static_cast<int>(m.node_sets.size()); ++s) {
    const std::vector<int>& sn = m.node_sets[s].nodes;
    if (sn.empty() || !std::all_of(sn.begin(), sn.end(), [&](int n) { return in_body[n]; })) continue;
    for (int j = 0; j < 3; ++j) {
      const auto [a, z] = std::minmax_element(sn.begin(), sn.end(), [&](int p, int q) { return m.X[p](j) < m.X[q](j); });
      if (m.X[*z](j) - m.X[*a](j) <= b.tol) candidates.push_back({s, j, m.X[sn.front()](j)});
    }
  }
  std::vector<unsigned> held = held_now;
  std::vector<Hold> chosen;
  std::vector<RigidMotion> free = free_rigid_motions(m, nodes, held);
  // Greedily the set that stops most motions, those that leave an inflation free first, then
  // those through the body's middle.
  while (!free.empty()) {
    int best = -1;
    std::size_t best_left = free.size();
    int best_rank = 4;
    for (int c = 0; c < static_cast<int>(candidates.size()); ++c) {
      const Candidate& cand = candidates[c];
      std::vector<unsigned> trial = held;
      apply(b, {cand.set, -1, cand.j}, trial);
      const std::size_t left = free_rigid_motions(m, nodes, trial).size();
      if (left >= free.size()) continue;
      const int rank = (leaves_inflation(b, held, cand.j, cand.v) ? 0 : 2) + (std::abs(cand.v - b.middle(cand.j)) <= b.tol ? 0 : 1);
      // Of sets that do equally well (a quarter tube's `end` is its `x0`), the one named for its
      // plane (`x0` for x = 0), as a deck would write it.
      const bool named = plane_named(m.node_sets[cand.set].name, cand.j, cand.v, b.tol);
      if (rank < best_rank || (rank == best_rank && left < best_left) ||
          (rank == best_rank && left == best_left && named && !plane_named(m.node_sets[candidates[best].set].name,
                                                                           candidates[best].j, candidates[best].v, b.tol)))
        best = c, best_rank = rank, best_left = left;
    }
    if (best < 0) break;
    const Hold h{candidates[best].set, -1, candidates[best].j, best_rank < 2};
    apply(b, h, held);
    chosen.push_back(h);
    free = free_rigid_motions(m, nodes, held);
  }
  // What no set stops: one node each.
  for (int guard = 0; !free.empty() && guard < 6; ++guard) {
    const Hold h = node_hold(b, free.front(), held);
    if (h.node < 0) break;
    apply(b, h, held);
    chosen.push_back(h);
    free = free_rigid_motions(m, nodes, held);
  }
  if (!free.empty() || chosen.empty()) return "";
  // "x and y of `balloon.north` (on x = 0 and y = 0)": the DOFs of a set together, in the order chosen.
  std::vector<std::string> items;
  std::vector<int> sets_done;
  bool all_leave = true;
  for (const Hold& h : chosen) {
    all_leave = all_leave && h.leaves_inflation;
    if (h.set < 0) {
      items.push_back(fmt::format("{} of {}", kAxis[h.dof], node_text(m, h.node)));
      continue;
    }
    if (std::find(sets_done.begin(), sets_done.end(), h.set) != sets_done.end()) continue;
    sets_done.push_back(h.set);
    std::vector<std::string> dofs, planes;
    for (const Hold& g : chosen)
      if (g.set == h.set) {
        dofs.push_back(kAxis[g.dof]);
        const double v = m.X[m.node_sets[h.set].nodes.front()](g.dof);
        planes.push_back(fmt::format("{} = {:.4g}", kAxis[g.dof], std::abs(v) <= b.tol ? 0.0 : v));
      }
    items.push_back(fmt::format("{} of `{}` (on {})", join(dofs), m.node_sets[h.set].name, join(planes)));
  }
  return join(items) + (all_leave ? ": held so, the body can still inflate freely" : "");
}

std::string axial_hold(const Model& m, const std::vector<int>& nodes) {
  if (nodes.empty()) return "";
  std::vector<char> in_body(m.num_nodes(), 0);
  double size = 0;
  for (int n : nodes) {
    in_body[n] = 1;
    size = std::max(size, (m.X[n] - m.X[nodes.front()]).norm());
  }
  for (const NodeSet& s : m.node_sets) {
    if (s.nodes.empty() || s.nodes.size() == nodes.size() ||
        !std::all_of(s.nodes.begin(), s.nodes.end(), [&](int n) { return in_body[n]; }))
      continue;
    const auto [a, z] = std::minmax_element(s.nodes.begin(), s.nodes.end(), [&](int p, int q) { return m.X[p].y() < m.X[q].y(); });
    if (m.X[*z].y() - m.X[*a].y() <= 1e-6 * size) return "of `" + s.name + "`";
  }
  return "of " + node_text(m, nodes.front());
}

}  // namespace tunica
