// Material frames of 3-D parts read from a deck: per-element vectors of a Gmsh
// element-data view (`frame: {type: mesh}`), the cylindrical rule on a tube
// (direction 1 circumferential, 2 axial) and a projected vector; the frame the
// Gauss points carry (and ParaView shows) is the one asked for.
#include <gtest/gtest.h>

#include <cmath>

#include "../support/capture.hpp"
#include "assembly/system.hpp"

using namespace tunica;
using namespace tunica::test;

namespace {

std::vector<MembranePoint> reference_points(const std::string& text, const std::string& file) {
  const Model m = read_deck_text(text, file);
  const System s(m);
  return s.points(Eigen::VectorXd::Zero(m.num_dofs()), 0);
}

const char* kHead = R"(units: {length: mm, force: N}
materials:
  wall: {type: hgo, mu: 30 kPa, k1: 100 kPa, k2: 5, beta: 40 deg}
parts:
  p:
    element: membrane
    material: wall
    thickness: 0.1
)";
const char* kTail = R"(steps:
  - {increments: 1}
)";

}  // namespace

TEST(Frames, PerElementVectorsFromAGmshView) {
  const std::string deck = std::string(TUNICA_SOURCE_DIR) + "/tests/data/meshes/frames.yaml";
  const std::string text = std::string(kHead) +
                           "    mesh: {type: gmsh, file: mixed_fibre.msh, surface: patch}\n"
                           "    frame: {type: mesh, view: fibre}\n" + kTail;
  const auto pts = reference_points(text, deck);
  // Triangles first (elements 6, 7 of the file), then the quad (element 5, four Gauss points).
  ASSERT_EQ(pts.size(), 6u);
  const Eigen::Vector3d want[6] = {{0.6, 0.8, 0}, {0, 1, 0}, {1, 0, 0}, {1, 0, 0}, {1, 0, 0}, {1, 0, 0}};
  for (int k = 0; k < 6; ++k) {
    EXPECT_LT((pts[k].e1 - want[k]).norm(), 1e-14) << k << ": " << pts[k].e1.transpose();
    EXPECT_NEAR(std::abs(pts[k].e2.dot(Eigen::Vector3d::UnitZ().cross(want[k]))), 1.0, 1e-14);
  }
}

TEST(Frames, CylindricalFrameOnATubeIsCircumferentialAndAxial) {
  const std::string text = std::string(kHead) +
                           "    mesh: {type: tube, radius: 1, length: 2, around: 7, along: 3, shape: triangle}\n"
                           "    frame: {type: cylindrical, axis: [0, 0, 2], point: [0, 0, -5]}\n" + kTail;
  const auto pts = reference_points(text, "tube.yaml");
  ASSERT_FALSE(pts.empty());
  for (const auto& q : pts) {
    const Eigen::Vector3d radial = Eigen::Vector3d(q.X.x(), q.X.y(), 0).normalized();
    const Eigen::Vector3d hoop = Eigen::Vector3d::UnitZ().cross(radial);
    // Flat facets: the frame lies in the facet; direction 1 is the horizontal chord direction.
    EXPECT_NEAR(q.e1.z(), 0.0, 1e-14);
    EXPECT_GT(q.e1.dot(hoop), 0.95);
    EXPECT_NEAR(std::abs(q.e2.z()), 1.0, 1e-14);
  }
}

TEST(Frames, AVectorIsProjectedOnTheTangentPlane) {
  const std::string deck = std::string(TUNICA_SOURCE_DIR) + "/tests/data/meshes/frames.yaml";
  const std::string text = std::string(kHead) +
                           "    mesh: {type: gmsh, file: mixed_fibre.msh, surface: patch}\n"
                           "    frame: {type: vector, direction: [1, 1, 5]}\n" + kTail;
  for (const auto& q : reference_points(text, deck))
    EXPECT_LT((q.e1 - Eigen::Vector3d(1, 1, 0).normalized()).norm(), 1e-14);
}
