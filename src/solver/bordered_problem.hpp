#pragma once
// Volume control (theory manual (7.5)): the equilibrium problem bordered by the constraint
// c(u) = V(u) − target = 0, whose load's pressure p is one more unknown. The correction solves
//   [K  −g; ∂V/∂uᵀ  0] [Δu; Δp] = −[R; c],   g = ∂f_ext/∂p,
// as one sparse matrix, which stays regular at a pressure maximum where K alone is singular.
// It wraps a MechanicalProblem whose loads it owns the pressure of.
#include "solver/mechanical_problem.hpp"

namespace tunica {

class BorderedProblem : public NonlinearProblem {
public:
  /// `load`: the index of the load whose pressure is the unknown (in `loads`, which the inner
  /// problem reads); `target`: the enclosed volume to reach.
  BorderedProblem(MechanicalProblem& inner, LoadState& loads, int load, double target);

  int size() const override { return inner_.size() + 1; }
  double evaluate(Eigen::VectorXd& r) override;
  /// ‖R‖ of the equilibrium rows: the volume row is tested by side_conditions_hold.
  double residual_norm(const Eigen::VectorXd& r) const override;
  double work(const Eigen::VectorXd& dx, const Eigen::VectorXd& r) const override;
  /// |V − target| ≤ tolerance |target|.
  bool side_conditions_hold(double tolerance) const override;
  const TangentMatrix& jacobian(int iteration) override;
  /// The bordered matrix of the last evaluation with K in place of the equilibrium tangent (a
  /// tangent of System::layout with both triangles; the stress-free start's K + K₀,
  /// solver/volume_start.hpp). A general matrix: K is expanded into it.
  const TangentMatrix& bordered(const TangentMatrix& K);
  void step(const Eigen::VectorXd& dx, double factor) override;
  void describe(IterationRecord& rec) override { inner_.describe(rec); }
  double max_correction() const override { return inner_.max_correction(); }
  /// A correction along the constraint is taken whole, and the bordered matrix, whose last
  /// diagonal entry is 0 by design, is never perturbed.
  bool allows_backtracking() const override { return false; }
  bool allows_perturbation() const override { return false; }
  /// R₀ is about 0 at the start of an increment (only the target moved).
  bool yardstick_after_first_correction() const override { return true; }

  MechanicalProblem& inner() { return inner_; }
  /// The index of the load whose pressure is the unknown, and that pressure now.
  int load() const { return load_; }
  double pressure() const { return loads_.pressure[load_]; }

private:
  MechanicalProblem& inner_;
  LoadState& loads_;
  int load_;
  double target_;
  TangentMatrix A_;           // the bordered matrix (pattern of K plus a full last row and column), general
  SparseMatrix K_;            // K expanded (both triangles), read column by column into A_
  Eigen::VectorXd g_, dV_;    // free parts of ∂f_ext/∂p and ∂V/∂u at the last evaluation
  double c_ = 0;              // V − target at the last evaluation
};

}  // namespace tunica
