#include "assembly/system.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cmath>
#include <exception>
#include <numbers>
#include <stdexcept>

#include "materials/membrane_material.hpp"
#include "model/meridian_curvature.hpp"
#include "model/surface_curvature.hpp"

namespace tunica {

namespace {

/// c of the slack step's tension T̄ = c μ₀ H, theory manual (7.14).
constexpr double kSlackTension = 0.1;

}  // namespace

System::System(const Model& model) : model_(model), dpn_(model.dofs_per_node()) {
  const int n = model.num_dofs();
  std::vector<char> fixed(n, 0);
  for (const auto& b : model.boundaries)
    for (int node : model.node_sets[b.node_set].nodes)
      for (int d : b.dofs) fixed[model.node_dof(node, d)] = 1;
  // Equations node by node (a shell node's slopes right after its position), so that a node's
  // equations are consecutive and grow with the node number.
  eq_.assign(n, -1);
  for (int node = 0; node < model.num_nodes(); ++node)
    for (int c = 0; c < model.node_dof_count(node); ++c)
      if (const int d = model.node_dof(node, c); !fixed[d]) eq_[d] = num_free_++;
  for (int i = 0; i < n; ++i)
    if (fixed[i]) prescribed_.push_back(i);

  // Pattern: every pair of free DOFs whose nodes share an element, built column by
  // column from the sorted node adjacency (no triplet list of (n·d)² per element).
  std::vector<std::vector<int>> adjacent(model.num_nodes());
  for (const auto& part : model.parts)
    for (const auto& block : part.blocks) {
      const int nen = element_type(block.kind).nodes;
      for (int e = 0; e < block.size(); ++e) {
        const int* en = block.element(e);
        for (int a = 0; a < nen; ++a)
          for (int b = 0; b < nen; ++b) adjacent[en[a]].push_back(en[b]);
      }
    }
  // Deformable contact pairs: every slave node with every master node (contact_assembly.hpp).
  ContactAssembly::add_couplings(model, adjacent);
  std::vector<int> outer(num_free_ + 1, 0), inner;
  for (int node = 0; node < model.num_nodes(); ++node) {
    auto& adj = adjacent[node];
    std::sort(adj.begin(), adj.end());
    adj.erase(std::unique(adj.begin(), adj.end()), adj.end());
    for (int c = 0; c < model.node_dof_count(node); ++c) {
      const int j = eq_[model.node_dof(node, c)];
      if (j < 0) continue;
      // Equation numbers grow with the node number and within a node, so rows come out sorted.
      for (int m : adj)
        for (int r = 0; r < model.node_dof_count(m); ++r)
          if (const int i = eq_[model.node_dof(m, r)]; i >= 0) inner.push_back(i);
      outer[j + 1] = static_cast<int>(inner.size());
    }
    adj.clear();
    adj.shrink_to_fit();
  }
  {
    SparseMatrix pattern(num_free_, num_free_);
    pattern.resizeNonZeros(static_cast<Eigen::Index>(inner.size()));
    std::copy(outer.begin(), outer.end(), pattern.outerIndexPtr());
    std::copy(inner.begin(), inner.end(), pattern.innerIndexPtr());
    std::fill(pattern.valuePtr(), pattern.valuePtr() + inner.size(), 0.0);
    pattern.makeCompressed();
    std::vector<int>().swap(inner);
    // CHOLMOD's symbolic analysis, once: the storage the tangent is assembled in.
    layout_ = std::make_shared<const TangentLayout>(std::move(pattern));
  }
  blocks_.resize(model.parts.size());
  extent_.assign(model.parts.size(), 0.0);
  slack_tension_.assign(model.parts.size(), 0.0);
  for (std::size_t p = 0; p < model.parts.size(); ++p) {
    const Part& part = model.parts[p];
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
    for (const auto& block : part.blocks)
      for (int node : block.nodes) {
        lo = lo.cwiseMin(model.X[node]);
        hi = hi.cwiseMax(model.X[node]);
      }
    if (hi(0) >= lo(0)) extent_[p] = (hi - lo).norm();
    if (part.material && part.thickness > 0) {
      // μ₀ from the tangent at rest: an incompressible membrane's dS11/dE11 = dS22/dE22 = 4μ there.
      const MembraneResponse rest = membrane_response(*part.material, Eigen::Vector3d(1, 1, 0));
      const double mu0 = (rest.D(0, 0) + rest.D(1, 1)) / 8;
      if (std::isfinite(mu0) && mu0 > 0) slack_tension_[p] = kSlackTension * mu0 * part.thickness;
    }
    std::vector<std::vector<double>> curvature = element_mean_curvature(model, part);
    std::vector<std::vector<double>> meridian = meridian_mean_curvature(model, part);
    for (std::size_t b = 0; b < curvature.size(); ++b)
      if (!meridian[b].empty()) curvature[b] = std::move(meridian[b]);
    int first = 0;
    for (const auto& block : part.blocks) {
      const ElementType& type = element_type(block.kind);
      BlockLayout layout;
      layout.slots = layout_->slots();
      const int ndn = type.unknowns_per_node, nd = type.nodes * ndn;
      layout.scatter.resize(static_cast<std::size_t>(block.size()) * nd * nd);
      int* code = layout.scatter.data();
      for (int e = 0; e < block.size(); ++e) {
        const int* en = block.element(e);
        for (int a = 0; a < nd; ++a)
          for (int b = 0; b < nd; ++b) {
            const int i = eq_[model.node_dof(en[a / ndn], a % ndn)], j = eq_[model.node_dof(en[b / ndn], b % ndn)];
            *code++ = layout_->entry(i, j);
          }
      }
      colour_elements(block, model.num_nodes(), layout);
      blocks_[p].push_back(type.make(BlockContext{.model = model,
                                                  .part = part,
                                                  .block = block,
                                                  .first_element = first,
                                                  .layout = std::move(layout),
                                                  .curvature = std::move(curvature[&block - part.blocks.data()])}));
      first += block.size();
    }
  }

  // Contact: rigid pairs' slave blocks are in the pattern (every node couples with itself),
  // deformable pairs' contact elements by the couplings added above.
  contact_ = std::make_unique<ContactAssembly>(model, eq_, *layout_);

  // Parts that enter later: the step from which each DOF may move, and the held free DOFs.
  dof_enter_.assign(n, 0);
  {
    std::vector<int> node_enter(model.num_nodes(), -1);
    for (const auto& part : model.parts)
      for (const auto& block : part.blocks)
        for (int node : block.nodes)
          node_enter[node] = node_enter[node] < 0 ? part.enter_step : std::min(node_enter[node], part.enter_step);
    for (int node = 0; node < model.num_nodes(); ++node)
      for (int c = 0; c < model.node_dof_count(node); ++c) {
        const int d = model.node_dof(node, c);
        dof_enter_[d] = std::max(0, node_enter[node]);
        if (dof_enter_[d] > 0 && eq_[d] >= 0) held_.push_back({d, layout_->entry(eq_[d], eq_[d]), 1.0});
      }
  }
  if (!held_.empty()) compute_hold_stiffness();
}

void System::compute_hold_stiffness() {
  // k_i = Σ_e (K_e)_ii at u = 0 over the elements of the parts that enter later.
  Eigen::VectorXd diag = Eigen::VectorXd::Zero(num_dofs());
  for (std::size_t p = 0; p < model_.parts.size(); ++p)
    if (model_.parts[p].enter_step != 0)
      for (const auto& block : blocks_[p]) block->reference_diagonal(diag);
  double largest = 0;
  for (const auto& h : held_) largest = std::max(largest, diag(h.dof));
  // A DOF without reference stiffness (a membrane's out-of-plane direction) gets the largest one.
  for (auto& h : held_) h.k = diag(h.dof) > 0 ? diag(h.dof) : (largest > 0 ? largest : 1.0);
}

void System::assemble_held(int step, const Eigen::VectorXd& u, Eigen::VectorXd& R, TangentMatrix* K) const {
  for (const auto& h : held_) {
    if (!held(h.dof, step)) continue;
    R(h.dof) += h.k * u(h.dof);
    if (K) K->add(h.pos, h.k);
  }
}

int colour_run_length(int elements) {
  // About 128 runs per block, of 32 to 4096 elements: enough runs per colour to share among the
  // threads, and long enough that consecutive elements, which share nodes and so entries of K,
  // are assembled one after the other (a colour of single elements writes K all over at every colour).
  return std::clamp(elements / 128, 32, 4096);
}

void colour_elements(const ElementBlock& block, int num_nodes, BlockLayout& layout) {
  const int nen = nodes_per_element(block.kind), n = block.size();
  const int length = colour_run_length(n), runs = (n + length - 1) / length;
  std::vector<int> colour(runs);
  // used[node]: bit c set if a run of colour 64·word + c already touches the node.
  int words = 1;
  std::vector<std::uint64_t> used(static_cast<std::size_t>(num_nodes), 0);
  int colours = 0;
  for (int r = 0; r < runs; ++r) {
    const int first = r * length, last = std::min(n, first + length);
    for (int w = 0;; ++w) {
      if (w == words) {  // more than 64·words colours (far more than a surface mesh needs): widen the masks
        std::vector<std::uint64_t> wider(static_cast<std::size_t>(num_nodes) * (words + 1), 0);
        for (int m = 0; m < num_nodes; ++m)
          for (int k = 0; k < words; ++k) wider[static_cast<std::size_t>(m) * (words + 1) + k] = used[static_cast<std::size_t>(m) * words + k];
        used.swap(wider);
        ++words;
      }
      std::uint64_t taken = 0;
      for (int e = first; e < last; ++e)
        for (int a = 0; a < nen; ++a) taken |= used[static_cast<std::size_t>(block.element(e)[a]) * words + w];
      if (~taken == 0) continue;
      const int c = std::countr_one(taken);
      for (int e = first; e < last; ++e)
        for (int a = 0; a < nen; ++a) used[static_cast<std::size_t>(block.element(e)[a]) * words + w] |= std::uint64_t{1} << c;
      colour[r] = 64 * w + c;
      colours = std::max(colours, colour[r] + 1);
      break;
    }
  }
  // Runs colour by colour (ascending within a colour), each run's elements ascending.
  layout.colour_start.assign(colours + 1, 0);
  for (int r = 0; r < runs; ++r) ++layout.colour_start[colour[r] + 1];
  for (int c = 0; c < colours; ++c) layout.colour_start[c + 1] += layout.colour_start[c];
  std::vector<int> run_order(runs);
  std::vector<int> next(layout.colour_start.begin(), layout.colour_start.end() - 1);
  for (int r = 0; r < runs; ++r) run_order[next[colour[r]]++] = r;
  layout.order.clear();
  layout.order.reserve(n);
  layout.run_start.assign(1, 0);
  for (int r : run_order) {
    for (int e = r * length; e < std::min(n, (r + 1) * length); ++e) layout.order.push_back(e);
    layout.run_start.push_back(static_cast<int>(layout.order.size()));
  }
}

void System::apply_boundary(const LoadState& loads, Eigen::VectorXd& u) const {
  for (std::size_t k = 0; k < model_.boundaries.size(); ++k) {
    const auto& b = model_.boundaries[k];
    for (int node : model_.node_sets[b.node_set].nodes)
      for (int d : b.dofs) u(model_.node_dof(node, d)) = loads.boundary[k];
  }
}

void System::assemble(const Eigen::VectorXd& u, const LoadState& loads, Eigen::VectorXd& R, TangentMatrix* K,
                      double* force_scale, int* active_contacts, std::vector<char>* active_set) const {
  R.setZero(num_dofs());
  double scale2 = 0;
  if (K) {
    if (K->shared_layout() != layout_) *K = tangent(true);
    else K->set_zero();
  }
  const std::vector<double> pressure = part_pressures(loads);

  // Inactive parts (not entered yet) are skipped with their loads; their nodes are held.
  for (std::size_t p = 0; p < model_.parts.size(); ++p) {
    if (!model_.part_active(static_cast<int>(p), loads.step)) continue;
    if (inverse(loads))
      for (const auto& block : blocks_[p]) block->assemble_inverse(u, pressure[p], R, K, scale2);
    else
      for (const auto& block : blocks_[p]) block->assemble(u, pressure[p], R, K, scale2);
  }
  assemble_held(loads.step, u, R, K);
  // Contact, serially in pair and node order (deterministic), after the elements; pairs with a
  // part that has not entered yet are skipped.
  int active = 0;
  contact_->assemble(u, loads.step, R, K, scale2, active, active_set);
  if (active_contacts) *active_contacts = active;
  if (force_scale) *force_scale = std::sqrt(scale2);
}

void System::assemble_full(const Eigen::VectorXd& u, const LoadState& loads, Eigen::VectorXd& R, SparseMatrix& K,
                           double* force_scale, int* active_contacts, std::vector<char>* active_set) const {
  TangentMatrix T = tangent(true);
  assemble(u, loads, R, &T, force_scale, active_contacts, active_set);
  T.expand(K);
}

std::vector<double> System::part_pressures(const LoadState& loads) const {
  std::vector<double> pressure(model_.parts.size(), 0.0);
  for (std::size_t l = 0; l < model_.loads.size(); ++l)
    pressure[model_.loads[l].part] += model_.loads[l].sign * loads.pressure[l];
  return pressure;
}

Eigen::VectorXd System::add_start_stiffness(const LoadState& loads, const Eigen::VectorXd& d, TangentMatrix& K) const {
  Eigen::VectorXd Kd = Eigen::VectorXd::Zero(num_dofs());
  const std::vector<double> pressure = part_pressures(loads);
  for (std::size_t p = 0; p < model_.parts.size(); ++p) {
    if (pressure[p] == 0.0 || !model_.part_active(static_cast<int>(p), loads.step)) continue;
    const double cap = extent_[p] > 0 ? 1.0 / extent_[p] : 0.0;  // |H| floor: T₀ ≤ |p| L
    // The inverse problem's ∂R/∂X is about −∂R/∂x near the stress-free state (R depends on x − X to
    // first order): its start stiffness is −K₀, (13.8).
    const double T = inverse(loads) ? -std::abs(pressure[p]) : std::abs(pressure[p]);
    StartTension t;
    t.abs_pressure = T;
    t.cap = cap;
    for (const auto& block : blocks_[p]) block->start_stiffness(t, d, Kd, K);
  }
  return Kd;
}

Eigen::VectorXd System::add_slack_stiffness(double theta, int step, const Eigen::VectorXd& d, TangentMatrix& K) const {
  Eigen::VectorXd Kd = Eigen::VectorXd::Zero(num_dofs());
  for (std::size_t p = 0; p < model_.parts.size(); ++p) {
    if (slack_tension_[p] == 0.0 || !model_.part_active(static_cast<int>(p), step)) continue;
    StartTension t;
    t.uniform = theta * slack_tension_[p];
    for (const auto& block : blocks_[p]) block->start_stiffness(t, d, Kd, K);
  }
  return Kd;
}

void System::add_contact_curvature(const Eigen::VectorXd& u, const LoadState& loads, double factor,
                                   TangentMatrix& K) const {
  contact_->add_curvature(u, loads.step, factor, K);
}

std::vector<ContactNodeState> System::contact_states(const Eigen::VectorXd& u, int c, int step) const {
  return contact_->states(u, c, step);
}

Eigen::VectorXd System::pressure_load(const Eigen::VectorXd& u, int l) const {
  const PressureLoad& load = model_.loads[l];
  Eigen::VectorXd g = Eigen::VectorXd::Zero(num_dofs());
  for (const auto& block : blocks_[load.part]) block->pressure_load(u, load.sign, g);
  return g;
}

double System::volume(const Eigen::VectorXd& u, int l, Eigen::VectorXd* grad) const {
  const PressureLoad& load = model_.loads[l];
  if (grad) grad->setZero(num_dofs());
  double V = 0;
  for (const auto& block : blocks_[load.part]) block->add_volume(u, load.volume, V, grad);
  // The volume is on the side the pressure pushes away from: flipping the load flips the sign.
  if (load.sign < 0) {
    V = -V;
    if (grad) *grad = -*grad;
  }
  return V;
}

std::vector<SolidPoint> System::solid_points(const Eigen::VectorXd& u, int p) const {
  std::vector<SolidPoint> out;
  for (const auto& block : blocks_[p]) block->solid_points(u, out);
  return out;
}

double System::part_energy(const Eigen::VectorXd& u, int p) const {
  double energy = 0;
  for (const auto& block : blocks_[p]) block->add_energy(u, energy);
  return energy;
}

std::vector<MembranePoint> System::points(const Eigen::VectorXd& u, int p, int step) const {
  std::vector<MembranePoint> out;
  LoadState at;
  at.step = step;
  if (inverse(at))
    for (const auto& block : blocks_[p]) block->inverse_points(u, out);
  else
    for (const auto& block : blocks_[p]) block->membrane_points(u, out);
  return out;
}

}  // namespace tunica
