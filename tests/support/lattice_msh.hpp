#pragma once
// Surface meshes on a node lattice, written as Gmsh 2.2 files: 3-node or 6-node triangles whose
// nodes are points of a lattice of twice the element density (corners at even lattice indices,
// mid-edge nodes at the lattice points between them), placed by a function of the lattice point,
// so that a 6-node triangle takes its mid-edge nodes on the exact curved surface (as Gmsh does
// with Mesh.ElementOrder = 2) and a 3-node one the corners of the same lattice. Node sets are
// written as physical points (each a 0-D physical group). Shared by
// tests/regression/test_tri6_convergence.cpp (sphere octant, quarter tube) and, through
// sphere_octant.hpp, bench/bench.cpp (`tunica-bench sphere --element tri6`).
#include <Eigen/Dense>
#include <fmt/format.h>

#include <array>
#include <fstream>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace tunica::test {

using LatticePoint = std::array<int, 3>;  ///< (I, J, K); two-parameter lattices leave K = 0

/// A surface mesh being written as a Gmsh 2.2 file: nodes at lattice points, triangles (order 1
/// or 2) in the physical surface "wall", node sets as physical points.
struct MshWriter {
  using Place = std::function<Eigen::Vector3d(const LatticePoint&)>;
  std::vector<Eigen::Vector3d> nodes;
  std::map<LatticePoint, int> index;        // lattice point → node tag
  std::vector<std::vector<int>> triangles;  // node tags, Gmsh order (corners, then mid-edges 0–1, 1–2, 2–0)
  std::map<std::string, std::vector<int>> sets;

  int node(const LatticePoint& l, const Place& at) {
    const auto [it, fresh] = index.emplace(l, static_cast<int>(nodes.size()) + 1);
    if (fresh) nodes.push_back(at(l));
    return it->second;
  }
  /// A triangle of corner lattice points (on even indices, counterclockwise about the outward
  /// normal); order 2 adds the lattice points halfway between them as its mid-edge nodes.
  void triangle(const std::array<LatticePoint, 3>& c, int order, const Place& at) {
    std::vector<int> t;
    for (const auto& l : c) t.push_back(node(l, at));
    if (order == 2)
      for (int a = 0; a < 3; ++a) {
        const LatticePoint &p = c[a], &q = c[(a + 1) % 3];
        LatticePoint mid{};
        for (int d = 0; d < 3; ++d) {
          if ((p[d] + q[d]) % 2 != 0) throw std::logic_error("MshWriter: corners must lie on even lattice points");
          mid[d] = (p[d] + q[d]) / 2;
        }
        t.push_back(node(mid, at));
      }
    triangles.push_back(t);
  }
  /// Every node (of either order: all lie on the lattice) whose lattice point satisfies `on`.
  std::vector<int> nodes_where(const std::function<bool(const LatticePoint&)>& on) const {
    std::vector<int> out;
    for (const auto& [l, tag] : index)
      if (on(l)) out.push_back(tag);
    return out;
  }
  void write(const std::string& path) const {
    std::ofstream out(path);
    if (!out) throw std::runtime_error("cannot write " + path);
    out << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n" << sets.size() + 1 << "\n2 1 \"wall\"\n";
    int tag = 2;
    for (const auto& [name, set] : sets) out << "0 " << tag++ << " \"" << name << "\"\n";
    out << "$EndPhysicalNames\n$Nodes\n" << nodes.size() << "\n";
    for (std::size_t k = 0; k < nodes.size(); ++k)
      out << fmt::format("{} {:.17g} {:.17g} {:.17g}\n", k + 1, nodes[k](0), nodes[k](1), nodes[k](2));
    std::size_t points = 0;
    for (const auto& [name, set] : sets) points += set.size();
    out << "$EndNodes\n$Elements\n" << triangles.size() + points << "\n";
    int e = 1;
    for (const auto& t : triangles) {
      out << e++ << (t.size() == 6 ? " 9" : " 2") << " 2 1 1";
      for (int n : t) out << " " << n;
      out << "\n";
    }
    tag = 2;
    for (const auto& [name, set] : sets) {
      for (int n : set) out << e++ << " 15 2 " << tag << " " << 100 + tag << " " << n << "\n";
      ++tag;
    }
    out << "$EndElements\n";
    if (!out) throw std::runtime_error("could not write " + path);
  }
};

/// Triangles of an n × m grid of cells of the two-parameter lattice (2n + 1) × (2m + 1), point
/// (I, J, 0) (or of a triangle of it, `triangle_domain`: cells with i + j < n only), each cell split
/// into (i, j), (i+1, j), (i, j+1) and (i+1, j), (i+1, j+1), (i, j+1); order 1 or 2.
inline void lattice_triangles(MshWriter& w, int n, int m, int order, bool triangle_domain, const MshWriter::Place& at) {
  const auto P = [](int i, int j) { return LatticePoint{2 * i, 2 * j, 0}; };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      if (triangle_domain && i + j >= n) continue;
      w.triangle({P(i, j), P(i + 1, j), P(i, j + 1)}, order, at);
      if (!triangle_domain || i + j + 1 < n) w.triangle({P(i + 1, j), P(i + 1, j + 1), P(i, j + 1)}, order, at);
    }
}

}  // namespace tunica::test
