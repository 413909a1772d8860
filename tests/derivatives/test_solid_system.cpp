// The assembled system (System) of a model with an axisymmetric membrane part (with a follower
// pressure) and an axisymmetric solid part (elements/axisym_solid.hpp, mean dilatation):
// (1) central differences of the assembled residual R against the tangent K, every free DOF,
//     with the solid active and, before it enters, with its DOFs held (R_i = k_i u_i);
// (2) without pressure K is symmetric and R = ∂E/∂u on the free DOFs, E = Σ_parts part_energy
//     (energy and residual consistent);
// (3) the assembly is the same with 1 and 2 OpenMP threads, bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "../support/capture.hpp"
#include "../support/solid_decks.hpp"
#include "../support/system_fd.hpp"

#ifdef _OPENMP
#include <omp.h>
#endif

using namespace tunica;
using namespace tunica::test;

namespace {

LoadState loads_of(const Model& m, double pressure, int step) {
  LoadState l;
  l.boundary.assign(m.boundaries.size(), 0.0);
  l.boundary[1] = 0.1;   // stretch
  l.boundary[3] = -0.02;  // plaque_push
  l.pressure.assign(m.loads.size(), pressure);
  l.volume.assign(m.loads.size(), 0.0);
  l.step = step;
  return l;
}

/// A deformed state: every DOF moved by a smooth pseudo-random amount (the solid by a few %).
Eigen::VectorXd deformed(const Model& m) {
  Eigen::VectorXd u(m.num_dofs());
  for (int n = 0; n < m.num_nodes(); ++n) {
    u(2 * n) = 0.02 * std::sin(1.3 * n + 0.4);
    u(2 * n + 1) = 0.015 * std::cos(0.7 * n);
  }
  return u;
}

double total_energy(const System& sys, const Model& m, const Eigen::VectorXd& u) {
  double E = 0;
  for (std::size_t p = 0; p < m.parts.size(); ++p) E += sys.part_energy(u, static_cast<int>(p));
  return E;
}

}  // namespace

TEST(SolidSystem, AssembledTangentMatchesFiniteDifferences) {
  const Model m = read_deck_text(kArteryWithPlaque, "artery-plaque.yaml");
  ASSERT_EQ(m.parts[1].enter_step, 1);
  const System sys(m);
  for (int step : {0, 1}) {  // plaque held, plaque active
    const LoadState loads = loads_of(m, 0.004, step);
    Eigen::VectorXd u = deformed(m);
    if (step == 0)  // a held DOF is at 0 in a run; here it is not, to test R_i = k_i u_i too
      for (int n : m.parts[1].nodes) u(2 * n) *= 0.1;
    sys.apply_boundary(loads, u);
    Eigen::VectorXd R;
    SparseMatrix K;
    sys.assemble_full(u, loads, R, K);
    const Eigen::MatrixXd Kd(K);
    const double worst = fd_tangent_error(sys, loads, u, Kd, 1e-7);
    const double size = Kd.cwiseAbs().maxCoeff();
    EXPECT_LT(worst, 1e-6 * size) << "step " << step;
    std::printf("step %d (plaque %s): FD of the assembled residual vs K: %.2e (max |K| %.2e)\n", step,
                step == 0 ? "held" : "active", worst, size);
  }
}

TEST(SolidSystem, WithoutPressureTheTangentIsSymmetricAndTheResidualIsTheEnergyGradient) {
  const Model m = read_deck_text(kArteryWithPlaque, "artery-plaque.yaml");
  const System sys(m);
  const LoadState loads = loads_of(m, 0.0, 1);
  Eigen::VectorXd u = deformed(m);
  sys.apply_boundary(loads, u);
  Eigen::VectorXd R;
  SparseMatrix K;
  sys.assemble_full(u, loads, R, K);
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

TEST(SolidSystem, ParallelAssemblyIsBitForBitTheSerialOne) {
#ifdef _OPENMP
  // Many solid elements, so that a colour is large enough to run in parallel.
  const Model m = read_deck_text(replace(replace(kArteryWithPlaque, "elements_r: 2", "elements_r: 20"), "elements_z: 4",
                                         "elements_z: 400"),
                                 "artery-plaque-fine.yaml");
  const System sys(m);
  LoadState loads = loads_of(m, 0.004, 1);
  loads.boundary[3] = -0.0005;  // the top row may move by a fraction of the 0.0025 mm element height only
  Eigen::VectorXd u = deformed(m) * 0.005;  // small against the 0.0025 mm element height
  sys.apply_boundary(loads, u);
  Eigen::VectorXd R1, R2;
  SparseMatrix K1, K2;
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  sys.assemble_full(u, loads, R1, K1);
  omp_set_num_threads(2);
  sys.assemble_full(u, loads, R2, K2);
  omp_set_num_threads(threads);
  EXPECT_EQ((R1 - R2).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(Eigen::MatrixXd(K1 - K2).cwiseAbs().maxCoeff(), 0.0);
#else
  GTEST_SKIP() << "built without OpenMP";
#endif
}
