// H_e = (Σ_shared |e| θ_e / 4) / A_e × P_e / P_shared (surface_curvature.hpp).
#include "model/surface_curvature.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace tunica {

namespace {

struct Facet {
  Eigen::Vector3d centroid, normal;
  double area = 0, perimeter = 0;
};

Facet facet(const Model& model, const int* en, int n) {
  Facet f;
  f.centroid.setZero();
  for (int a = 0; a < n; ++a) f.centroid += model.X[en[a]];
  f.centroid /= n;
  const Eigen::Vector3d g = n == 3 ? Eigen::Vector3d((model.X[en[1]] - model.X[en[0]]).cross(model.X[en[2]] - model.X[en[0]]))
                                   : Eigen::Vector3d((model.X[en[2]] - model.X[en[0]]).cross(model.X[en[3]] - model.X[en[1]]));
  const double len = g.norm();
  f.normal = len > 0 ? Eigen::Vector3d(g / len) : Eigen::Vector3d::Zero();
  f.area = 0.5 * len;  // exact for a triangle; a quadrilateral's half diagonal cross product
  for (int a = 0; a < n; ++a) f.perimeter += (model.X[en[(a + 1) % n]] - model.X[en[a]]).norm();
  return f;
}

}  // namespace

std::vector<std::vector<double>> element_mean_curvature(const Model& model, const Part& part) {
  std::vector<std::vector<double>> H(part.blocks.size());
  std::vector<std::vector<Facet>> facets(part.blocks.size());
  std::vector<std::vector<double>> shared(part.blocks.size());  // P_shared
  // The first element seen on each edge (sorted node pair): block and element.
  std::map<std::pair<int, int>, std::pair<int, int>> first;
  std::vector<std::pair<std::pair<int, int>, std::pair<int, int>>> pairs;  // elements sharing an edge
  for (std::size_t b = 0; b < part.blocks.size(); ++b) {
    const ElementBlock& block = part.blocks[b];
    if (!is_surface_kind(block.kind)) continue;
    const int n = corner_nodes(block.kind);
    H[b].assign(block.size(), 0.0);
    shared[b].assign(block.size(), 0.0);
    facets[b].resize(block.size());
    for (int e = 0; e < block.size(); ++e) facets[b][e] = facet(model, block.element(e), n);
  }
  for (std::size_t b = 0; b < part.blocks.size(); ++b) {
    const ElementBlock& block = part.blocks[b];
    if (facets[b].empty()) continue;
    const int n = corner_nodes(block.kind);
    for (int e = 0; e < block.size(); ++e) {
      const int* en = block.element(e);
      for (int a = 0; a < n; ++a) {
        const std::pair<int, int> edge = std::minmax(en[a], en[(a + 1) % n]);
        const auto [it, inserted] = first.emplace(edge, std::make_pair(static_cast<int>(b), e));
        if (inserted) continue;
        const auto [bf, f] = it->second;
        const Facet &fe = facets[b][e], &ff = facets[bf][f];
        const double length = (model.X[edge.second] - model.X[edge.first]).norm();
        double theta = std::atan2(fe.normal.cross(ff.normal).norm(), fe.normal.dot(ff.normal));
        if ((ff.normal - fe.normal).dot(ff.centroid - fe.centroid) < 0) theta = -theta;
        H[b][e] += 0.25 * length * theta;
        H[bf][f] += 0.25 * length * theta;
        pairs.push_back({{static_cast<int>(b), e}, {bf, f}});
        shared[b][e] += length;
        shared[bf][f] += length;
      }
    }
  }
  for (std::size_t b = 0; b < H.size(); ++b)
    for (std::size_t e = 0; e < H[b].size(); ++e) {
      const Facet& fe = facets[b][e];
      H[b][e] = shared[b][e] > 0 && fe.area > 0 ? H[b][e] / fe.area * fe.perimeter / shared[b][e] : 0.0;
    }
  // One smoothing pass: the area-weighted mean over the facet and its edge neighbours.
  std::vector<std::vector<double>> sum(H.size()), weight(H.size());
  for (std::size_t b = 0; b < H.size(); ++b) {
    sum[b].resize(H[b].size());
    weight[b].resize(H[b].size());
    for (std::size_t e = 0; e < H[b].size(); ++e) {
      weight[b][e] = facets[b][e].area;
      sum[b][e] = facets[b][e].area * H[b][e];
    }
  }
  for (const auto& [x, y] : pairs) {
    sum[x.first][x.second] += facets[y.first][y.second].area * H[y.first][y.second];
    weight[x.first][x.second] += facets[y.first][y.second].area;
    sum[y.first][y.second] += facets[x.first][x.second].area * H[x.first][x.second];
    weight[y.first][y.second] += facets[x.first][x.second].area;
  }
  for (std::size_t b = 0; b < H.size(); ++b)
    for (std::size_t e = 0; e < H[b].size(); ++e)
      if (weight[b][e] > 0) H[b][e] = sum[b][e] / weight[b][e];
  return H;
}

}  // namespace tunica
