// The assembled system (System) of a model with axisymmetric shell parts (the DOF map with
// slope unknowns, model/model.hpp; system_shell.cpp), follower pressure on the Hermite
// mid-surface, penalty contact of a shell balloon on a shell artery and a membrane part
// (tests/support/shell_decks.hpp):
// (1) central differences of the assembled residual R against the tangent K, every free DOF
//     (positions and slopes), with the balloon held before it enters (R_i = k_i u_i, slopes
//     too) and active, in contact;
// (2) without pressure and contact K is symmetric and R = ∂E/∂u on the free DOFs;
// (3) the volume gradient of a shell load against central differences of the volume.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "../support/capture.hpp"
#include "../support/shell_decks.hpp"
#include "../support/system_fd.hpp"
#include "assembly/system.hpp"

using namespace tunica;
using namespace tunica::test;

namespace {

LoadState loads_of(const Model& m, double pressure, int step) {
  LoadState l;
  l.boundary.assign(m.boundaries.size(), 0.0);
  l.boundary[1] = 0.1;  // stretch
  l.pressure.assign(m.loads.size(), pressure);
  l.volume.assign(m.loads.size(), 0.0);
  l.step = step;
  return l;
}

/// A deformed state: every DOF moved smoothly; the balloon inflated to touch the artery.
Eigen::VectorXd deformed(const Model& m) {
  Eigen::VectorXd u(m.num_dofs());
  for (int d = 0; d < m.num_dofs(); ++d) u(d) = 0.01 * std::sin(1.3 * d + 0.4);
  const Part& balloon = m.parts[static_cast<std::size_t>(m.find_part("balloon"))];
  for (int n : balloon.nodes) u(2 * n) += 0.25 * m.X[n](0);  // r: 0.8 → 1.0 at the equator
  return u;
}

double total_energy(const System& sys, const Model& m, const Eigen::VectorXd& u) {
  double E = 0;
  for (std::size_t p = 0; p < m.parts.size(); ++p) E += sys.part_energy(u, static_cast<int>(p));
  return E;
}

}  // namespace

TEST(ShellSystem, TheDofMapGivesShellNodesTwoSlopeUnknowns) {
  const Model m = read_deck_text(kShellArteryBalloon, "shells.yaml");
  EXPECT_EQ(m.num_slope_nodes, 8 + 10);
  EXPECT_EQ(m.num_dofs(), 2 * m.num_nodes() + 2 * 18);
  const Part& cuff = m.parts[0];
  for (int n : cuff.nodes) EXPECT_FALSE(m.has_slopes(n));
  const Part& balloon = m.parts[2];
  // Reference slopes: unit tangents of the arc, (1, 0) at the lower pole, (0, 1) at the equator… (9 elements: none there)
  EXPECT_NEAR((m.slope_ref[balloon.nodes.front()] - Eigen::Vector2d(1, 0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((m.slope_ref[balloon.nodes.back()] - Eigen::Vector2d(-1, 0)).norm(), 0.0, 1e-12);
  const System sys(m);
  // slope_r of the artery ends and r, z, slope_z of the poles are prescribed.
  EXPECT_LT(sys.equation(m.node_dof(m.parts[1].nodes.front(), 2)), 0);
  EXPECT_GE(sys.equation(m.node_dof(m.parts[1].nodes.front(), 3)), 0);
  EXPECT_LT(sys.equation(m.node_dof(balloon.nodes.back(), 3)), 0);
  EXPECT_GE(sys.equation(m.node_dof(balloon.nodes.back(), 2)), 0);
}

TEST(ShellSystem, AssembledTangentMatchesFiniteDifferences) {
  const Model m = read_deck_text(kShellArteryBalloon, "shells.yaml");
  const System sys(m);
  for (int step : {0, 1}) {  // balloon held, balloon active
    const LoadState loads = loads_of(m, 0.004, step);
    Eigen::VectorXd u = deformed(m);
    sys.apply_boundary(loads, u);
    Eigen::VectorXd R;
    SparseMatrix K;
    int active = 0;
    sys.assemble_full(u, loads, R, K, nullptr, &active);
    if (step == 1) {
      EXPECT_GT(active, 0) << "the balloon should be in contact";
    }
    const Eigen::MatrixXd Kd(K);
    const double worst = test::fd_tangent_error(sys, loads, u, Kd, 1e-7);
    const double size = Kd.cwiseAbs().maxCoeff();
    EXPECT_LT(worst, 1e-6 * size) << "step " << step;
    std::printf("step %d (balloon %s, %d contact nodes): FD of the assembled residual vs K: %.2e (max |K| %.2e)\n",
                step, step == 0 ? "held" : "active", active, worst, size);
  }
}

TEST(ShellSystem, WithoutPressureTheTangentIsSymmetricAndTheResidualIsTheEnergyGradient) {
  std::string deck = replace(kShellArteryBalloon, "offset: 0.09", "offset: 0.0");
  const Model m = read_deck_text(deck, "shells.yaml");
  const System sys(m);
  const LoadState loads = loads_of(m, 0.0, 1);
  Eigen::VectorXd u = deformed(m);
  for (int n : m.parts[2].nodes) u(2 * n) -= 0.2 * m.X[n](0);  // the balloon off the artery: no contact
  sys.apply_boundary(loads, u);
  Eigen::VectorXd R;
  SparseMatrix K;
  int active = -1;
  sys.assemble_full(u, loads, R, K, nullptr, &active);
  ASSERT_EQ(active, 0);
  const Eigen::MatrixXd Kd(K);
  const double asym = (Kd - Kd.transpose()).cwiseAbs().maxCoeff(), size = Kd.cwiseAbs().maxCoeff();
  EXPECT_LT(asym, 1e-13 * size);
  double worst = 0, largest = 0;
  const double h = 1e-6;
  for (int i = 0; i < m.num_dofs(); ++i) {
    if (sys.equation(i) < 0) continue;
    Eigen::VectorXd up = u, um = u;
    up(i) += h;
    um(i) -= h;
    const double dE = (total_energy(sys, m, up) - total_energy(sys, m, um)) / (2 * h);
    worst = std::max(worst, std::abs(dE - R(i)));
    largest = std::max(largest, std::abs(R(i)));
  }
  EXPECT_LT(worst, 1e-6 * largest);
  std::printf("|K − Kᵀ| = %.2e (max |K| %.2e); |∂E/∂u − R| = %.2e (max |R| %.2e)\n", asym, size, worst, largest);
}

TEST(ShellSystem, VolumeGradientAndPressureLoadOfAShellPart) {
  const Model m = read_deck_text(kShellArteryBalloon, "shells.yaml");
  const System sys(m);
  const Eigen::VectorXd u = deformed(m);
  const int l = 1;  // inflation, on the balloon
  Eigen::VectorXd g;
  const double V = sys.volume(u, l, &g);
  EXPECT_GT(V, 0.0);
  double worst = 0;
  const double h = 1e-6;
  for (int i = 0; i < m.num_dofs(); ++i) {
    Eigen::VectorXd up = u, um = u;
    up(i) += h;
    um(i) -= h;
    worst = std::max(worst, std::abs((sys.volume(up, l) - sys.volume(um, l)) / (2 * h) - g(i)));
  }
  EXPECT_LT(worst, 1e-8 * g.cwiseAbs().maxCoeff());
  // ∂f_ext/∂p: the assembled residual with unit pressure minus without.
  LoadState with = loads_of(m, 0.0, 1), without = with;
  with.pressure[l] = 1.0;
  Eigen::VectorXd R1, R0;
  sys.assemble(u, with, R1, nullptr);
  sys.assemble(u, without, R0, nullptr);
  EXPECT_LT((R0 - R1 - sys.pressure_load(u, l)).cwiseAbs().maxCoeff(), 1e-12 * R1.cwiseAbs().maxCoeff());
}
