// The sphere octant of the CalculiX comparison (bench/peers/, tunica-bench sphere --element tri6) with
// 6-node triangles (tests/support/sphere_octant.hpp):
//  - the cube lattice's Gmsh file is the `octant` generator's mesh split into triangles, corner for
//    corner (bit for bit) and triangle for triangle, with its mid-edge nodes on the exact sphere, its
//    triangles outward and its symmetry sets exactly on the planes, and a deck reads it as 6n² tri6;
//  - on it, the raw p error of bench/peers/ (the pressure against the closed form (8.3) at the mean
//    nodal radius, λ = 1.2, one increment) falls faster with the mesh than the 4-node quads' on the
//    same nodes, and is smaller at every size.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>
#include <vector>

#include <fmt/format.h>

#include "../support/capture.hpp"
#include "../support/scratch.hpp"
#include "../support/sphere_octant.hpp"
#include "mesh/surface_generators.hpp"

using namespace tunica;
using namespace tunica::test;
namespace fs = std::filesystem;

namespace {

using Key = std::array<double, 3>;
Key key(const Eigen::Vector3d& x) { return {x(0), x(1), x(2)}; }

}  // namespace

TEST(SphereOctantTri6, CubeLatticeIsTheGeneratorsMeshWithMidEdgeNodesOnTheSphere) {
  for (int n : {1, 2, 3, 5}) {
    const SurfaceMesh g = octant_mesh(1.0, n, /*triangles=*/true);
    for (int order : {1, 2}) {
      SCOPED_TRACE(fmt::format("n = {}, order {}", n, order));
      const MshWriter w = sphere_octant_lattice(n, order, OctantLattice::cube);
      const int m = order * n;
      EXPECT_EQ(w.nodes.size(), static_cast<std::size_t>(3 * m * m + 3 * m + 1));
      ASSERT_EQ(w.triangles.size(), g.surfaces[0].triangles.size());
      EXPECT_EQ(w.triangles.size(), static_cast<std::size_t>(6 * n * n));
      // Corners: the generator's nodes, bit for bit; triangles: the generator's, node for node.
      std::map<Key, int> generator;
      for (int i = 0; i < static_cast<int>(g.nodes.size()); ++i) generator[key(g.nodes[i])] = i;
      for (std::size_t e = 0; e < w.triangles.size(); ++e) {
        const auto& t = w.triangles[e];
        ASSERT_EQ(t.size(), static_cast<std::size_t>(order == 2 ? 6 : 3));
        for (int a = 0; a < 3; ++a) {
          const auto it = generator.find(key(w.nodes[t[a] - 1]));
          ASSERT_NE(it, generator.end()) << "corner not a generator node";
          EXPECT_EQ(it->second, g.surfaces[0].triangles[e][a]);
        }
        const Eigen::Vector3d x0 = w.nodes[t[0] - 1], x1 = w.nodes[t[1] - 1], x2 = w.nodes[t[2] - 1];
        EXPECT_GT((x1 - x0).cross(x2 - x0).dot(x0 + x1 + x2), 0.0) << "triangle " << e << " not outward";
        for (std::size_t a = 3; a < t.size(); ++a) {  // mid-edge nodes: near the middle of their chord
          const Eigen::Vector3d p = w.nodes[t[a] - 1], c0 = w.nodes[t[a - 3] - 1], c1 = w.nodes[t[(a - 2) % 3] - 1];
          EXPECT_LT((p - 0.5 * (c0 + c1)).norm(), 0.2 * (c1 - c0).norm());
        }
      }
      for (const auto& x : w.nodes) EXPECT_NEAR(x.norm(), 1.0, 1e-15);  // round-off of the projection
      // The symmetry sets: exactly on their planes, every node of the plane, one pole.
      for (const auto& [name, axis] : {std::pair<const char*, int>{"x0", 0}, {"y0", 1}, {"z0", 2}}) {
        const auto& set = w.sets.at(name);
        EXPECT_EQ(set.size(), static_cast<std::size_t>(2 * m + 1)) << name;
        for (int tag : set) EXPECT_EQ(w.nodes[tag - 1](axis), 0.0) << name;
        int on_plane = 0;
        for (const auto& x : w.nodes) on_plane += x(axis) == 0.0;
        EXPECT_EQ(on_plane, static_cast<int>(set.size())) << name;
      }
      ASSERT_EQ(w.sets.at("pole").size(), 1u);
      EXPECT_EQ(w.nodes[w.sets.at("pole")[0] - 1], Eigen::Vector3d(0, 0, 1));
    }
  }
  // A deck reads the file as 6n² six-node triangles on 12n² + 6n + 1 nodes.
  const int n = 3;
  const fs::path msh = scratch("sphere-octant-tri6") / "cube-3.msh";
  const std::string deck = sphere_octant_deck("tri6 octant", octant_msh_mesh(msh.string(), msh.string(), n, 2, OctantLattice::cube), "", 1);
  const Model model = read_deck_text(deck, (scratch("sphere-octant-tri6") / "sphere.yaml").string());
  ASSERT_EQ(model.parts.size(), 1u);
  ASSERT_EQ(model.parts[0].blocks.size(), 1u);
  EXPECT_EQ(model.parts[0].blocks[0].size(), 6 * n * n);
  EXPECT_EQ(nodes_per_element(model.parts[0].blocks[0].kind), 6);
  EXPECT_EQ(model.num_nodes(), 12 * n * n + 6 * n + 1);
}

namespace {

struct SphereRun {
  double error = 0;
  int unknowns = 0, iterations = 0, cutbacks = 0;
};

SphereRun sphere(const OctantMesh& mesh) {
  const std::string file = (scratch("sphere-octant-tri6") / "sphere.yaml").string();
  const Model m = read_deck_text(sphere_octant_deck("sphere octant", mesh, "", 1), file);
  Capture cap;
  Analysis a(m);
  a.run(cap);
  SphereRun r;
  const Eigen::VectorXd& u = a.displacement();
  r.error = sphere_octant_p_error(m.num_nodes(), [&](int n) { return Eigen::Vector3d(m.X[n] + u.segment<3>(3 * n)); });
  r.unknowns = a.system().num_free();
  for (const auto& it : cap.iterations) r.iterations += it.rec.iteration > 0;  // corrections (linear solves)
  r.cutbacks = cap.cutbacks;
  return r;
}

}  // namespace

TEST(SphereOctantTri6, PressureErrorFallsFasterThanTheQuadsOnTheSameNodes) {
  const std::vector<int> ns = {2, 4, 8};
  std::vector<SphereRun> tri6, quad4;
  for (int n : ns) {
    const fs::path msh = scratch("sphere-octant-tri6") / fmt::format("cube-tri6-{}.msh", n);
    tri6.push_back(sphere(octant_msh_mesh(msh.string(), msh.string(), n, 2, OctantLattice::cube)));
    quad4.push_back(sphere(octant_generator_mesh(2 * n)));  // the same nodes: the corners of the 2n lattice
  }
  std::printf("sphere octant to λ = 1.2 in one increment: p error at the mean nodal radius\n");
  for (std::size_t k = 0; k < ns.size(); ++k) {
    std::printf("  tri6 n = %d: %+.3e (%d unknowns, %d iterations) | quad4 n = %d: %+.3e (%d unknowns)\n", ns[k],
                tri6[k].error, tri6[k].unknowns, tri6[k].iterations, 2 * ns[k], quad4[k].error, quad4[k].unknowns);
    EXPECT_EQ(tri6[k].unknowns, quad4[k].unknowns);
    EXPECT_LT(std::abs(tri6[k].error), 0.25 * std::abs(quad4[k].error));
    EXPECT_EQ(tri6[k].cutbacks, 0);
    EXPECT_LE(tri6[k].iterations, 6);  // 5 measured
  }
  for (std::size_t k = 1; k < ns.size(); ++k) {
    const double r6 = std::log2(std::abs(tri6[k - 1].error / tri6[k].error));
    const double r4 = std::log2(std::abs(quad4[k - 1].error / quad4[k].error));
    std::printf("  rates %d → %d: tri6 %.2f, quad4 %.2f\n", ns[k - 1], ns[k], r6, r4);
    EXPECT_NEAR(r4, 2.0, 0.3);
    EXPECT_GT(r6, r4 + 1.0);
  }
}
