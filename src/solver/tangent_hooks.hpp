#pragma once
// Modifications of the tangent that change Newton's direction but never its converged state
// (the residual stays exact): they are attached to a MechanicalProblem, which applies them in
// the order attached to the Jacobian it hands to Newton (solver/nonlinear_problem.hpp).
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
class StartStiffness : public TangentHook {
public:
  StartStiffness(const System& system, const LoadState& loads) : system_(system), loads_(loads) {}
  void apply(int iteration, TangentMatrix& K) override {
    if (iteration == 0) add(Eigen::VectorXd(), K);
  }
  /// K += K₀; returns K₀ d over all DOFs (d over all DOFs, or empty for none).
  Eigen::VectorXd add(const Eigen::VectorXd& d, TangentMatrix& K) const {
    return system_.add_start_stiffness(loads_, d, K);
  }

private:
  const System& system_;
  const LoadState& loads_;
};

/// K ← (K + Kᵀ)/2 at every iteration: the follower-pressure load stiffness symmetrized so that
/// a Cholesky factorization applies (a modified Newton method, linear convergence; §7). K is a
/// split tangent with both triangles (solver/increment.cpp asks for them): slot by slot.
class Symmetrization : public TangentHook {
public:
  void apply(int, TangentMatrix& K) override { K.symmetrize(); }
};

}  // namespace tunica
