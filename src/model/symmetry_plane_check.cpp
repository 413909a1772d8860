#include "model/symmetry_plane_check.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace tunica {

std::vector<SymmetryMisfit> symmetry_name_warnings(const Model& m) {
  std::vector<SymmetryMisfit> out;
  if (m.geometry != Geometry::three_d || m.X.empty()) return out;
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
  for (const auto& X : m.X) {
    lo = lo.cwiseMin(X);
    hi = hi.cwiseMax(X);
  }
  const double tol = 1e-6 * std::max((hi - lo).norm(), 1e-300);
  // The surfaces' unit normals at their nodes (area-weighted over the elements at a node, from
  // the corner polygon of each), at the reference state.
  std::vector<Eigen::Vector3d> normal(m.num_nodes(), Eigen::Vector3d::Zero());
  for (const Part& part : m.parts)
    for (const ElementBlock& b : part.blocks) {
      if (!is_surface_kind(b.kind)) continue;
      const int c = corner_nodes(b.kind), per = nodes_per_element(b.kind);
      for (int e = 0; e < b.size(); ++e) {
        const int* n = b.element(e);
        const Eigen::Vector3d a = c == 4 ? Eigen::Vector3d(0.5 * (m.X[n[2]] - m.X[n[0]]).cross(m.X[n[3]] - m.X[n[1]]))
                                         : Eigen::Vector3d(0.5 * (m.X[n[1]] - m.X[n[0]]).cross(m.X[n[2]] - m.X[n[0]]));
        for (int k = 0; k < per; ++k) normal[n[k]] += a;
      }
    }
  const std::vector<std::string> names = m.dof_names();
  for (int bi = 0; bi < static_cast<int>(m.boundaries.size()); ++bi) {
    const Boundary& b = m.boundaries[bi];
    if (b.dofs.size() != 1 || b.dofs[0] >= 3 || b.node_set < 0) continue;
    const NodeSet& set = m.node_sets[b.node_set];
    if (set.nodes.size() < 3) continue;
    const int d = b.dofs[0];
    Eigen::Vector3d slo = Eigen::Vector3d::Constant(1e300), shi = -slo, across = Eigen::Vector3d::Zero();
    int with_normal = 0;
    for (int n : set.nodes) {
      slo = slo.cwiseMin(m.X[n]);
      shi = shi.cwiseMax(m.X[n]);
      if (normal[n].norm() > 0) {
        across += normal[n].normalized().cwiseAbs();
        ++with_normal;
      }
    }
    const bool normals = with_normal == static_cast<int>(set.nodes.size());
    if (normals) across /= with_normal;
    const Eigen::Vector3d range = shi - slo;
    // A plane k = c holds every node, and the surface crosses it (or, without normals, it is the
    // only such plane: the nodes span it).
    int flat = 0;
    for (int k = 0; k < 3; ++k) flat += range(k) <= tol;
    const auto symmetry_plane = [&](int k) {
      if (range(k) > tol) return false;
      return normals ? across(k) < 0.5 : flat == 1;
    };
    if (symmetry_plane(d)) continue;
    int plane = -1, planes = 0;
    for (int k = 0; k < 3; ++k)
      if (k != d && symmetry_plane(k)) plane = k, ++planes;
    if (planes != 1) continue;
    const double mid = 0.5 * (slo(plane) + shi(plane));
    const double c = std::abs(mid) <= tol ? 0.0 : mid;
    const std::string& k = names[plane];
    const std::string& held = names[d];
    out.push_back({bi, fmt::format(
        "boundary '{}' holds {} of node set '{}', whose {} nodes all lie on the plane {} = {:.6g} {} ({}): a symmetry "
        "plane there holds {}, the DOF normal to it, while holding {} lets the nodes move off it. Are the names of two "
        "node sets swapped (a mesh's edge named after another plane)? If '{}' is the symmetry plane {} = {:.6g}, hold "
        "`dofs: [{}]`; if holding {} is meant, ignore this warning",
        b.name, held, set.name, set.nodes.size(), k, c, m.units.display_unit(Dimension::length),
        normals ? "which the surface crosses there" : "which they span", k, held, set.name, k, c, k, held)});
  }
  return out;
}

}  // namespace tunica
