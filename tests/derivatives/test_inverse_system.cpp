// The assembled tangent of an inverse step (theory manual (13.1)–(13.2)) is the Jacobian of the
// assembled residual R(u) = f_int(x̂ + u, x̂) − f_p(x̂), pressure included, by central differences:
// the axisymmetric sphere (examples/balloon-sphere.yaml) and a 3-D octant of quadrilaterals and of triangles, at a
// reference state away from the imaged one.
#include <gtest/gtest.h>

#include <random>

#include "../support/capture.hpp"
#include "../support/fd.hpp"
#include "assembly/system.hpp"

using namespace tunica;
using namespace tunica::test;

namespace {

double check(const std::string& text, const std::string& file, double amplitude) {
  const Model m = read_deck_text(text, file);
  const System system(m);
  LoadState loads;
  loads.step = 0;
  loads.boundary.assign(m.boundaries.size(), 0.0);
  loads.pressure.assign(m.loads.size(), 0.008);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> d(-1, 1);
  Eigen::VectorXd u(m.num_dofs());
  for (int i = 0; i < u.size(); ++i) u(i) = system.equation(i) >= 0 ? amplitude * d(rng) - 0.1 * m.X[i / m.dofs_per_node()](i % m.dofs_per_node()) : 0.0;
  Eigen::VectorXd R;
  SparseMatrix K;
  system.assemble_full(u, loads, R, K);
  const auto residual = [&](const Eigen::VectorXd& v) -> Eigen::VectorXd {
    Eigen::VectorXd full = u, Rv;
    for (int i = 0; i < u.size(); ++i)
      if (system.equation(i) >= 0) full(i) = v(system.equation(i));
    system.assemble(full, loads, Rv, nullptr);
    Eigen::VectorXd free(system.num_free());
    for (int i = 0; i < u.size(); ++i)
      if (system.equation(i) >= 0) free(system.equation(i)) = Rv(i);
    return free;
  };
  Eigen::VectorXd v(system.num_free());
  for (int i = 0; i < u.size(); ++i)
    if (system.equation(i) >= 0) v(system.equation(i)) = u(i);
  return relative_error(Eigen::MatrixXd(K), fd_jacobian(residual, v, 1e-7));
}

}  // namespace

TEST(InverseSystem, AssembledTangentIsTheJacobianOfTheAssembledResidual) {
  const std::string axisym = std::string(TUNICA_SOURCE_DIR) + "/examples/balloon-sphere.yaml";
  const std::string sphere = replace(read_text(axisym), "name: inflate", "name: zero_pressure\n    type: inverse");
  const double ea = check(replace(sphere, "elements: 100", "elements: 12"), axisym, 0.01);
  const std::string octant = std::string(TUNICA_SOURCE_DIR) + "/examples/balloon-sphere-3d.yaml";
  std::string t = replace(read_text(octant), "n: 8}", "n: 3}");
  t = replace(t, "increments: 40\n    volume_control: {load: inflation, volume: 4.45 mm^3}",
              "type: inverse\n    increments: 1\n    set: {inflation: 0.008 MPa}\n    #");
  const double eq = check(t, octant, 0.01);
  const double et = check(replace(t, "n: 3}", "n: 3, shape: triangle}"), octant, 0.01);
  std::printf("inverse system tangent vs central differences: axisymmetric %.2e, octant quad4 %.2e, tri3 %.2e\n", ea, eq, et);
  EXPECT_LT(ea, 1e-6);
  EXPECT_LT(eq, 1e-6);
  EXPECT_LT(et, 1e-6);
}

TEST(InverseSystem, AssembledTangentWithAnImagedThicknessIsTheJacobianOfTheAssembledResidual) {
  // The same with `thickness_at: imaged` (theory manual (13.12)–(13.13)): H = h λ₁λ₂ at each Gauss point.
  const auto imaged = [](const std::string& deck) {
    const std::string t = replace(deck, "thickness: 0.01 mm", "thickness: 0.008 mm\n    thickness_at: imaged");
    EXPECT_NE(t.find("thickness_at: imaged"), std::string::npos);
    return t;
  };
  const std::string axisym = std::string(TUNICA_SOURCE_DIR) + "/examples/balloon-sphere.yaml";
  const std::string sphere = replace(read_text(axisym), "name: inflate", "name: zero_pressure\n    type: inverse");
  const double ea = check(imaged(replace(sphere, "elements: 100", "elements: 12")), axisym, 0.01);
  const std::string octant = std::string(TUNICA_SOURCE_DIR) + "/examples/balloon-sphere-3d.yaml";
  std::string t = replace(read_text(octant), "n: 8}", "n: 3}");
  t = replace(t, "increments: 40\n    volume_control: {load: inflation, volume: 4.45 mm^3}",
              "type: inverse\n    increments: 1\n    set: {inflation: 0.008 MPa}\n    #");
  const double eq = check(imaged(t), octant, 0.01);
  const double et = check(imaged(replace(t, "n: 3}", "n: 3, shape: triangle}")), octant, 0.01);
  std::printf("inverse system tangent with an imaged thickness vs central differences: axisymmetric %.2e, octant quad4 "
              "%.2e, tri3 %.2e\n",
              ea, eq, et);
  EXPECT_LT(ea, 1e-6);
  EXPECT_LT(eq, 1e-6);
  EXPECT_LT(et, 1e-6);
}
