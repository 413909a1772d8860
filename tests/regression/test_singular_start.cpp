// A flat membrane stretched biaxially from its stress-free state: with no stress
// and no curvature its tangent has no stiffness against out-of-plane motion of
// the interior nodes (singular to round-off). The first correction is therefore
// wild out of the plane; the line search halves it (each halving halves the correction
// actually taken, so repeated halvings approach the start of the step); once the sheet
// is in tension its tangent is regular and Newton converges to the exact homogeneous state
// x = 1.2 X, y = 1.2 Y, z = 0.
// The diagonal perturbation of a tangent that the solver reports singular is
// tested directly (SolvePerturbed.*).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "../support/capture.hpp"
#include "solver/newton.hpp"

using namespace tunica;
using namespace tunica::test;
namespace fs = std::filesystem;

namespace {

/// A 1 mm × 1 mm square in z = 0, n × n quads, Gmsh 2.2 ASCII: physical surface "sheet",
/// curves "left" (x = 0), "right" (x = 1), "bottom" (y = 0), "top" (y = 1).
void write_square(const fs::path& file, int n) {
  std::ofstream o(file);
  const auto id = [n](int i, int j) { return 1 + i + (n + 1) * j; };
  o << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n5\n1 2 \"left\"\n1 3 \"right\"\n1 4 \"bottom\"\n"
       "1 5 \"top\"\n2 1 \"sheet\"\n$EndPhysicalNames\n$Nodes\n"
    << (n + 1) * (n + 1) << "\n";
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) o << id(i, j) << " " << double(i) / n << " " << double(j) / n << " 0\n";
  o << "$EndNodes\n$Elements\n" << 4 * n + n * n << "\n";
  int e = 0;
  for (int j = 0; j < n; ++j) o << ++e << " 1 2 2 1 " << id(0, j) << " " << id(0, j + 1) << "\n";
  for (int j = 0; j < n; ++j) o << ++e << " 1 2 3 2 " << id(n, j) << " " << id(n, j + 1) << "\n";
  for (int i = 0; i < n; ++i) o << ++e << " 1 2 4 3 " << id(i, 0) << " " << id(i + 1, 0) << "\n";
  for (int i = 0; i < n; ++i) o << ++e << " 1 2 5 4 " << id(i, n) << " " << id(i + 1, n) << "\n";
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      o << ++e << " 3 2 1 1 " << id(i, j) << " " << id(i + 1, j) << " " << id(i + 1, j + 1) << " " << id(i, j + 1) << "\n";
  o << "$EndElements\n";
}

}  // namespace

TEST(SingularStart, FlatSheetStretchedFromRestConvergesToTheHomogeneousState) {
  const fs::path dir = fs::temp_directory_path() / ("tunica-singular-start-" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  write_square(dir / "square.msh", 6);
  const std::string deck = R"(title: flat sheet, uniaxial stretch from rest
units: {length: mm, force: N}
materials:
  rubber: {type: neo_hookean, mu: 1 MPa}
parts:
  sheet:
    element: membrane
    material: rubber
    thickness: 0.1 mm
    mesh: {type: gmsh, file: square.msh, surface: sheet}
boundary:
  hold: {node_set: left, dofs: [x, z]}
  pull: {node_set: right, dofs: [x]}
  flat: {node_set: right, dofs: [z]}
  base: {node_set: bottom, dofs: [y]}
  lift: {node_set: top, dofs: [y]}
steps:
  - {name: stretch, increments: 2, set: {pull: 0.2 mm, lift: 0.2 mm}}
output: {vtk: false}
)";
  const Model model = read_deck_text(deck, (dir / "sheet.yaml").string());
  Analysis a(model);
  Capture c;
  a.run(c);
  ASSERT_EQ(c.rows.back().info.fraction, 1.0);
  EXPECT_EQ(c.cutbacks, 0);
  EXPECT_LE(c.rows.back().info.iterations, 3);  // the second increment starts from a tense sheet
  const Eigen::VectorXd& u = a.displacement();
  const double l1 = 1.2, l2 = 1.2;
  double worst = 0;
  for (int n = 0; n < model.num_nodes(); ++n) {
    const Eigen::Vector3d X = model.X[n];
    const Eigen::Vector3d x = X + u.segment<3>(3 * n);
    const double d = std::max({std::abs(x(0) - l1 * X(0)), std::abs(x(1) - l2 * X(1)), std::abs(x(2))});
    worst = std::max(worst, d);
  }
  EXPECT_LT(worst, 1e-9) << "largest deviation from the homogeneous state [mm]";
  fs::remove_all(dir);
}

TEST(SolvePerturbed, ASingularMatrixIsSolvedWithAPerturbedDiagonal) {
  // K = [[2, 1, 0], [1, 2, 0], [0, 0, 0]]: no stiffness in the third unknown (as a flat,
  // unstressed membrane out of its plane). b has no component there.
  SparseMatrix K(3, 3);
  K.insert(0, 0) = 2;
  K.insert(1, 0) = 1;
  K.insert(0, 1) = 1;
  K.insert(1, 1) = 2;
  K.insert(2, 2) = 0;
  K.makeCompressed();
  const Eigen::Vector3d b(1, 2, 0);
  for (const char* name : {"cholmod", "umfpack", "auto"}) {
    auto solver = make_linear_solver(name);
    Eigen::VectorXd x;
    std::string note;
    double tf = 0, ts = 0;
    ASSERT_TRUE(solve_perturbed(*solver, K, b, true, 1e3, x, note, tf, ts)) << name;
    EXPECT_EQ(note, "+shift") << name;
    // (2 + 2e-6) x0 + x1 = 1, x0 + (2 + 2e-6) x1 = 2: x ≈ (0, 1) to 1e-6, x2 = 0 exactly.
    EXPECT_NEAR(x(0), 0.0, 2e-6) << name;
    EXPECT_NEAR(x(1), 1.0, 2e-6) << name;
    EXPECT_EQ(x(2), 0.0) << name;
    // Without the perturbation the same matrix is reported singular.
    EXPECT_FALSE(solve_perturbed(*solver, K, b, false, 1e3, x, note, tf, ts)) << name;
  }
  // A regular matrix is solved as it is.
  SparseMatrix I(2, 2);
  I.setIdentity();
  auto solver = make_linear_solver("auto");
  Eigen::VectorXd x;
  std::string note;
  double tf = 0, ts = 0;
  ASSERT_TRUE(solve_perturbed(*solver, I, Eigen::Vector2d(3, 4), true, 1e3, x, note, tf, ts));
  EXPECT_TRUE(note.empty());
  EXPECT_EQ(x, Eigen::Vector2d(3, 4));
}
