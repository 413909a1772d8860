#include "model/meridian_curvature.hpp"

#include <cmath>

namespace tunica {

std::vector<std::vector<double>> meridian_mean_curvature(const Model& model, const Part& part) {
  std::vector<std::vector<double>> H(part.blocks.size());
  // Per node: the segment arriving (as its node b) and leaving (as its node a), as (block, element).
  constexpr std::pair<int, int> kNone{-1, -1};
  std::vector<std::pair<int, int>> in(model.num_nodes(), kNone), out(model.num_nodes(), kNone);
  const auto tangent = [&](const int* en, double& length) {
    const Eigen::Vector2d d = model.X[en[1]].head<2>() - model.X[en[0]].head<2>();
    length = d.norm();
    return length > 0 ? Eigen::Vector2d(d / length) : Eigen::Vector2d::Zero();
  };
  for (std::size_t b = 0; b < part.blocks.size(); ++b) {
    const ElementBlock& block = part.blocks[b];
    if (block.kind != ElementKind::axisym2 && block.kind != ElementKind::shell2) continue;  // a meridian of 2-node segments
    for (int e = 0; e < block.size(); ++e) {
      const int* en = block.element(e);
      out[en[0]] = {static_cast<int>(b), e};
      in[en[1]] = {static_cast<int>(b), e};
    }
  }
  // κ at every node with a segment on each side (the meridian's turning angle over the mean length).
  std::vector<double> kappa(model.num_nodes(), 0.0);
  std::vector<char> has(model.num_nodes(), 0);
  for (int node = 0; node < model.num_nodes(); ++node) {
    if (in[node] == kNone || out[node] == kNone) continue;
    double l_in = 0, l_out = 0;
    const Eigen::Vector2d t_in = tangent(part.blocks[in[node].first].element(in[node].second), l_in);
    const Eigen::Vector2d t_out = tangent(part.blocks[out[node].first].element(out[node].second), l_out);
    const double theta = std::atan2(t_in(0) * t_out(1) - t_in(1) * t_out(0), t_in.dot(t_out));
    if (l_in + l_out > 0) {
      kappa[node] = theta / (0.5 * (l_in + l_out));
      has[node] = 1;
    }
  }
  for (std::size_t b = 0; b < part.blocks.size(); ++b) {
    const ElementBlock& block = part.blocks[b];
    if (block.kind != ElementKind::axisym2 && block.kind != ElementKind::shell2) continue;  // a meridian of 2-node segments
    H[b].assign(block.size(), 0.0);
    for (int e = 0; e < block.size(); ++e) {
      const int* en = block.element(e);
      double length = 0;
      const Eigen::Vector2d t = tangent(en, length);
      const int n = has[en[0]] + has[en[1]];
      const double ks = n > 0 ? (has[en[0]] * kappa[en[0]] + has[en[1]] * kappa[en[1]]) / n : 0.0;
      const double r_mid = 0.5 * (model.X[en[0]](0) + model.X[en[1]](0));
      const double kt = r_mid > 0 ? t(1) / r_mid : 0.0;  // n_r = t_z
      H[b][e] = 0.5 * (ks + kt);
    }
  }
  return H;
}

}  // namespace tunica
