// Objectivity of the whole 3-D model: a clamped anisotropic (Fung, cylindrical
// frame) and an isotropic tube inflated by follower pressure, solved once as
// given and once after a rigid rotation Q of the reference geometry and of the
// frame rule. The Gauss-point strains and stresses (material frame) must agree,
// and the displacements must be Q u, to solver round-off.
#include <gtest/gtest.h>

#include <cmath>

#include "../support/capture.hpp"

using namespace tunica;
using namespace tunica::test;

namespace {

const char* kTube = R"(
units: {length: mm, force: N}
materials:
  fung: {type: fung, c: 0.05, a1: 1.1, a2: 0.7, a4: 0.2, a7: 0.4}
  rubber: {type: neo_hookean, mu: 0.3}
parts:
  wall:
    element: membrane
    material: MATERIAL
    thickness: 0.1
    mesh: {type: tube, radius: 1, length: 3, around: 12, along: 6, shape: SHAPE}
    frame: {type: cylindrical, axis: [0, 0, 1], point: [0, 0, 0]}
boundary:
  bottom: {node_set: wall.bottom, dofs: [x, y, z]}
  top: {node_set: wall.top, dofs: [x, y, z]}
loads:
  p: {type: pressure, part: wall}
steps:
  - {increments: 3, set: {p: 0.02}}
output: {vtk: false}
)";

Eigen::Matrix3d rotation() {
  return (Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, -0.5).normalized()) *
          Eigen::AngleAxisd(-1.9, Eigen::Vector3d(0.3, -1, 0.8).normalized()))
      .toRotationMatrix();
}

}  // namespace

TEST(RotationInvariance, RotatedModelGivesTheSameStressesAndRotatedDisplacements) {
  for (const char* material : {"fung", "rubber"})
    for (const char* shape : {"quad", "triangle"}) {
      const std::string text = replace(replace(kTube, "MATERIAL", material), "SHAPE", shape);
      const Model m = read_deck_text(text, "tube.yaml");
      Model r = read_deck_text(text, "tube.yaml");
      const Eigen::Matrix3d Q = rotation();
      for (auto& X : r.X) X = Q * X + Eigen::Vector3d(0.3, -2, 5);
      r.parts[0].frame.axis = Q * r.parts[0].frame.axis;
      r.parts[0].frame.point = Q * r.parts[0].frame.point + Eigen::Vector3d(0.3, -2, 5);
      Capture c1, c2;
      Analysis a1(m), a2(r);
      a1.run(c1);
      a2.run(c2);
      const auto p1 = a1.system().points(a1.displacement(), 0), p2 = a2.system().points(a2.displacement(), 0);
      ASSERT_EQ(p1.size(), p2.size());
      double smax = 0, ds = 0, de = 0;
      for (std::size_t k = 0; k < p1.size(); ++k) {
        smax = std::max(smax, p1[k].S.norm());
        ds = std::max(ds, (p1[k].S - p2[k].S).norm());
        de = std::max(de, (p1[k].E - p2[k].E).norm());
        EXPECT_NEAR(p1[k].sigma_principal(0), p2[k].sigma_principal(0), 1e-9 * std::abs(p1[k].sigma_principal(0)) + 1e-12);
      }
      double umax = 0, du = 0;
      for (int n = 0; n < m.num_nodes(); ++n) {
        const Eigen::Vector3d u1 = a1.displacement().segment<3>(3 * n), u2 = a2.displacement().segment<3>(3 * n);
        umax = std::max(umax, u1.norm());
        du = std::max(du, (Q * u1 - u2).norm());
      }
      std::printf("%s %s: max |ΔS| / max |S| = %.2e, max |ΔE| = %.2e, max |Qu − u'| / max |u| = %.2e\n", material, shape,
                  ds / smax, de, du / umax);
      EXPECT_GT(smax, 0);
      EXPECT_LT(ds / smax, 1e-9);
      EXPECT_LT(de, 1e-10);
      EXPECT_LT(du / umax, 1e-9);
    }
}
