// The smooth (Catmull–Rom) master curve of deformable contact (contact/smooth_chain.hpp):
//  - force f = ∂Π/∂y and tangent K = ∂f/∂y by central differences of the whole
//    chain (slave and every master node), re-projecting at every perturbed state,
//    so the derivatives of the foot point ξ*(y) are checked too — interior and
//    end segments, chains of 2, 3 and 7 nodes, with and without an offset;
//  - the curve through the nodes, with a continuous normal at every node (along the
//    chord of its neighbours);
//  - a straight chain with uneven node spacing is its straight line (a flat
//    master keeps the faceted gap and normal: the contact patch test).
#include <gtest/gtest.h>

#include <cstdio>
#include <numbers>
#include <random>

#include "../support/fd.hpp"
#include "contact/contact_search.hpp"
#include "contact/smooth_chain.hpp"

using namespace tunica;
using tunica::test::fd_gradient;
using tunica::test::fd_jacobian;
using tunica::test::relative_error;

namespace {

/// An arc-like chain of m nodes with random spacing and perturbations, running in −z on the
/// r ≈ 1 side (normal towards −r: a lumen seen from inside).
Eigen::Matrix2Xd random_chain(std::mt19937& rng, int m) {
  std::uniform_real_distribution<double> u(0, 1);
  Eigen::Matrix2Xd c(2, m);
  double z = 0;
  for (int i = 0; i < m; ++i) {
    const double phi = 0.4 * (z - 1.0);
    c.col(i) << 1.0 - 0.5 * phi * phi + 0.01 * (u(rng) - 0.5), -z;
    z += 0.15 + 0.2 * u(rng);
  }
  return c;
}

/// Energy, force on the full vector v = (x_s, P_0 … P_{m−1}) by projecting afresh.
struct Evaluation {
  ContactPoint point;
  Eigen::VectorXd f;
  Eigen::MatrixXd K;
  int segment = -1;
};

Evaluation evaluate(const Eigen::VectorXd& v, int m, const ContactLaw& law, double area) {
  const Eigen::Vector2d xs = v.head<2>();
  const Eigen::Matrix2Xd chain = Eigen::Map<const Eigen::Matrix2Xd>(v.data() + 2, 2, m);
  const ChainProjection start = project_on_chain(xs, chain);
  const SmoothProjection p = project_on_smooth_chain(xs, chain, start, 0.0);
  Evaluation e;
  e.f = Eigen::VectorXd::Zero(v.size());
  e.K = Eigen::MatrixXd::Zero(v.size(), v.size());
  if (!p.found) return e;
  ContactVector10 f;
  ContactMatrix10 K;
  e.point = smooth_contact(xs, chain, p.segment, p.xi, area, law, f, &K);
  e.segment = p.segment;
  const std::array<int, 4> w = smooth_window(p.segment, m);
  const auto slot = [&](int a) { return a < 2 ? a : (w[(a - 2) / 2] < 0 ? -1 : 2 + 2 * w[(a - 2) / 2] + a % 2); };
  for (int a = 0; a < 10; ++a) {
    const int i = slot(a);
    if (i < 0) continue;
    e.f(i) += f(a);
    for (int b = 0; b < 10; ++b)
      if (const int j = slot(b); j >= 0) e.K(i, j) += K(a, b);
  }
  return e;
}

}  // namespace

TEST(SmoothContact, ForceAndTangentMatchFiniteDifferencesOfTheWholeChain) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  const double area = 0.05;
  double worst_f = 0, worst_K = 0;
  int n = 0;
  for (int m : {2, 3, 7})
    for (double offset : {0.0, 0.02})
      for (int trial = 0; trial < 12; ++trial) {
        const Eigen::Matrix2Xd chain = random_chain(rng, m);
        const ContactLaw law{.penalty = 1e3, .offset = offset};
        // A slave inside (smaller r) near a random point of a random segment, pushed through by depth.
        const int k = static_cast<int>(u(rng) * (m - 1));
        const double xi = 0.05 + 0.9 * u(rng), depth = 0.002 + 0.05 * u(rng);
        const Eigen::Vector2d foot = smooth_point(chain, k, xi);
        const Eigen::Vector2d tangent = smooth_point(chain, k, xi + 1e-6) - smooth_point(chain, k, xi - 1e-6);
        const Eigen::Vector2d normal = Eigen::Vector2d(tangent(1), -tangent(0)).normalized();
        Eigen::VectorXd v(2 + 2 * m);
        v << foot + (offset - depth) * normal, Eigen::Map<const Eigen::VectorXd>(chain.data(), 2 * m);
        const Evaluation e = evaluate(v, m, law, area);
        ASSERT_TRUE(e.point.active) << "m " << m << " trial " << trial;
        EXPECT_NEAR(e.point.gap, -depth, 1e-9);
        const auto energy = [&](const Eigen::VectorXd& y) { return evaluate(y, m, law, area).point.energy; };
        const auto force = [&](const Eigen::VectorXd& y) -> Eigen::VectorXd { return evaluate(y, m, law, area).f; };
        const double ef = relative_error(e.f, fd_gradient(energy, v, 1e-6));
        const double eK = relative_error(e.K, fd_jacobian(force, v, 1e-6));
        EXPECT_LT(ef, 1e-7) << "m " << m << " segment " << e.segment;
        EXPECT_LT(eK, 1e-6) << "m " << m << " segment " << e.segment;
        EXPECT_LT((e.K - e.K.transpose()).norm(), 1e-10 * e.K.norm());
        worst_f = std::max(worst_f, ef);
        worst_K = std::max(worst_K, eK);
        ++n;
      }
  std::printf("smooth master (%d states): largest FD error force %.2e, tangent %.2e\n", n, worst_f, worst_K);
}

TEST(SmoothContact, TheCurvePassesThroughTheNodesWithAContinuousNormal) {
  std::mt19937 rng(8);
  const Eigen::Matrix2Xd chain = random_chain(rng, 6);
  for (int k = 0; k + 1 < 6; ++k) {
    EXPECT_LT((smooth_point(chain, k, 0.0) - chain.col(k)).norm(), 1e-14);
    EXPECT_LT((smooth_point(chain, k, 1.0) - chain.col(k + 1)).norm(), 1e-14);
  }
  for (int k = 0; k + 2 < 6; ++k) {
    const double h = 1e-7;
    const Eigen::Vector2d left = (smooth_point(chain, k, 1.0) - smooth_point(chain, k, 1.0 - h)) / h;
    const Eigen::Vector2d right = (smooth_point(chain, k + 1, h) - smooth_point(chain, k + 1, 0.0)) / h;
    EXPECT_LT((left.normalized() - right.normalized()).norm(), 1e-6) << "node " << k + 1;
    // Both along the chord of the node's neighbours.
    const Eigen::Vector2d chord = (chain.col(k + 2) - chain.col(k)).normalized();
    EXPECT_LT((left.normalized() - chord).norm(), 1e-6) << "node " << k + 1;
  }
}

TEST(SmoothContact, AStraightChainIsItsLineWhateverTheSpacing) {
  // Flat master z = 0 from r = 2 to r = 0 (normal +z), uneven spacing.
  Eigen::Matrix2Xd chain(2, 5);
  chain << 2.0, 1.7, 0.9, 0.75, 0.0, 0, 0, 0, 0, 0;
  const ContactLaw law{.penalty = 500};
  for (double r : {1.95, 1.3, 0.8, 0.2}) {
    const Eigen::Vector2d xs(r, -0.003);
    const SmoothProjection p = project_on_smooth_chain(xs, chain, project_on_chain(xs, chain), 0.0);
    ASSERT_TRUE(p.found);
    EXPECT_NEAR(p.signed_distance, -0.003, 1e-15);
    EXPECT_NEAR(p.normal(1), 1.0, 1e-15);
    ContactVector10 f;
    const ContactPoint c = smooth_contact(xs, chain, p.segment, p.xi, 0.1, law, f, nullptr);
    EXPECT_NEAR(c.pressure, 500 * 0.003, 1e-12);
    EXPECT_NEAR(smooth_point(chain, p.segment, p.xi)(0), r, 1e-13);
    // The slave's force is the pressure times its area along −n... and the master carries the rest.
    EXPECT_NEAR(f(1), -500 * 0.003 * 0.1, 1e-13);
    double master_z = 0;
    for (int a = 2; a < 10; a += 2) master_z += f(a + 1);
    EXPECT_NEAR(master_z, 500 * 0.003 * 0.1, 1e-13);
  }
}
