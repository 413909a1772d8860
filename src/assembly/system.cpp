#include "assembly/system.hpp"

#include <algorithm>
#include <cmath>

#include "loads/axisym_pressure.hpp"

namespace tunica {

System::System(const Model& model) : model_(model) {
  const int n = model.num_dofs();
  std::vector<char> fixed(n, 0);
  for (const auto& b : model.boundaries)
    for (int node : model.node_sets[b.node_set].nodes)
      for (int d : b.dofs) fixed[kDofsPerNode * node + d] = 1;
  eq_.assign(n, -1);
  for (int i = 0; i < n; ++i) {
    if (fixed[i]) prescribed_.push_back(i);
    else eq_[i] = num_free_++;
  }

  // Pattern: every pair of free DOFs that share an element.
  std::vector<Eigen::Triplet<double>> trip;
  for (const auto& part : model.parts)
    for (const auto& e : part.elements)
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b) {
          const int i = eq_[kDofsPerNode * e[a / 2] + a % 2], j = eq_[kDofsPerNode * e[b / 2] + b % 2];
          if (i >= 0 && j >= 0) trip.emplace_back(i, j, 0.0);
        }
  pattern_.resize(num_free_, num_free_);
  pattern_.setFromTriplets(trip.begin(), trip.end());
  pattern_.makeCompressed();

  // Scatter positions: index of (i, j) in the CSC value array.
  auto position = [&](int i, int j) {
    const int* begin = pattern_.innerIndexPtr() + pattern_.outerIndexPtr()[j];
    const int* end = pattern_.innerIndexPtr() + pattern_.outerIndexPtr()[j + 1];
    return static_cast<int>(std::lower_bound(begin, end, i) - pattern_.innerIndexPtr());
  };
  scatter_.resize(model.parts.size());
  for (std::size_t p = 0; p < model.parts.size(); ++p)
    for (const auto& e : model.parts[p].elements) {
      std::array<int, 16> pos;
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b) {
          const int i = eq_[kDofsPerNode * e[a / 2] + a % 2], j = eq_[kDofsPerNode * e[b / 2] + b % 2];
          pos[4 * a + b] = (i >= 0 && j >= 0) ? position(i, j) : -1;
        }
      scatter_[p].push_back(pos);
    }
}

void System::apply_boundary(const LoadState& loads, Eigen::VectorXd& u) const {
  for (std::size_t k = 0; k < model_.boundaries.size(); ++k) {
    const auto& b = model_.boundaries[k];
    for (int node : model_.node_sets[b.node_set].nodes)
      for (int d : b.dofs) u(kDofsPerNode * node + d) = loads.boundary[k];
  }
}

AxisymNodes System::reference(const std::array<int, 2>& e) const {
  AxisymNodes X;
  X.col(0) = model_.X[e[0]];
  X.col(1) = model_.X[e[1]];
  return X;
}

AxisymNodes System::current(const std::array<int, 2>& e, const Eigen::VectorXd& u) const {
  AxisymNodes x = reference(e);
  x.col(0) += u.segment<2>(kDofsPerNode * e[0]);
  x.col(1) += u.segment<2>(kDofsPerNode * e[1]);
  return x;
}

void System::assemble(const Eigen::VectorXd& u, const LoadState& loads, Eigen::VectorXd& R, SparseMatrix* K,
                      double* force_scale) const {
  R.setZero(num_dofs());
  double scale2 = 0;
  if (K) {
    if (K->nonZeros() != pattern_.nonZeros()) *K = pattern_;
    std::fill(K->valuePtr(), K->valuePtr() + K->nonZeros(), 0.0);
  }
  // Pressure per part (sum of the loads acting on it, with their sides).
  std::vector<double> pressure(model_.parts.size(), 0.0);
  for (std::size_t l = 0; l < model_.loads.size(); ++l)
    pressure[model_.loads[l].part] += model_.loads[l].sign * loads.pressure[l];

  Eigen::Vector4d f, fp;
  Eigen::Matrix4d Ke, dfp;
  for (std::size_t p = 0; p < model_.parts.size(); ++p) {
    const Part& part = model_.parts[p];
    for (std::size_t k = 0; k < part.elements.size(); ++k) {
      const auto& e = part.elements[k];
      const AxisymNodes x = current(e, u);
      axisym_membrane(reference(e), x, part.thickness, *part.material, f, K ? &Ke : nullptr);
      scale2 += f.squaredNorm();
      if (pressure[p] != 0.0) {
        axisym_pressure(x, pressure[p], fp, K ? &dfp : nullptr);
        scale2 += fp.squaredNorm();
        f -= fp;
        if (K) Ke -= dfp;
      }
      for (int a = 0; a < 4; ++a) R(kDofsPerNode * e[a / 2] + a % 2) += f(a);
      if (K) {
        scale2 += Ke.squaredNorm() * (model_.X[e[1]] - model_.X[e[0]]).squaredNorm();
        const auto& pos = scatter_[p][k];
        double* values = K->valuePtr();
        for (int ab = 0; ab < 16; ++ab)
          if (pos[ab] >= 0) values[pos[ab]] += Ke(ab / 4, ab % 4);
      }
    }
  }
  if (force_scale) *force_scale = std::sqrt(scale2);
}

std::vector<MembranePoint> System::points(const Eigen::VectorXd& u, int p) const {
  const Part& part = model_.parts[p];
  std::vector<MembranePoint> out;
  out.reserve(2 * part.elements.size());
  Eigen::Vector4d f;
  std::array<MembranePoint, 2> pts;
  for (const auto& e : part.elements) {
    axisym_membrane(reference(e), current(e, u), part.thickness, *part.material, f, nullptr, &pts);
    out.push_back(pts[0]);
    out.push_back(pts[1]);
  }
  return out;
}

}  // namespace tunica
