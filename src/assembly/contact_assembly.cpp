#include "assembly/contact_assembly.hpp"

#include <algorithm>
#include <stdexcept>

#include "contact/contact_search.hpp"
#include "contact/rigid_surface.hpp"
#include "contact/smooth_chain.hpp"

namespace tunica {

namespace {

/// Slave node at x_s against rigid surface `r`: state, f (2) and, if K is given, K (2×2).
ContactPoint rigid_contact(const RigidSurface& r, const Eigen::Vector2d& xs, double area, const ContactLaw& law,
                           Eigen::Vector2d& f, Eigen::Matrix2d* K) {
  return r.type == RigidSurface::Type::cylinder ? rigid_cylinder_contact(r.cylinder, xs, area, law, f, K)
                                                : rigid_polyline_contact(r.polyline, xs, area, law, f, K);
}

/// The contact element of one slave node of a deformable pair: the slave and up to four master
/// chain indices (−1: unused), f (10) and K (10×10) in that order (r, z per node), the state.
struct DeformableContactElement {
  std::array<int, 4> master{-1, -1, -1, -1};
  ContactVector10 f = ContactVector10::Zero();
  ContactMatrix10 K = ContactMatrix10::Zero();
  ContactPoint point;
  int segment = -1;
};

/// Slave x_s against the current master chain of `pair`: the faceted (node to segment / vertex) or
/// the smooth (Catmull–Rom) surface. Returns whether the node is active (e filled; K only if wanted).
bool deformable_element(const ContactPair& pair, const Eigen::Vector2d& xs, const Eigen::Matrix2Xd& chain,
                        double area, bool want_K, DeformableContactElement& e) {
  const bool smooth = pair.master_surface == ContactPair::MasterSurface::smooth;
  const double tau = smooth ? kSmoothMasterEndTolerance : kMasterEndTolerance;
  const ChainProjection where = project_on_chain(xs, chain, std::numeric_limits<double>::infinity(), tau);
  if (smooth) {
    const SmoothProjection p = project_on_smooth_chain(xs, chain, where, tau);
    if (!p.found) return false;
    e.point = smooth_contact(xs, chain, p.segment, p.xi, area, pair.law, e.f, want_K ? &e.K : nullptr);
    e.master = smooth_window(p.segment, static_cast<int>(chain.cols()));
    e.segment = p.segment;
    return e.point.active;
  }
  ContactVector6 f;
  ContactMatrix6 Kc;
  e.point = chain_contact(xs, chain, where, area, pair.law, f, want_K && where.feature != ChainFeature::none && pair.law.touching(where.gap(pair.law.offset)) ? &Kc : nullptr);
  if (!e.point.active) return false;
  e.master = {where.segment, where.segment + 1, -1, -1};
  e.segment = where.segment;
  e.f.head<6>() = f;
  if (want_K) e.K.topLeftCorner<6, 6>() = Kc;
  return true;
}

/// The curvature part of a contact element's tangent, K − A_s p′ ∂g_N/∂u ⊗ ∂g_N/∂u (the Gauss–Newton
/// part; f = −A_s p ∂g_N/∂u gives ∂g_N/∂u), times `factor`; theory manual (9.10).
template <typename Vector, typename Matrix>
Matrix curvature_part(const Vector& f, const Matrix& K, const ContactLaw& law, double area, double gap, double factor) {
  const double pA = law.pressure(gap) * area;
  if (!(pA > 0)) return factor * K;  // p = 0 at the edge of the blend: K is its Gauss–Newton part (0)
  const Vector dg = -f / pA;
  return factor * (K - law.stiffness(gap) * area * dg * dg.transpose());
}

}  // namespace

void ContactAssembly::add_couplings(const Model& m, std::vector<std::vector<int>>& adjacent) {
  for (const auto& pair : m.contacts) {
    if (!pair.deformable()) continue;  // a rigid pair couples a slave node with itself only
    for (int s : pair.nodes)
      for (int q : pair.master) {
        adjacent[s].push_back(q);
        adjacent[q].push_back(s);
      }
    // Master nodes of one contact element: consecutive (faceted), or within a window of four (smooth).
    const std::size_t reach = pair.master_surface == ContactPair::MasterSurface::smooth ? 3 : 1;
    for (std::size_t k = 0; k < pair.master.size(); ++k)
      for (std::size_t d = 1; d <= reach && k + d < pair.master.size(); ++d) {
        adjacent[pair.master[k]].push_back(pair.master[k + d]);
        adjacent[pair.master[k + d]].push_back(pair.master[k]);
      }
  }
}

ContactAssembly::ContactAssembly(const Model& m, const std::vector<int>& eq, const TangentLayout& layout)
    : model_(m), eq_(eq) {
  // The latest enter_step among the parts holding each node, then per pair over its nodes.
  std::vector<int> node_enter(m.num_nodes(), 0);
  for (const auto& part : m.parts)
    for (const auto& block : part.blocks)
      for (int node : block.nodes) node_enter[node] = std::max(node_enter[node], part.enter_step);
  for (const auto& pair : m.contacts) {
    int e = pair.part >= 0 ? m.parts[pair.part].enter_step : 0;
    for (int node : pair.nodes) e = std::max(e, node_enter[node]);
    for (int node : pair.master) e = std::max(e, node_enter[node]);
    pair_enter_.push_back(e);
  }
  for (const auto& pair : m.contacts) {
    std::vector<std::array<int, 4>> pos;
    if (!pair.deformable())
      for (int node : pair.nodes) {
        std::array<int, 4> q{};
        for (int a = 0; a < 2; ++a)
          for (int b = 0; b < 2; ++b) q[2 * a + b] = layout.entry(eq_[2 * node + a], eq_[2 * node + b]);
        pos.push_back(q);
      }
    rigid_pos_.push_back(std::move(pos));
  }
}

Eigen::Matrix2Xd ContactAssembly::current_chain(const std::vector<int>& nodes, const Eigen::VectorXd& u) const {
  Eigen::Matrix2Xd chain(2, static_cast<Eigen::Index>(nodes.size()));
  for (std::size_t i = 0; i < nodes.size(); ++i)
    chain.col(static_cast<Eigen::Index>(i)) = model_.X[nodes[i]].head<2>() + u.segment<2>(2 * nodes[i]);
  return chain;
}

void ContactAssembly::assemble(const Eigen::VectorXd& u, int step, Eigen::VectorXd& R, TangentMatrix* K,
                               double& scale2, int& active, std::vector<char>* active_set) const {
  if (active_set) {
    std::size_t n = 0;
    for (const auto& pair : model_.contacts) n += pair.nodes.size();
    active_set->assign(n, 0);
  }
  std::size_t first = 0;  // the pair's first slave node in active_set
  for (std::size_t c = 0; c < model_.contacts.size(); ++c) {
    const int ci = static_cast<int>(c);
    char* flags = active_set ? active_set->data() + first : nullptr;
    first += model_.contacts[c].nodes.size();
    if (!pair_active(ci, step)) continue;
    if (model_.contacts[c].deformable()) assemble_deformable(ci, u, R, K, scale2, active, flags, 0.0);
    else assemble_rigid(ci, u, R, K, scale2, active, flags, 0.0);
  }
}

void ContactAssembly::add_curvature(const Eigen::VectorXd& u, int step, double factor, TangentMatrix& K) const {
  if (factor == 0) return;
  Eigen::VectorXd R = Eigen::VectorXd::Zero(u.size());
  double scale2 = 0;
  int active = 0;
  for (std::size_t c = 0; c < model_.contacts.size(); ++c) {
    const int ci = static_cast<int>(c);
    if (!pair_active(ci, step)) continue;
    if (model_.contacts[c].deformable()) assemble_deformable(ci, u, R, &K, scale2, active, nullptr, factor);
    else assemble_rigid(ci, u, R, &K, scale2, active, nullptr, factor);
  }
}

void ContactAssembly::assemble_rigid(int c, const Eigen::VectorXd& u, Eigen::VectorXd& R, TangentMatrix* K,
                                     double& scale2, int& active, char* flags, double curvature) const {
  const ContactPair& pair = model_.contacts[c];
  const RigidSurface& rigid = model_.rigid_surfaces[pair.rigid];
  for (std::size_t k = 0; k < pair.nodes.size(); ++k) {
    const int n = pair.nodes[k];
    const Eigen::Vector2d xs = model_.X[n].head<2>() + u.segment<2>(2 * n);
    Eigen::Vector2d f;
    Eigen::Matrix2d Kc;
    const ContactPoint cp = rigid_contact(rigid, xs, pair.areas[k], pair.law, f, K ? &Kc : nullptr);
    if (!cp.active) continue;
    if (curvature != 0) {
      Kc = curvature_part(f, Kc, pair.law, pair.areas[k], cp.gap, curvature);
      for (int q = 0; q < 4; ++q) K->add(rigid_pos_[c][k][q], Kc(q / 2, q % 2));
      continue;
    }
    ++active;
    if (flags) flags[k] = 1;
    R.segment<2>(2 * n) += f;
    scale2 += f.squaredNorm();
    // The gap is a difference of coordinates: its round-off is ~ε_mach |x_s|, times the penalty stiffness.
    if (K) scale2 += Kc.squaredNorm() * xs.squaredNorm();
    if (K)
      for (int q = 0; q < 4; ++q) K->add(rigid_pos_[c][k][q], Kc(q / 2, q % 2));
  }
}

void ContactAssembly::assemble_deformable(int c, const Eigen::VectorXd& u, Eigen::VectorXd& R, TangentMatrix* K,
                                          double& scale2, int& active, char* flags, double curvature) const {
  const ContactPair& pair = model_.contacts[c];
  const Eigen::Matrix2Xd chain = current_chain(pair.master, u);
  for (std::size_t k = 0; k < pair.nodes.size(); ++k) {
    const int s = pair.nodes[k];
    const Eigen::Vector2d xs = model_.X[s].head<2>() + u.segment<2>(2 * s);
    DeformableContactElement e;
    if (!deformable_element(pair, xs, chain, pair.areas[k], K != nullptr, e)) continue;
    // The contact element (slave, master nodes), DOFs (r, z) per node; −1: a ghost slot (no DOFs).
    std::array<int, 5> nodes{};
    nodes[0] = s;
    for (int j = 1; j < 5; ++j) nodes[j] = e.master[j - 1] < 0 ? -1 : pair.master[e.master[j - 1]];
    if (curvature != 0) {
      e.K = curvature_part(e.f, e.K, pair.law, pair.areas[k], e.point.gap, curvature);
      scatter(nodes, e.K, *K);
      continue;
    }
    ++active;
    if (flags) flags[k] = 1;
    double x2 = xs.squaredNorm();
    for (int j = 1; j < 5; ++j)
      if (e.master[j - 1] >= 0) x2 = std::max(x2, chain.col(e.master[j - 1]).squaredNorm());
    for (int a = 0; a < 10; ++a)
      if (nodes[a / 2] >= 0) R(2 * nodes[a / 2] + a % 2) += e.f(a);
    scale2 += e.f.squaredNorm();
    if (!K) continue;
    // The gap is a difference of the nodes' coordinates: round-off ~ε_mach max |x|.
    scale2 += e.K.squaredNorm() * x2;
    scatter(nodes, e.K, *K);
  }
}

void ContactAssembly::scatter(const std::array<int, 5>& nodes, const ContactMatrix10& Ke, TangentMatrix& K) const {
  const TangentLayout& layout = K.layout();
  for (int b = 0; b < 10; ++b) {
    if (nodes[b / 2] < 0) continue;
    const int j = eq_[2 * nodes[b / 2] + b % 2];
    if (j < 0) continue;
    for (int a = 0; a < 10; ++a)
      if (nodes[a / 2] >= 0) K.add(layout.entry(eq_[2 * nodes[a / 2] + a % 2], j), Ke(a, b));
  }
}

std::vector<ContactNodeState> ContactAssembly::states(const Eigen::VectorXd& u, int c, int step) const {
  const ContactPair& pair = model_.contacts[c];
  if (!pair_active(c, step)) {
    std::vector<ContactNodeState> out(pair.nodes.size());
    for (std::size_t k = 0; k < pair.nodes.size(); ++k) out[k].node = pair.nodes[k];
    return out;
  }
  // Current tributary areas on the current chain that gave the reference ones.
  const Eigen::VectorXd current = slave_tributary_areas(current_chain(pair.area_chain, u));
  Eigen::Matrix2Xd master;
  if (pair.deformable()) master = current_chain(pair.master, u);
  std::vector<ContactNodeState> out;
  for (std::size_t k = 0; k < pair.nodes.size(); ++k) {
    ContactNodeState s;
    s.node = pair.nodes[k];
    const Eigen::Vector2d xs = model_.X[s.node].head<2>() + u.segment<2>(2 * s.node);
    if (pair.deformable()) {
      DeformableContactElement e;
      if (deformable_element(pair, xs, master, pair.areas[k], false, e)) s.master_segment = e.segment;
      s.point = e.point;
    } else {
      Eigen::Vector2d f;
      s.point = rigid_contact(model_.rigid_surfaces[pair.rigid], xs, pair.areas[k], pair.law, f, nullptr);
    }
    s.force = s.point.pressure * pair.areas[k];
    out.push_back(s);
  }
  if (pair.reverse >= 0) {
    // Two-pass pair (theory manual §9.1, (9.9)): the reverse pass's slave nodes push on the pair's
    // slave chain, its master; the normal component f_j·n of the force on master node j of its
    // element (f_j = ε A g_N ∂g_N/∂x_j = p_c A w_j n, the shape function w_j of the closest point)
    // is added to that node's normal force.
    const ContactPair& rev = model_.contacts[pair.reverse];
    const Eigen::Matrix2Xd chain = current_chain(rev.master, u);
    const bool flipped = rev.master.front() != pair.nodes.front();  // rev.master: pair.nodes, maybe reversed
    const int last = static_cast<int>(pair.nodes.size()) - 1;
    for (std::size_t k = 0; k < rev.nodes.size(); ++k) {
      const int n = rev.nodes[k];
      const Eigen::Vector2d xs = model_.X[n].head<2>() + u.segment<2>(2 * n);
      DeformableContactElement e;
      if (!deformable_element(rev, xs, chain, rev.areas[k], false, e)) continue;
      for (int j = 0; j < 4; ++j)
        if (e.master[j] >= 0)
          out[flipped ? last - e.master[j] : e.master[j]].force += e.f.segment<2>(2 + 2 * j).dot(e.point.normal);
    }
  }
  for (std::size_t k = 0; k < out.size(); ++k) {
    const double a = current(pair.area_index[k]);
    out[k].pressure = a > 0 ? out[k].force / a : out[k].point.pressure;
  }
  return out;
}

}  // namespace tunica
