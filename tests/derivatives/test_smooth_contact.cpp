// The smooth (Catmull–Rom) master curve of deformable contact (contact/smooth_chain.hpp):
//  - force f = ∂Π/∂y and tangent K = ∂f/∂y by central differences of the whole
//    chain (slave and every master node), re-projecting at every perturbed state,
//    so the derivatives of the foot point ξ*(y) are checked too — interior and
//    end segments, chains of 2, 3 and 7 nodes, with and without an offset;
//  - the curve through the nodes, with a continuous normal at every node (along the
//    chord of its neighbours);
//  - a straight chain with uneven node spacing is its straight line (a flat
//    master keeps the faceted gap and normal: the contact patch test);
//  - the chain's ends: the end tangent along the end chord; f and K by finite
//    differences for slaves whose foot lies beyond an end (within the end
//    tolerance), on a chain far from the origin (|x| ≈ 300 segment lengths, where
//    an absolute stopping test of the projection would sit below round-off); a
//    slave beyond an end and deep behind the surface is not in contact.
#include <gtest/gtest.h>

#include <cstdio>
#include <limits>
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

Evaluation evaluate(const Eigen::VectorXd& v, int m, const ContactLaw& law, double area, double tau = 0.0) {
  const Eigen::Vector2d xs = v.head<2>();
  const Eigen::Matrix2Xd chain = Eigen::Map<const Eigen::Matrix2Xd>(v.data() + 2, 2, m);
  const ChainProjection start = project_on_chain(xs, chain, std::numeric_limits<double>::infinity(), tau);
  const SmoothProjection p = project_on_smooth_chain(xs, chain, start, tau);
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

TEST(SmoothContact, TheEndTangentIsAlongTheEndChord) {
  std::mt19937 rng(9);
  const Eigen::Matrix2Xd chain = random_chain(rng, 5);
  const double h = 1e-7;
  const Eigen::Vector2d first = (smooth_point(chain, 0, h) - smooth_point(chain, 0, 0.0)) / h;
  const Eigen::Vector2d last = (smooth_point(chain, 3, 1.0) - smooth_point(chain, 3, 1.0 - h)) / h;
  EXPECT_LT((first.normalized() - (chain.col(1) - chain.col(0)).normalized()).norm(), 1e-6);
  EXPECT_LT((last.normalized() - (chain.col(4) - chain.col(3)).normalized()).norm(), 1e-6);
}

TEST(SmoothContact, BeyondTheEndsForceAndTangentMatchFiniteDifferencesFarFromTheOrigin) {
  std::mt19937 rng(10);
  std::uniform_real_distribution<double> u(0, 1);
  const double area = 0.05, tau = kSmoothMasterEndTolerance;
  double worst_f = 0, worst_K = 0;
  int n = 0;
  for (int trial = 0; trial < 20; ++trial) {
    // Far from the origin: shift the chain by (75, −40) (segments ≈ 0.25: |x|/ℓ ≈ 300).
    Eigen::Matrix2Xd chain = random_chain(rng, 6);
    chain.row(0).array() += 75.0;
    chain.row(1).array() -= 40.0;
    const int m = 6;
    const bool at_start = trial % 2 == 0;
    const int k = at_start ? 0 : m - 2;
    // The end tangent and normal; the slave beyond the end by 5–15 % of the end segment, at a
    // distance of offset − depth with an offset of half the end segment.
    const Eigen::Vector2d end = at_start ? chain.col(0) : chain.col(m - 1);
    const Eigen::Vector2d t = (at_start ? chain.col(1) - chain.col(0) : chain.col(m - 1) - chain.col(m - 2));
    const double l = t.norm();
    const Eigen::Vector2d tn = t / l, normal(tn(1), -tn(0));
    const double beyond = (0.05 + 0.1 * u(rng)) * l, offset = 0.5 * l, depth = 0.002 + 0.02 * u(rng) * l;
    const Eigen::Vector2d xs = end + (at_start ? -beyond : beyond) * tn + (offset - depth) * normal;
    const ContactLaw law{.penalty = 1e3, .offset = offset};
    Eigen::VectorXd v(2 + 2 * m);
    v << xs, Eigen::Map<const Eigen::VectorXd>(chain.data(), 2 * m);
    const Evaluation e = evaluate(v, m, law, area, tau);
    ASSERT_TRUE(e.point.active) << "trial " << trial;
    ASSERT_EQ(e.segment, k) << "trial " << trial;
    EXPECT_TRUE(at_start ? e.point.xi < 0 : e.point.xi > 1) << "the foot lies beyond the end, xi " << e.point.xi;
    // The cubic's continuation bends away from the end tangent's line: about the depth built.
    EXPECT_NEAR(e.point.gap, -depth, 0.01 * l);
    const auto energy = [&](const Eigen::VectorXd& y) { return evaluate(y, m, law, area, tau).point.energy; };
    const auto force = [&](const Eigen::VectorXd& y) -> Eigen::VectorXd { return evaluate(y, m, law, area, tau).f; };
    const double ef = relative_error(e.f, fd_gradient(energy, v, 1e-6));
    const double eK = relative_error(e.K, fd_jacobian(force, v, 1e-6));
    EXPECT_LT(ef, 1e-6) << "trial " << trial;
    EXPECT_LT(eK, 1e-5) << "trial " << trial;
    worst_f = std::max(worst_f, ef);
    worst_K = std::max(worst_K, eK);
    ++n;
  }
  std::printf("smooth master beyond the ends, |x| ~ 300 segments (%d states): largest FD error force %.2e, tangent %.2e\n",
              n, worst_f, worst_K);
}

TEST(SmoothContact, BeyondAnEndAndDeepBehindTheSurfaceIsNoContact) {
  // A flat master along r (normal +z) ending at r = 1, segments 0.25; a slave just beyond the end.
  Eigen::Matrix2Xd chain(2, 4);
  chain << 1.75, 1.5, 1.25, 1.0, 0, 0, 0, 0;
  const double tau = kSmoothMasterEndTolerance;
  for (const auto& [x, contact] : std::vector<std::pair<Eigen::Vector2d, bool>>{
           {Eigen::Vector2d(0.95, -1.0), false},   // 4 segments behind: no surface there
           {Eigen::Vector2d(0.995, -0.02), true},  // just behind, shifted by less than half its distance
           {Eigen::Vector2d(0.95, -0.01), false},  // shifted by more than half its distance
           {Eigen::Vector2d(0.80, -0.01), false},  // beyond by more than half its distance
       }) {
    const SmoothProjection p =
        project_on_smooth_chain(x, chain, project_on_chain(x, chain, std::numeric_limits<double>::infinity(), tau), tau);
    EXPECT_EQ(p.found && p.signed_distance < 0, contact) << "slave at (" << x(0) << ", " << x(1) << ")";
  }
}
