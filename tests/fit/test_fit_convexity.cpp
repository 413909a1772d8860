// Convexity of every fitted Fung material (theory manual §3: c > 0 and a positive definite
// quadratic form): guaranteed by the Cholesky parametrisation with a bounded-below
// diagonal, whatever the start — even a non-convex one, which is projected first.
#include <gtest/gtest.h>

#include <random>

#include "fit/inflation_fit.hpp"
#include "fit_test_support.hpp"
#include "materials/fung.hpp"

using namespace tunica;
using namespace tunica::fit_test;

namespace {

/// Fung's matrix and c from the constants of fung2d (c, a1, a2, a4) or fung3d (c, a1 … a6).
bool fung_convex(const Eigen::VectorXd& k) {
  Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
  if (k.size() == 4) {
    A << k(1), k(3), 0, k(3), k(2), 0, 0, 0, 0;
  } else {
    A << k(1), k(4), k(6), k(4), k(2), k(5), k(6), k(5), k(3);
  }
  return k(0) > 0 && FungMaterial::is_convex(A, 0.0);
}

}  // namespace

// Any θ in the box maps to c > 0 and A = L Lᵀ with a positive diagonal of L, so A is positive
// definite; the deck's factory (a floating-point Cholesky test) accepts it unless A is within
// round-off of singular (condition number > 1e12, possible only in 3-D at the box's corners;
// a fit never stops there, as Ceres rejects steps whose evaluation fails). 2-D: every draw.
TEST(FitConvexity, EveryPointOfTheBoxIsAConvexFungMaterial) {
  std::mt19937_64 rng(7);
  for (const char* name : {"fung2d", "fung3d"}) {
    const MaterialParametrization& m = material_parametrization(name);
    int checked = 0;
    for (int trial = 0; trial < 500; ++trial) {
      Eigen::VectorXd theta(m.lower.size());
      for (int j = 0; j < theta.size(); ++j) {
        // Uniform in a box around the region of interest; every fifth draw puts the
        // Cholesky diagonal at its lower bound (the edge of the convex set).
        const double lo = std::max(m.lower(j), -10.0), hi = std::min(m.upper(j), 10.0);
        theta(j) = lo + (hi - lo) * std::uniform_real_distribution<double>(0, 1)(rng);
        if (trial % 5 == 0 && m.lower(j) > -1) theta(j) = m.lower(j);
      }
      const Eigen::VectorXd k = m.constants_of(theta);
      EXPECT_GT(k(0), 0);
      const int n = k.size() == 4 ? 2 : 3;
      Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);
      if (n == 2)
        A << k(1), k(3), k(3), k(2);
      else
        A << k(1), k(4), k(6), k(4), k(2), k(5), k(6), k(5), k(3);
      const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(A).eigenvalues();
      if (n == 3 && ev(0) < 1e-12 * ev(n - 1)) continue;
      ++checked;
      EXPECT_TRUE(fung_convex(k)) << name << " θ = " << theta.transpose();
      EXPECT_NO_THROW(m.make_material(k)) << name << " θ = " << theta.transpose();
    }
    EXPECT_GE(checked, std::string(name) == "fung2d" ? 500 : 350) << name;
  }
}

// Bad starts, one of them not even convex (a4² > a1 a2, projected onto the admissible set).
// Every fit ends convex. With the default rescaling of c to the data they all reach the
// optimum of the built-in starts; taken literally, a start whose exponent is e^50 too stiff
// may stall — convex all the same.
TEST(FitConvexity, BadStartsEndConvex) {
  const InflationData data = three_levels(*make("fung2d", paper_fung()), 0.02, 3);
  const FitResult reference = fit_inflation_data(data, FitOptions{});
  const Eigen::Vector4d starts[] = {
      {1 * kKPa, 0.1, 0.1, 1.0},       // not convex: a4² = 1 > a1 a2 = 0.01
      {1e4 * kKPa, 50.0, 1e-3, -0.2},  // far too stiff, nearly degenerate
      {1e-3 * kKPa, 1e-6, 1e-6, 0.0},  // far too soft, nearly zero quadratic form
  };
  for (const Eigen::Vector4d& start : starts)
    for (bool rescale : {true, false}) {
      FitOptions o;
      o.start_constants = {start};
      o.use_builtin_starts = false;
      o.rescale_starts = rescale;
      o.max_iterations = rescale ? 400 : 100;
      const FitResult fit = fit_inflation_data(data, o);
      EXPECT_TRUE(fung_convex(fit.constants)) << start.transpose();
      EXPECT_TRUE(fung_convex(fit.starts[0].start)) << start.transpose();
      EXPECT_EQ(fit.starts[0].projected, &start == &starts[0]);
      if (rescale) {
        EXPECT_NEAR(fit.cost, reference.cost, 1e-8 * reference.cost) << start.transpose();
      }
    }
}

// A model that cannot describe the data (Fung fitted to Mooney–Rivlin data: the best Fung
// fit drifts towards c → ∞, a → 0, the quadratic limit c Q) still ends convex, and the
// fit says it did not converge.
TEST(FitConvexity, MisspecifiedModelEndsConvex) {
  const InflationData data = three_levels(*make("mooney_rivlin", Eigen::Vector2d(0.2, 0.05)));
  FitOptions o;
  o.max_starts = 1;
  o.max_iterations = 50;
  const FitResult fit = fit_inflation_data(data, o);
  EXPECT_TRUE(fung_convex(fit.constants)) << fit.constants.transpose();
  EXPECT_FALSE(fit.starts[fit.best_start].converged);
}
