// check_surface: a usable mesh passes; a flipped element, a degenerate element, a repeated
// node, a node index out of range and an edge shared by three elements are each reported
// with a message naming the surface and the element.
#include <gtest/gtest.h>

#include <array>
#include <map>
#include <utility>

#include "mesh/mesh_checks.hpp"
#include "mesh/surface_generators.hpp"

using namespace tunica;

namespace {

/// A 3 × 2 grid of unit squares in the plane z = 0, split into 12 triangles, normals +z.
SurfaceMesh grid() {
  SurfaceMesh m;
  for (int j = 0; j <= 2; ++j)
    for (int i = 0; i <= 3; ++i) m.nodes.emplace_back(i, j, 0);
  m.surfaces.resize(1);
  m.surfaces[0].name = "patch";
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 3; ++i) {
      const int a = j * 4 + i, b = a + 1, c = a + 5, d = a + 4;
      m.surfaces[0].triangles.push_back({a, b, c});
      m.surfaces[0].triangles.push_back({a, c, d});
    }
  return m;
}

void expect_message(const SurfaceMesh& m, std::initializer_list<const char*> parts) {
  const std::string msg = check_surface(m, m.surfaces[0]);
  ASSERT_FALSE(msg.empty());
  EXPECT_NE(msg.find("surface 'patch'"), std::string::npos) << msg;
  for (const char* p : parts) EXPECT_NE(msg.find(p), std::string::npos) << "missing '" << p << "' in: " << msg;
  std::printf("  %s\n", msg.c_str());
}

}  // namespace

TEST(MeshChecks, ConsistentMeshPasses) {
  const SurfaceMesh m = grid();
  EXPECT_EQ(check_surface(m, m.surfaces[0]), "");
  SurfaceMesh q;  // quads and triangles mixed, sharing edges consistently
  q.nodes = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0}};
  q.surfaces.resize(1);
  q.surfaces[0].name = "patch";
  q.surfaces[0].quads.push_back({0, 1, 4, 3});
  q.surfaces[0].triangles.push_back({1, 2, 5});
  q.surfaces[0].triangles.push_back({1, 5, 4});
  EXPECT_EQ(check_surface(q, q.surfaces[0]), "");
}

TEST(MeshChecks, FlippedTriangleIsInverted) {
  SurfaceMesh m = grid();
  std::swap(m.surfaces[0].triangles[7][1], m.surfaces[0].triangles[7][2]);
  expect_message(m, {"element 7 (triangle 7) is inverted", "1 of 12"});
  // Whichever element is flipped (also the first one), the minority is named.
  m = grid();
  std::swap(m.surfaces[0].triangles[0][0], m.surfaces[0].triangles[0][1]);
  expect_message(m, {"element 0 (triangle 0) is inverted"});
}

TEST(MeshChecks, FlippedQuadOnAClosedSurface) {
  SurfaceMesh m = sphere_mesh(1.0, 2, false);
  m.surfaces[0].name = "patch";
  auto& q = m.surfaces[0].quads[5];
  std::swap(q[1], q[3]);
  expect_message(m, {"element 5 (quadrilateral 5) is inverted"});
}

TEST(MeshChecks, DegenerateTriangle) {
  SurfaceMesh m = grid();
  m.nodes.emplace_back(0.5, 0.5, 0);  // on the diagonal of the first square
  m.surfaces[0].triangles.push_back({0, static_cast<int>(m.nodes.size()) - 1, 5});  // collinear
  expect_message(m, {"element 12 (triangle 12) is degenerate"});
}

TEST(MeshChecks, NonConvexQuadIsDegenerate) {
  SurfaceMesh m;
  m.nodes = {{0, 0, 0}, {2, 0, 0}, {0.5, 0.5, 0}, {0, 2, 0}};  // a dart: re-entrant corner at node 2
  m.surfaces.resize(1);
  m.surfaces[0].name = "patch";
  m.surfaces[0].quads.push_back({0, 1, 2, 3});
  expect_message(m, {"element 0 (quadrilateral 0) is degenerate", "node 2"});
}

TEST(MeshChecks, RepeatedNode) {
  SurfaceMesh m = grid();
  m.surfaces[0].triangles[3] = {4, 9, 4};
  expect_message(m, {"element 3 (triangle 3) has the repeated node 4",
                      "an edge of it has collapsed onto one node, so it has no area",
                      "remove element 3 from the mesh file, or remesh the surface (without the very short curve"});
}

TEST(MeshChecks, NodeIndexOutOfRange) {
  SurfaceMesh m = grid();
  m.surfaces[0].triangles[2][1] = 12;
  expect_message(m, {"element 2 (triangle 2) has node index 12 outside the mesh (nodes 0 to 11)"});
  m.surfaces[0].triangles[2][1] = -1;
  expect_message(m, {"node index -1"});
}

TEST(MeshChecks, EdgeSharedByThreeElements) {
  SurfaceMesh m = grid();
  m.nodes.emplace_back(0.5, 0.5, 1.0);  // a fin on the edge 0–5
  m.surfaces[0].triangles.push_back({0, 5, static_cast<int>(m.nodes.size()) - 1});
  expect_message(m, {"edge between nodes 0 and 5 is shared by more than two elements (element 0 (triangle 0), element 1 "
                     "(triangle 1), element 12 (triangle 12))", "not a manifold"});
}

TEST(MeshChecks, EmptySurface) {
  SurfaceMesh m = grid();
  m.surfaces[0].triangles.clear();
  expect_message(m, {"no elements"});
}

TEST(MeshChecks, QuadsAreNumberedAfterTriangles) {
  SurfaceMesh q;
  q.nodes = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0}};
  q.surfaces.resize(1);
  q.surfaces[0].name = "patch";
  q.surfaces[0].quads.push_back({0, 3, 4, 1});  // clockwise seen from +z: the odd one out
  q.surfaces[0].triangles.push_back({1, 2, 5});
  q.surfaces[0].triangles.push_back({1, 5, 4});
  expect_message(q, {"element 2 (quadrilateral 0) is inverted", "1 of 3"});
}

namespace {

/// The grid as 6-node triangles: a mid-edge node at the middle of every edge, shared by the two
/// triangles on it.
SurfaceMesh quadratic_grid() {
  SurfaceMesh m = grid();
  std::map<std::pair<int, int>, int> mid;
  for (const auto& t : m.surfaces[0].triangles) {
    std::array<int, 3> ms{};
    for (int a = 0; a < 3; ++a) {
      const auto key = std::minmax(t[a], t[(a + 1) % 3]);
      auto [it, fresh] = mid.emplace(key, static_cast<int>(m.nodes.size()));
      if (fresh) m.nodes.push_back(0.5 * (m.nodes[t[a]] + m.nodes[t[(a + 1) % 3]]));
      ms[a] = it->second;
    }
    m.surfaces[0].triangle_midsides.push_back(ms);
  }
  return m;
}

}  // namespace

TEST(MeshChecks, QuadraticTrianglesMustShareTheirMidEdgeNodes) {
  SurfaceMesh m = quadratic_grid();
  EXPECT_EQ(check_surface(m, m.surfaces[0]), "");
  // Element 1's mid-edge node on its edge 0–2 (shared with element 0) replaced by a new node nearby:
  // a gap would open along the edge.
  SurfaceMesh gap = m;
  gap.nodes.push_back(gap.nodes[gap.surfaces[0].triangle_midsides[1][0]] + Eigen::Vector3d(0.02, 0, 0));
  gap.surfaces[0].triangle_midsides[1][0] = static_cast<int>(gap.nodes.size()) - 1;
  expect_message(gap, {"share the edge between nodes 0 and 5 but not its mid-edge node", "not conforming"});
  // Mid-edge nodes listed in the wrong order: on two shared edges (element 1: edges 0–5 and 5–4) not
  // conforming; on two boundary edges (element 4: 2–3 and 3–7) far from the middle of their edges.
  SurfaceMesh permuted = m;
  std::swap(permuted.surfaces[0].triangle_midsides[1][0], permuted.surfaces[0].triangle_midsides[1][1]);
  expect_message(permuted, {"not conforming"});
  permuted = m;
  std::swap(permuted.surfaces[0].triangle_midsides[4][0], permuted.surfaces[0].triangle_midsides[4][1]);
  expect_message(permuted, {"element 4 (triangle 4): its mid-edge node", "0.707 edge lengths from the middle of the edge"});
  // A corner used as a mid-edge node.
  SurfaceMesh corner = m;
  corner.surfaces[0].triangle_midsides[0][1] = 7;
  expect_message(corner, {"is a corner of an element"});
}
