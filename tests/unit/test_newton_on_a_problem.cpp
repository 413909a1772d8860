// Newton's method sees a NonlinearProblem only (solver/nonlinear_problem.hpp, theory manual §7):
// it runs on problems that have nothing to do with a mesh, with its convergence tests, its line
// search (7.4), admissibility, side conditions and a first-correction strategy.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <stdexcept>
#include <vector>

#include "solver/newton.hpp"

using namespace tunica;

namespace {

/// r_i(x) = f(x_i) − b_i, one unknown per equation (a diagonal Jacobian).
class Scalars : public NonlinearProblem {
public:
  Scalars(std::function<double(double)> f, std::function<double(double)> df, Eigen::VectorXd x, Eigen::VectorXd b)
      : f_(std::move(f)), df_(std::move(df)), x_(std::move(x)), b_(std::move(b)), J_(x_.size(), x_.size()) {
    J_.setIdentity();
  }
  int size() const override { return static_cast<int>(x_.size()); }
  double evaluate(Eigen::VectorXd& r) override {
    ++evaluations;
    r.resize(size());
    for (int i = 0; i < size(); ++i) {
      if (admissible && !admissible(x_(i))) throw std::domain_error("x leaves the admissible states");
      r(i) = f_(x_(i)) - b_(i);
      J_.coeffRef(i, i) = df_(x_(i));
    }
    return b_.norm();
  }
  bool side_conditions_hold(double) const override { return side; }
  const TangentMatrix& jacobian(int) override {
    M_ = J_;
    return M_;
  }
  void step(const Eigen::VectorXd& dx, double factor) override { x_ += factor * dx; }
  double max_correction() const override { return 1e6; }
  void describe(IterationRecord& rec) override { rec.active_contacts = 7; }  // the problem's own column

  const Eigen::VectorXd& x() const { return x_; }
  std::function<bool(double)> admissible;
  bool side = true;
  int evaluations = 0;

private:
  std::function<double(double)> f_, df_;
  Eigen::VectorXd x_, b_;
  SparseMatrix J_;
  TangentMatrix M_;
};

std::vector<IterationRecord> run(NonlinearProblem& p, const SolverSettings& s, NewtonResult& result,
                                 FirstCorrectionStrategy* first = nullptr) {
  std::vector<IterationRecord> records;
  auto solver = make_linear_solver("auto");
  result = newton(p, *solver, s, [&](const IterationRecord& r) { records.push_back(r); }, first);
  return records;
}

}  // namespace

TEST(NewtonOnAProblem, ConvergesQuadraticallyOnACubic) {
  // x³ + x = b from x = 0: the relative residual r_{k+1} ≈ C r_k² once near the root.
  Scalars p([](double x) { return x * x * x + x; }, [](double x) { return 3 * x * x + 1; },
            Eigen::VectorXd::Zero(3), Eigen::Vector3d(2.0, 10.0, -30.0));
  NewtonResult result;
  const auto records = run(p, SolverSettings{}, result);
  ASSERT_TRUE(result.converged) << result.failure;
  EXPECT_NEAR(p.x()(0), 1.0, 1e-8);  // ‖r‖ ≤ 1e-9 ‖b‖, f′ ≥ 4
  EXPECT_NEAR(p.x()(1), 2.0, 1e-8);  // ‖r‖ ≤ 1e-9 ‖b‖, f′ ≥ 4
  EXPECT_NEAR(p.x()(2), -3.0, 1e-8);  // ‖r‖ ≤ 1e-9 ‖b‖, f′ ≥ 4
  // The last three reductions before round-off: the exponent log r_{k+1} / log r_k tends to 2.
  int quadratic = 0;
  for (std::size_t k = 1; k + 1 < records.size(); ++k) {
    const double a = records[k].relative_residual, b = records[k + 1].relative_residual;
    if (a < 1e-2 && b > 1e-15) quadratic += std::log(b) / std::log(a) > 1.8;
  }
  EXPECT_GE(quadratic, 1);
  EXPECT_EQ(records.front().iteration, 0);
  EXPECT_EQ(records.back().active_contacts, 7);  // describe() fills the problem's columns
  EXPECT_EQ(records.back().solver, "");          // the converged residual needs no solve
}

TEST(NewtonOnAProblem, LineSearchTamesArctan) {
  // atan(x) = 0 from x = 3: plain Newton overshoots further each step (|x₀| > 1.39 diverges);
  // halving the corrections that raise |r| converges.
  const auto f = [](double x) { return std::atan(x); };
  const auto df = [](double x) { return 1.0 / (1.0 + x * x); };
  SolverSettings s;
  s.max_iterations = 30;
  {
    Scalars p(f, df, Eigen::VectorXd::Constant(1, 3.0), Eigen::VectorXd::Zero(1));
    NewtonResult result;
    const auto records = run(p, s, result);
    ASSERT_TRUE(result.converged) << result.failure;
    EXPECT_LE(std::abs(std::atan(p.x()(0))), SolverSettings{}.residual_tolerance * std::atan(3.0));  // (7.2)
    int backtracks = 0;
    for (const auto& r : records) backtracks += r.backtracks;
    EXPECT_GT(backtracks, 0);
  }
  {
    s.line_search = false;
    Scalars p(f, df, Eigen::VectorXd::Constant(1, 3.0), Eigen::VectorXd::Zero(1));
    NewtonResult result;
    run(p, s, result);
    EXPECT_FALSE(result.converged);
  }
}

TEST(NewtonOnAProblem, AnInadmissibleCorrectionIsHalvedAndAnInadmissibleStartNamed) {
  // log x = log 2 from x = 10: the first correction lands at x < 0, where the problem throws.
  const auto f = [](double x) { return std::log(x); };
  const auto df = [](double x) { return 1.0 / x; };
  Scalars p(f, df, Eigen::VectorXd::Constant(1, 10.0), Eigen::VectorXd::Constant(1, std::log(2.0)));
  p.admissible = [](double x) { return x > 0; };
  NewtonResult result;
  const auto records = run(p, SolverSettings{}, result);
  ASSERT_TRUE(result.converged) << result.failure;
  EXPECT_NEAR(p.x()(0), 2.0, 4e-9);  // |r| ≤ 1e-9 log 5, f′ = 1/2
  ASSERT_GE(records.size(), 2u);
  EXPECT_GT(records[1].backtracks, 0);

  Scalars q(f, df, Eigen::VectorXd::Constant(1, -1.0), Eigen::VectorXd::Zero(1));
  q.admissible = [](double x) { return x > 0; };
  run(q, SolverSettings{}, result);
  EXPECT_FALSE(result.converged);
  EXPECT_EQ(result.failure, "x leaves the admissible states");
}

TEST(NewtonOnAProblem, SideConditionsMustHoldAndTheLimitIsNamed) {
  Scalars p([](double x) { return x; }, [](double) { return 1.0; }, Eigen::VectorXd::Zero(2),
            Eigen::Vector2d(1.0, 2.0));
  p.side = false;
  SolverSettings s;
  s.max_iterations = 4;
  NewtonResult result;
  const auto records = run(p, s, result);
  EXPECT_FALSE(result.converged);
  EXPECT_EQ(result.failure, "no convergence in 4 iterations");
  EXPECT_EQ(result.iterations, 4);
  EXPECT_EQ(records.size(), 5u);
}

TEST(NewtonOnAProblem, AFirstCorrectionStrategyIsIterationZero) {
  // A strategy that moves x most of the way to the root; Newton carries on from iteration 1
  // with its R₀ as the yardstick.
  struct HalfWay : FirstCorrectionStrategy {
    Scalars& p;
    explicit HalfWay(Scalars& q) : p(q) {}
    std::optional<FirstCorrection> take(LinearSolver&, const std::function<void(const IterationRecord&)>& cb) override {
      IterationRecord rec;
      rec.residual = 8.0;
      cb(rec);
      FirstCorrection f;
      f.dx = Eigen::VectorXd::Constant(1, 1.9);
      f.reference_residual = 8.0;
      f.slope = -8.0 * 1.9;
      p.step(f.dx, 1.0);
      return f;
    }
  };
  Scalars p([](double x) { return x * x * x; }, [](double x) { return 3 * x * x; }, Eigen::VectorXd::Zero(1),
            Eigen::VectorXd::Constant(1, 8.0));
  HalfWay first(p);
  NewtonResult result;
  const auto records = run(p, SolverSettings{}, result, &first);
  ASSERT_TRUE(result.converged) << result.failure;
  EXPECT_LE(std::abs(std::pow(p.x()(0), 3) - 8.0), SolverSettings{}.residual_tolerance * 8.0);  // R₀ = 8, (7.2)
  ASSERT_GE(records.size(), 2u);
  EXPECT_EQ(records[0].iteration, 0);
  EXPECT_EQ(records[1].iteration, 1);
  EXPECT_NEAR(records[1].relative_residual, std::abs(1.9 * 1.9 * 1.9 - 8.0) / 8.0, 1e-12);
}

TEST(NewtonOnAProblem, ASolverThatRefusesTheTangentSaysWhyAndWhichSolverTakesIt) {
  // −x = 1: a regular but negative definite tangent, which CHOLMOD refuses and UMFPACK factorizes.
  const auto f = [](double x) { return -x; };
  const auto df = [](double) { return -1.0; };
  Scalars p(f, df, Eigen::VectorXd::Zero(2), Eigen::Vector2d(1.0, 1.0));
  auto cholmod = make_linear_solver("cholmod");
  const NewtonResult refused = newton(p, *cholmod, SolverSettings{}, [](const IterationRecord&) {});
  EXPECT_FALSE(refused.converged);
  EXPECT_NE(refused.failure.find("could not factorize"), std::string::npos) << refused.failure;
  EXPECT_NE(refused.failure.find("`linear_solver: auto` or `umfpack`"), std::string::npos) << refused.failure;

  Scalars q(f, df, Eigen::VectorXd::Zero(2), Eigen::Vector2d(1.0, 1.0));
  auto umfpack = make_linear_solver("umfpack");
  EXPECT_TRUE(newton(q, *umfpack, SolverSettings{}, [](const IterationRecord&) {}).converged);
  EXPECT_EQ(umfpack->refusal(), "");
}

TEST(NewtonOnAProblem, ConvergingSurelyGoesPastTheLimitAndASteadyRateDoesNot) {
  // x³ + x = 1e4 (root near 21.5) from x = 1000: each correction takes a third of x off, ‖r‖
  // falls at a steady rate of about 8/27, then the rate improves into the quadratic basin.
  Scalars full([](double x) { return x * x * x + x; }, [](double x) { return 3 * x * x + 1; },
               Eigen::VectorXd::Constant(1, 1000.0), Eigen::VectorXd::Constant(1, 1e4));
  NewtonResult result;
  SolverSettings s;
  s.max_iterations = 100;
  run(full, s, result);
  ASSERT_TRUE(result.converged) << result.failure;
  const int needed = result.iterations;
  ASSERT_GE(needed, 12);
  // The limit two iterations short of it: the last three reductions improve, so Newton goes on.
  Scalars p([](double x) { return x * x * x + x; }, [](double x) { return 3 * x * x + 1; },
            Eigen::VectorXd::Constant(1, 1000.0), Eigen::VectorXd::Constant(1, 1e4));
  s.max_iterations = needed - 2;
  run(p, s, result);
  EXPECT_TRUE(result.converged) << result.failure;
  EXPECT_EQ(result.iterations, needed);
  // With max_iterations_contracting at the limit it stops there.
  Scalars q([](double x) { return x * x * x + x; }, [](double x) { return 3 * x * x + 1; },
            Eigen::VectorXd::Constant(1, 1000.0), Eigen::VectorXd::Constant(1, 1e4));
  s.max_iterations_contracting = s.max_iterations;
  run(q, s, result);
  EXPECT_FALSE(result.converged);
  EXPECT_EQ(result.failure, fmt::format("no convergence in {} iterations", needed - 2));
  // eˣ = 1 from x = 40: each correction takes 1 off x, ‖r‖ falls by 1/e at a steady rate for
  // about 37 iterations: not converging surely, no iterations past the limit.
  Scalars e([](double x) { return std::exp(x); }, [](double x) { return std::exp(x); },
            Eigen::VectorXd::Constant(1, 40.0), Eigen::VectorXd::Constant(1, 1.0));
  run(e, SolverSettings{}, result);
  EXPECT_FALSE(result.converged);
  EXPECT_EQ(result.failure, "no convergence in 12 iterations");
}

TEST(NewtonOnAProblem, AFlatResidualStopsAsStagnating) {
  // A tangent 1e9 times too stiff: every correction is tiny and ‖r‖ stays put.
  Scalars p([](double x) { return x; }, [](double) { return 1e9; }, Eigen::VectorXd::Zero(1),
            Eigen::VectorXd::Constant(1, 1.0));
  NewtonResult result;
  const auto records = run(p, SolverSettings{}, result);
  EXPECT_FALSE(result.converged);
  EXPECT_EQ(result.failure, "stagnating (‖R‖ within 10 % over the last 5 iterations)");
  EXPECT_EQ(result.iterations, 5);
  SolverSettings off;
  off.stagnation_iterations = 0;
  Scalars q([](double x) { return x; }, [](double) { return 1e9; }, Eigen::VectorXd::Zero(1),
            Eigen::VectorXd::Constant(1, 1.0));
  run(q, off, result);
  EXPECT_EQ(result.failure, "no convergence in 12 iterations");
}

TEST(NewtonOnAProblem, AnEnergyTestThatStallsIsNamedInTheFailure) {
  // x = b with the Jacobian 2: each correction halves r, |Δx·r| falls by 4 per iteration. The
  // residual test (1e-2) holds from iteration 7; an energy test of 1e-30 is never met in 12.
  Scalars p([](double x) { return x; }, [](double) { return 2.0; }, Eigen::VectorXd::Zero(1),
            Eigen::VectorXd::Constant(1, 1.0));
  SolverSettings s;
  s.residual_tolerance = 1e-2;
  s.energy_tolerance = 1e-30;
  s.roundoff_tolerance = 0;
  NewtonResult result;
  run(p, s, result);
  ASSERT_FALSE(result.converged);
  EXPECT_GT(result.energy_stall, 0.0);
  EXPECT_NE(result.failure.find("; ‖R‖ met `residual_tolerance` ("), std::string::npos) << result.failure;
  EXPECT_NE(result.failure.find("the energy test did not (|Δu·R| at "), std::string::npos) << result.failure;
  EXPECT_NE(result.failure.find("above `energy_tolerance` 1e-30"), std::string::npos) << result.failure;
  // The residual test not met: no such words.
  s.residual_tolerance = 1e-12;
  Scalars q([](double x) { return x; }, [](double) { return 2.0; }, Eigen::VectorXd::Zero(1),
            Eigen::VectorXd::Constant(1, 1.0));
  NewtonResult other;
  run(q, s, other);
  ASSERT_FALSE(other.converged);
  EXPECT_EQ(other.energy_stall, 0.0);
  EXPECT_EQ(other.failure.find("energy test"), std::string::npos) << other.failure;
}
