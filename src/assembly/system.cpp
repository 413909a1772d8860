#include "assembly/system.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cmath>
#include <exception>
#include <numbers>
#include <stdexcept>

#include "assembly/shell_nodes.hpp"
#include "assembly/system_coloured.hpp"
#include "elements/axisym_membrane.hpp"
#include "elements/axisym_shell.hpp"
#include "elements/shell_output.hpp"
#include "elements/start_tension.hpp"
#include "loads/axisym_shell_pressure.hpp"
#include "loads/axisym_pressure.hpp"
#include "loads/surface_pressure.hpp"
#include "model/surface_curvature.hpp"

namespace tunica {

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
      const int nen = nodes_per_element(block.kind);
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
  pattern_.resize(num_free_, num_free_);
  pattern_.resizeNonZeros(static_cast<Eigen::Index>(inner.size()));
  std::copy(outer.begin(), outer.end(), pattern_.outerIndexPtr());
  std::copy(inner.begin(), inner.end(), pattern_.innerIndexPtr());
  std::fill(pattern_.valuePtr(), pattern_.valuePtr() + inner.size(), 0.0);
  pattern_.makeCompressed();

  // Scatter positions: index of (i, j) in the CSC value array; reference data of 3-D elements.
  auto position = [&](int i, int j) {
    const int* begin = pattern_.innerIndexPtr() + pattern_.outerIndexPtr()[j];
    const int* end = pattern_.innerIndexPtr() + pattern_.outerIndexPtr()[j + 1];
    return static_cast<int>(std::lower_bound(begin, end, i) - pattern_.innerIndexPtr());
  };
  blocks_.resize(model.parts.size());
  extent_.assign(model.parts.size(), 0.0);
  for (std::size_t p = 0; p < model.parts.size(); ++p) {
    const Part& part = model.parts[p];
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
    for (const auto& block : part.blocks)
      for (int node : block.nodes) {
        lo = lo.cwiseMin(model.X[node]);
        hi = hi.cwiseMax(model.X[node]);
      }
    if (hi(0) >= lo(0)) extent_[p] = (hi - lo).norm();
    std::vector<std::vector<double>> curvature = element_mean_curvature(model, part);
    int first = 0;
    for (const auto& block : part.blocks) {
      Block data;
      if (block.kind == ElementKind::tri3) data.tri = block_references<3>(model, part, block, first);
      if (block.kind == ElementKind::quad4) data.quad = block_references<4>(model, part, block, first);
      const int ndn = unknowns_per_node(block.kind), nd = nodes_per_element(block.kind) * ndn;
      data.scatter.resize(static_cast<std::size_t>(block.size()) * nd * nd);
      int* pos = data.scatter.data();
      for (int e = 0; e < block.size(); ++e) {
        const int* en = block.element(e);
        for (int a = 0; a < nd; ++a)
          for (int b = 0; b < nd; ++b) {
            const int i = eq_[model.node_dof(en[a / ndn], a % ndn)], j = eq_[model.node_dof(en[b / ndn], b % ndn)];
            *pos++ = (i >= 0 && j >= 0) ? position(i, j) : -1;
          }
      }
      colour_elements(block, model.num_nodes(), data.order, data.colour_start);
      data.curvature = std::move(curvature[&block - part.blocks.data()]);
      first += block.size();
      blocks_[p].push_back(std::move(data));
    }
  }

  // Contact: rigid pairs' slave blocks are in the pattern (every node couples with itself),
  // deformable pairs' contact elements by the couplings added above.
  contact_ = std::make_unique<ContactAssembly>(model, eq_, pattern_);

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
        if (dof_enter_[d] > 0 && eq_[d] >= 0) held_.push_back({d, position(eq_[d], eq_[d]), 1.0});
      }
  }
  if (!held_.empty()) compute_hold_stiffness();
}

namespace {

/// Reference and current nodes of a 4-node axisymmetric solid element: column a = (r_a, z_a).
void solid_nodes(const Model& m, const int* en, const Eigen::VectorXd& u, SolidNodes& X, SolidNodes& x) {
  for (int a = 0; a < 4; ++a) {
    X.col(a) = m.X[en[a]].head<2>();
    x.col(a) = X.col(a) + u.segment<2>(2 * en[a]);
  }
}

}  // namespace

void System::compute_hold_stiffness() {
  // k_i = Σ_e (K_e)_ii at u = 0 over the elements of the parts that enter later.
  const Eigen::VectorXd u0 = Eigen::VectorXd::Zero(num_dofs());
  Eigen::VectorXd diag = Eigen::VectorXd::Zero(num_dofs());
  for (std::size_t p = 0; p < model_.parts.size(); ++p) {
    const Part& part = model_.parts[p];
    if (part.enter_step == 0) continue;
    for (std::size_t b = 0; b < part.blocks.size(); ++b) {
      const ElementBlock& block = part.blocks[b];
      for (int e = 0; e < block.size(); ++e) {
        const int* en = block.element(e);
        Eigen::VectorXd d;
        if (block.kind == ElementKind::solid4) {
          SolidNodes X, x;
          SolidVector f;
          SolidMatrix Ke;
          solid_nodes(model_, en, u0, X, x);
          axisym_solid(X, x, *part.solid_material, part.formulation, f, &Ke);
          d = Ke.diagonal();
        } else if (block.kind == ElementKind::shell2) {
          ShellNodes X, x;
          ShellVector f;
          ShellMatrix Ke;
          shell_nodes(model_, en, u0, X, x);
          axisym_shell(X, x, part.thickness, *part.material, f, &Ke, shell_quadrature(part));
          d = Ke.diagonal();
        } else if (block.kind == ElementKind::axisym2) {
          AxisymNodes X, x;
          Eigen::Vector4d f;
          Eigen::Matrix4d Ke;
          for (int a = 0; a < 2; ++a) X.col(a) = x.col(a) = model_.X[en[a]].head<2>();
          axisym_membrane(X, x, part.thickness, *part.material, f, &Ke);
          d = Ke.diagonal();
        } else if (block.kind == ElementKind::tri3) {
          SurfaceNodes<3> x;
          ElementVector<3> f;
          ElementMatrix<3> Ke;
          for (int a = 0; a < 3; ++a) x.col(a) = model_.X[en[a]];
          membrane3d<3>(blocks_[p][b].tri[e], x, *part.material, f, &Ke);
          d = Ke.diagonal();
        } else {
          SurfaceNodes<4> x;
          ElementVector<4> f;
          ElementMatrix<4> Ke;
          for (int a = 0; a < 4; ++a) x.col(a) = model_.X[en[a]];
          membrane3d<4>(blocks_[p][b].quad[e], x, *part.material, f, &Ke);
          d = Ke.diagonal();
        }
        const int ndn = unknowns_per_node(block.kind);
        for (int a = 0; a < d.size(); ++a) diag(model_.node_dof(en[a / ndn], a % ndn)) += d(a);
      }
    }
  }
  double largest = 0;
  for (const auto& h : held_) largest = std::max(largest, diag(h.dof));
  // A DOF without reference stiffness (a membrane's out-of-plane direction) gets the largest one.
  for (auto& h : held_) h.k = diag(h.dof) > 0 ? diag(h.dof) : (largest > 0 ? largest : 1.0);
}

void System::assemble_held(int step, const Eigen::VectorXd& u, Eigen::VectorXd& R, SparseMatrix* K) const {
  for (const auto& h : held_) {
    if (!held(h.dof, step)) continue;
    R(h.dof) += h.k * u(h.dof);
    if (K) K->valuePtr()[h.pos] += h.k;
  }
}

void colour_elements(const ElementBlock& block, int num_nodes, std::vector<int>& order, std::vector<int>& start) {
  const int nen = nodes_per_element(block.kind);
  std::vector<int> colour(block.size());
  // used[node]: bit c set if an element of colour 64·word + c already touches the node.
  int words = 1;
  std::vector<std::uint64_t> used(static_cast<std::size_t>(num_nodes), 0);
  int colours = 0;
  for (int e = 0; e < block.size(); ++e) {
    const int* en = block.element(e);
    for (int w = 0;; ++w) {
      if (w == words) {  // more than 64·words colours (far more than a surface mesh needs): widen the masks
        std::vector<std::uint64_t> wider(static_cast<std::size_t>(num_nodes) * (words + 1), 0);
        for (int n = 0; n < num_nodes; ++n)
          for (int k = 0; k < words; ++k) wider[static_cast<std::size_t>(n) * (words + 1) + k] = used[static_cast<std::size_t>(n) * words + k];
        used.swap(wider);
        ++words;
      }
      std::uint64_t taken = 0;
      for (int a = 0; a < nen; ++a) taken |= used[static_cast<std::size_t>(en[a]) * words + w];
      if (~taken == 0) continue;
      const int c = std::countr_one(taken);
      for (int a = 0; a < nen; ++a) used[static_cast<std::size_t>(en[a]) * words + w] |= std::uint64_t{1} << c;
      colour[e] = 64 * w + c;
      colours = std::max(colours, colour[e] + 1);
      break;
    }
  }
  start.assign(colours + 1, 0);
  for (int e = 0; e < block.size(); ++e) ++start[colour[e] + 1];
  for (int c = 0; c < colours; ++c) start[c + 1] += start[c];
  order.resize(block.size());
  std::vector<int> next(start.begin(), start.end() - 1);
  for (int e = 0; e < block.size(); ++e) order[next[colour[e]]++] = e;
}

void System::apply_boundary(const LoadState& loads, Eigen::VectorXd& u) const {
  for (std::size_t k = 0; k < model_.boundaries.size(); ++k) {
    const auto& b = model_.boundaries[k];
    for (int node : model_.node_sets[b.node_set].nodes)
      for (int d : b.dofs) u(model_.node_dof(node, d)) = loads.boundary[k];
  }
}

namespace {

/// Reference and current nodes of a 2-node axisymmetric element: column a = (r_a, z_a).
void axisym_nodes(const Model& m, const int* en, const Eigen::VectorXd& u, AxisymNodes& X, AxisymNodes& x) {
  for (int a = 0; a < 2; ++a) {
    X.col(a) = m.X[en[a]].head<2>();
    x.col(a) = X.col(a) + u.segment<2>(2 * en[a]);
  }
}

template <int N>
void surface_nodes(const Model& m, const int* en, const Eigen::VectorXd& u, SurfaceNodes<N>& x) {
  for (int a = 0; a < N; ++a) x.col(a) = m.X[en[a]] + u.segment<3>(3 * en[a]);
}

/// Adds element vector and matrix into R and K's values.
template <class V, class M>
void scatter(const int* en, int dpn, const V& f, const M* Ke, const int* pos, Eigen::VectorXd& R, SparseMatrix* K) {
  const int nd = static_cast<int>(f.size());
  for (int a = 0; a < nd; ++a) R(dpn * en[a / dpn] + a % dpn) += f(a);
  if (!K) return;
  double* values = K->valuePtr();
  for (int a = 0; a < nd; ++a)
    for (int b = 0; b < nd; ++b)
      if (const int k = pos[a * nd + b]; k >= 0) values[k] += (*Ke)(a, b);
}

}  // namespace

void System::assemble_axisym(int p, int b, const Eigen::VectorXd& u, double pressure, Eigen::VectorXd& R,
                             SparseMatrix* K, double& scale2) const {
  const Part& part = model_.parts[p];
  const ElementBlock& block = part.blocks[b];
  const int* scatter_pos = blocks_[p][b].scatter.data();
  std::vector<double> scale_e(block.size());  // per element: summed in element order, whatever the threads
  for_each_coloured(blocks_[p][b], [&](int e) {
    Eigen::Vector4d f, fp;
    Eigen::Matrix4d Ke, dfp;
    AxisymNodes X, x;
    const int* en = block.element(e);
    axisym_nodes(model_, en, u, X, x);
    axisym_membrane(X, x, part.thickness, *part.material, f, K ? &Ke : nullptr);
    double s2 = f.squaredNorm();
    if (pressure != 0.0) {
      axisym_pressure(x, pressure, fp, K ? &dfp : nullptr);
      s2 += fp.squaredNorm();
      f -= fp;
      if (K) Ke -= dfp;
    }
    if (K) s2 += Ke.squaredNorm() * (X.col(1) - X.col(0)).squaredNorm();
    scale_e[e] = s2;
    scatter(en, 2, f, K ? &Ke : nullptr, scatter_pos + 16 * e, R, K);
  });
  for (double s2 : scale_e) scale2 += s2;
}

void System::assemble_solid(int p, int b, const Eigen::VectorXd& u, Eigen::VectorXd& R, SparseMatrix* K,
                            double& scale2) const {
  const Part& part = model_.parts[p];
  const ElementBlock& block = part.blocks[b];
  const int* scatter_pos = blocks_[p][b].scatter.data();
  std::vector<double> scale_e(block.size());  // per element: summed in element order, whatever the threads
  for_each_coloured(blocks_[p][b], [&](int e) {
    SolidVector f;
    SolidMatrix Ke;
    SolidNodes X, x;
    const int* en = block.element(e);
    solid_nodes(model_, en, u, X, x);
    axisym_solid(X, x, *part.solid_material, part.formulation, f, K ? &Ke : nullptr);
    double s2 = f.squaredNorm();
    // Stiffness × element size (its diagonal) bounds the round-off of stresses near zero strain.
    if (K) s2 += Ke.squaredNorm() * (X.col(2) - X.col(0)).squaredNorm();
    scale_e[e] = s2;
    scatter(en, 2, f, K ? &Ke : nullptr, scatter_pos + 64 * e, R, K);
  });
  for (double s2 : scale_e) scale2 += s2;
}

template <int N>
void System::assemble_surface(int p, int b, const Eigen::VectorXd& u, double pressure, Eigen::VectorXd& R,
                              SparseMatrix* K, double& scale2) const {
  const Part& part = model_.parts[p];
  const ElementBlock& block = part.blocks[b];
  const Block& data = blocks_[p][b];
  const int* scatter_pos = data.scatter.data();
  constexpr int nd = 3 * N;
  std::vector<double> scale_e(block.size());  // per element: summed in element order, whatever the threads
  for_each_coloured(data, [&](int e) {
    ElementVector<N> f, fp;
    ElementMatrix<N> Ke, dfp;
    SurfaceNodes<N> x;
    const int* en = block.element(e);
    surface_nodes<N>(model_, en, u, x);
    const MembraneReference<N>* ref;
    if constexpr (N == 3) ref = &data.tri[e];
    else ref = &data.quad[e];
    membrane3d<N>(*ref, x, *part.material, f, K ? &Ke : nullptr);
    double s2 = f.squaredNorm();
    if (pressure != 0.0) {
      surface_pressure<N>(x, pressure, fp, K ? &dfp : nullptr);
      s2 += fp.squaredNorm();
      f -= fp;
      if (K) Ke -= dfp;
    }
    if (K) s2 += Ke.squaredNorm() * (model_.X[en[1]] - model_.X[en[0]]).squaredNorm();
    scale_e[e] = s2;
    scatter(en, 3, f, K ? &Ke : nullptr, scatter_pos + nd * nd * e, R, K);
  });
  for (double s2 : scale_e) scale2 += s2;
}

void System::assemble(const Eigen::VectorXd& u, const LoadState& loads, Eigen::VectorXd& R, SparseMatrix* K,
                      double* force_scale, int* active_contacts, std::vector<char>* active_set) const {
  R.setZero(num_dofs());
  double scale2 = 0;
  if (K) {
    if (K->nonZeros() != pattern_.nonZeros()) *K = pattern_;
    std::fill(K->valuePtr(), K->valuePtr() + K->nonZeros(), 0.0);
  }
  const std::vector<double> pressure = part_pressures(loads);

  // Inactive parts (not entered yet) are skipped with their loads; their nodes are held.
  for (std::size_t p = 0; p < model_.parts.size(); ++p) {
    if (!model_.part_active(static_cast<int>(p), loads.step)) continue;
    for (std::size_t b = 0; b < model_.parts[p].blocks.size(); ++b) {
      const int pi = static_cast<int>(p), bi = static_cast<int>(b);
      switch (model_.parts[p].blocks[b].kind) {
        case ElementKind::axisym2: assemble_axisym(pi, bi, u, pressure[p], R, K, scale2); break;
        case ElementKind::tri3: assemble_surface<3>(pi, bi, u, pressure[p], R, K, scale2); break;
        case ElementKind::quad4: assemble_surface<4>(pi, bi, u, pressure[p], R, K, scale2); break;
        case ElementKind::solid4: assemble_solid(pi, bi, u, R, K, scale2); break;
        case ElementKind::shell2: assemble_shell(pi, bi, u, pressure[p], R, K, scale2); break;
      }
    }
  }
  assemble_held(loads.step, u, R, K);
  // Contact, serially in pair and node order (deterministic), after the elements; pairs with a
  // part that has not entered yet are skipped.
  int active = 0;
  contact_->assemble(u, loads.step, R, K, scale2, active, active_set);
  if (active_contacts) *active_contacts = active;
  if (force_scale) *force_scale = std::sqrt(scale2);
}

std::vector<double> System::part_pressures(const LoadState& loads) const {
  std::vector<double> pressure(model_.parts.size(), 0.0);
  for (std::size_t l = 0; l < model_.loads.size(); ++l)
    pressure[model_.loads[l].part] += model_.loads[l].sign * loads.pressure[l];
  return pressure;
}

Eigen::VectorXd System::add_start_stiffness(const LoadState& loads, const Eigen::VectorXd& d, SparseMatrix& K) const {
  Eigen::VectorXd Kd = Eigen::VectorXd::Zero(num_dofs());
  const std::vector<double> pressure = part_pressures(loads);
  for (std::size_t p = 0; p < model_.parts.size(); ++p) {
    if (pressure[p] == 0.0 || !model_.part_active(static_cast<int>(p), loads.step)) continue;
    const double cap = extent_[p] > 0 ? 1.0 / extent_[p] : 0.0;  // |H| floor: T₀ ≤ |p| L
    for (std::size_t b = 0; b < model_.parts[p].blocks.size(); ++b) {
      const ElementBlock& block = model_.parts[p].blocks[b];
      const Block& data = blocks_[p][b];
      const auto kernel = [&]<int N>(const std::vector<MembraneReference<N>>& refs) {
        constexpr int nd = 3 * N;
        for_each_coloured(data, [&](int e) {
          const double T0 = std::abs(pressure[p]) / std::max(std::abs(data.curvature[e]), cap);
          ElementMatrix<N> Ke;
          normal_tension_stiffness<N>(refs[e], T0, Ke);
          const int* en = block.element(e);
          ElementVector<N> f = ElementVector<N>::Zero();
          if (d.size() > 0) {
            ElementVector<N> de;
            for (int a = 0; a < N; ++a) de.template segment<3>(3 * a) = d.segment<3>(3 * en[a]);
            f = Ke * de;
          }
          scatter(en, 3, f, &Ke, data.scatter.data() + nd * nd * e, Kd, &K);
        });
      };
      if (block.kind == ElementKind::tri3) kernel(data.tri);
      if (block.kind == ElementKind::quad4) kernel(data.quad);
    }
  }
  return Kd;
}

std::vector<ContactNodeState> System::contact_states(const Eigen::VectorXd& u, int c, int step) const {
  return contact_->states(u, c, step);
}

Eigen::VectorXd System::pressure_load(const Eigen::VectorXd& u, int l) const {
  const PressureLoad& load = model_.loads[l];
  const Part& part = model_.parts[load.part];
  Eigen::VectorXd g = Eigen::VectorXd::Zero(num_dofs());
  for (const auto& block : part.blocks)
    for (int e = 0; e < block.size(); ++e) {
      const int* en = block.element(e);
      if (block.kind == ElementKind::shell2) {
        ShellNodes X, x;
        ShellVector f;
        shell_nodes(model_, en, u, X, x);
        axisym_shell_pressure(X, x, load.sign, f, nullptr);
        for (int a = 0; a < 8; ++a) g(shell_dof(model_, en, a)) += f(a);
      } else if (block.kind == ElementKind::axisym2) {
        AxisymNodes X, x;
        Eigen::Vector4d f;
        axisym_nodes(model_, en, u, X, x);
        axisym_pressure(x, load.sign, f, nullptr);
        for (int a = 0; a < 4; ++a) g(2 * en[a / 2] + a % 2) += f(a);
      } else if (block.kind == ElementKind::tri3) {
        SurfaceNodes<3> x;
        ElementVector<3> f;
        surface_nodes<3>(model_, en, u, x);
        surface_pressure<3>(x, load.sign, f, nullptr);
        for (int a = 0; a < 9; ++a) g(3 * en[a / 3] + a % 3) += f(a);
      } else {
        SurfaceNodes<4> x;
        ElementVector<4> f;
        surface_nodes<4>(model_, en, u, x);
        surface_pressure<4>(x, load.sign, f, nullptr);
        for (int a = 0; a < 12; ++a) g(3 * en[a / 3] + a % 3) += f(a);
      }
    }
  return g;
}

double System::volume(const Eigen::VectorXd& u, int l, Eigen::VectorXd* grad) const {
  const PressureLoad& load = model_.loads[l];
  const Part& part = model_.parts[load.part];
  if (grad) grad->setZero(num_dofs());
  double V = 0;
  for (const auto& block : part.blocks)
    for (int e = 0; e < block.size(); ++e) {
      const int* en = block.element(e);
      if (block.kind == ElementKind::shell2) {
        // V_e = π ∫ r² dz on the Hermite meridian (loads/axisym_shell_pressure.hpp).
        ShellNodes X, x;
        ShellVector ge;
        shell_nodes(model_, en, u, X, x);
        V += axisym_shell_volume(X, x, grad ? &ge : nullptr);
        if (grad)
          for (int a = 0; a < 8; ++a) (*grad)(shell_dof(model_, en, a)) += ge(a);
      } else if (block.kind == ElementKind::axisym2) {
        // V_e = π ∫ r² dz = π Δz (r1² + r1 r2 + r2²)/3 for a straight segment.
        AxisymNodes X, x;
        axisym_nodes(model_, en, u, X, x);
        const double r1 = x(0, 0), r2 = x(0, 1), dz = x(1, 1) - x(1, 0);
        const double q = (r1 * r1 + r1 * r2 + r2 * r2) / 3.0;
        V += std::numbers::pi * dz * q;
        if (grad) {
          (*grad)(2 * en[0]) += std::numbers::pi * dz * (2 * r1 + r2) / 3.0;
          (*grad)(2 * en[1]) += std::numbers::pi * dz * (r1 + 2 * r2) / 3.0;
          (*grad)(2 * en[0] + 1) -= std::numbers::pi * q;
          (*grad)(2 * en[1] + 1) += std::numbers::pi * q;
        }
      } else if (block.kind == ElementKind::tri3) {
        SurfaceNodes<3> x;
        ElementVector<3> g;
        surface_nodes<3>(model_, en, u, x);
        V += enclosed_volume<3>(x, load.volume, grad ? &g : nullptr);
        if (grad)
          for (int a = 0; a < 9; ++a) (*grad)(3 * en[a / 3] + a % 3) += g(a);
      } else {
        SurfaceNodes<4> x;
        ElementVector<4> g;
        surface_nodes<4>(model_, en, u, x);
        V += enclosed_volume<4>(x, load.volume, grad ? &g : nullptr);
        if (grad)
          for (int a = 0; a < 12; ++a) (*grad)(3 * en[a / 3] + a % 3) += g(a);
      }
    }
  // The volume is on the side the pressure pushes away from: flipping the load flips the sign.
  if (load.sign < 0) {
    V = -V;
    if (grad) *grad = -*grad;
  }
  return V;
}

std::vector<SolidPoint> System::solid_points(const Eigen::VectorXd& u, int p) const {
  const Part& part = model_.parts[p];
  std::vector<SolidPoint> out;
  if (!part.is_solid()) return out;
  for (const auto& block : part.blocks) {
    out.reserve(out.size() + 4 * static_cast<std::size_t>(block.size()));
    for (int e = 0; e < block.size(); ++e) {
      SolidNodes X, x;
      SolidVector f;
      std::array<SolidPoint, 4> pts;
      solid_nodes(model_, block.element(e), u, X, x);
      axisym_solid(X, x, *part.solid_material, part.formulation, f, nullptr, &pts);
      out.insert(out.end(), pts.begin(), pts.end());
    }
  }
  return out;
}

double System::part_energy(const Eigen::VectorXd& u, int p) const {
  const Part& part = model_.parts[p];
  double energy = 0;
  if (part.is_solid()) {
    for (const auto& block : part.blocks)
      for (int e = 0; e < block.size(); ++e) {
        SolidNodes X, x;
        SolidVector f;
        solid_nodes(model_, block.element(e), u, X, x);
        energy += axisym_solid(X, x, *part.solid_material, part.formulation, f, nullptr);
      }
    return energy;
  }
  for (const auto& pt : points(u, p)) energy += pt.W * pt.weight;
  return energy;
}

std::vector<MembranePoint> System::points(const Eigen::VectorXd& u, int p) const {
  const Part& part = model_.parts[p];
  std::vector<MembranePoint> out;
  if (part.is_solid()) return out;
  for (std::size_t b = 0; b < part.blocks.size(); ++b) {
    const ElementBlock& block = part.blocks[b];
    out.reserve(out.size() + static_cast<std::size_t>(block.size()) * points_per_element(part, block.kind));
    for (int e = 0; e < block.size(); ++e) {
      const int* en = block.element(e);
      if (block.kind == ElementKind::shell2) {
        ShellNodes X, x;
        ShellVector f;
        std::vector<ShellPoint> pts;
        shell_nodes(model_, en, u, X, x);
        axisym_shell(X, x, part.thickness, *part.material, f, nullptr, shell_quadrature(part), &pts);
        for (const auto& pt : pts) out.push_back(shell_membrane_point(pt, part.thickness));
      } else if (block.kind == ElementKind::axisym2) {
        AxisymNodes X, x;
        Eigen::Vector4d f;
        std::array<MembranePoint, 2> pts;
        axisym_nodes(model_, en, u, X, x);
        axisym_membrane(X, x, part.thickness, *part.material, f, nullptr, &pts);
        out.insert(out.end(), pts.begin(), pts.end());
      } else if (block.kind == ElementKind::tri3) {
        SurfaceNodes<3> x;
        ElementVector<3> f;
        std::array<MembranePoint, 1> pts;
        surface_nodes<3>(model_, en, u, x);
        membrane3d<3>(blocks_[p][b].tri[e], x, *part.material, f, nullptr, &pts);
        out.insert(out.end(), pts.begin(), pts.end());
      } else {
        SurfaceNodes<4> x;
        ElementVector<4> f;
        std::array<MembranePoint, 4> pts;
        surface_nodes<4>(model_, en, u, x);
        membrane3d<4>(blocks_[p][b].quad[e], x, *part.material, f, nullptr, &pts);
        out.insert(out.end(), pts.begin(), pts.end());
      }
    }
  }
  return out;
}

}  // namespace tunica
