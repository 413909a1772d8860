#pragma once
// Modifications of the tangent that change Newton's direction but never its converged state
// (the residual stays exact): they are attached to a MechanicalProblem, which applies them in
// the order attached to the Jacobian it hands to Newton (solver/nonlinear_problem.hpp).
#include <algorithm>
#include <functional>
#include <optional>

#include <Eigen/Core>

#include "assembly/system.hpp"
#include "linalg/tangent_matrix.hpp"

namespace tunica {

class TangentHook {
public:
  virtual ~TangentHook() = default;
  /// Modifies K, the Jacobian of iteration `iteration` (0: the first correction of the increment).
  virtual void apply(int iteration, TangentMatrix& K) = 0;
};

/// The stiffened first correction from a stress-free state, theory manual §7.2, (7.6)–(7.8):
/// K + K₀ at iteration 0 only, K₀ the normal-tension stiffness of a Laplace tension estimate
/// (System::add_start_stiffness). The tangent predictor (solver/tangent_predictor.hpp), when it
/// makes the first correction, uses it through add() with the prescribed increment.
///
/// With `slack` the tension is not Laplace's but the uniform T̄ of a step without pressure, (7.14)
/// (System::add_slack_stiffness): the metric of SlackRegularization.
class StartStiffness : public TangentHook {
public:
  StartStiffness(const System& system, const LoadState& loads, bool slack = false)
      : system_(system), loads_(loads), slack_(slack) {}
  void apply(int iteration, TangentMatrix& K) override {
    if (iteration == 0) add(Eigen::VectorXd(), K);
  }
  /// K += K₀; returns K₀ d over all DOFs (d over all DOFs, or empty for none).
  Eigen::VectorXd add(const Eigen::VectorXd& d, TangentMatrix& K) const {
    return slack_ ? system_.add_slack_stiffness(1.0, loads_.step, d, K) : system_.add_start_stiffness(loads_, d, K);
  }
  /// K += θ K₀ (K₀ is linear in the pressures, and in T̄).
  void add_scaled(double theta, TangentMatrix& K) const {
    if (slack_) {
      system_.add_slack_stiffness(theta, loads_.step, Eigen::VectorXd(), K);
      return;
    }
    LoadState scaled = loads_;
    for (double& p : scaled.pressure) p *= theta;
    system_.add_start_stiffness(scaled, Eigen::VectorXd(), K);
  }

private:
  const System& system_;
  const LoadState& loads_;
  bool slack_ = false;
};

/// A tangent regularized at every iteration by a normal-tension stiffness scaled by the residual:
/// K + θ_k K₀, θ_k = min(1, ‖R_k‖/‖R_0‖) (R_0 the first residual whose tangent it regularizes), a
/// Levenberg–Marquardt step with K₀ for the metric, which converges quadratically also where the
/// solutions form a manifold, while the residual stays exact. Two uses:
///  - the inverse problem's ∂R/∂X (theory manual §13, (13.11)), with the start stiffness of the
///    opposite sign: a tube's reference shapes that differ by an inextensional motion give the
///    imaged state the same residual to first order, and ∂R/∂X is singular along them;
///  - a 3-D membrane step without pressure ((7.14), the slack StartStiffness): a wall without hoop
///    tension (a tube stretched alone) has no stiffness against ovalizing, and K is singular along
///    those modes.
/// In both the regularization keeps the corrections off the singular modes.
class ScaledRegularization : public TangentHook {
public:
  ScaledRegularization(const StartStiffness& k0, std::function<double()> residual_norm)
      : k0_(k0), norm_(std::move(residual_norm)) {}
  void apply(int iteration, TangentMatrix& K) override {
    const double r = norm_();
    // R_0: the first residual it sees (iteration 1 after a first correction by the predictor).
    if (iteration == 0 || !(r0_ > 0)) r0_ = r;
    const double theta = r0_ > 0 ? std::min(1.0, r / r0_) : 0.0;
    if (theta > 0) k0_.add_scaled(theta, K);
  }

private:
  const StartStiffness& k0_;
  std::function<double()> norm_;
  double r0_ = 0;
};

/// K ← (K + Kᵀ)/2 at every iteration: the follower-pressure load stiffness symmetrized so that
/// a Cholesky factorization applies (a modified Newton method, linear convergence; §7). K is a
/// split tangent with both triangles (solver/increment.cpp asks for them): slot by slot.
class Symmetrization : public TangentHook {
public:
  void apply(int, TangentMatrix& K) override { K.symmetrize(); }
};

}  // namespace tunica
