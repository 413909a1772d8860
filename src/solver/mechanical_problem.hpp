#pragma once
// The equilibrium of one load increment as a NonlinearProblem (theory manual (7.1)): the
// unknowns are the free DOFs of u (prescribed DOFs already set), the residual R_f(u) and the
// tangent K_ff = ∂R_f/∂u_f come from System::assemble at fixed loads. It tracks the contact
// active set for the record, takes the Gauss–Newton contact tangent where slave nodes enter it
// (theory manual (9.10)) and applies its tangent hooks (solver/tangent_hooks.hpp).
#include <memory>
#include <vector>

#include "assembly/system.hpp"
#include "solver/nonlinear_problem.hpp"
#include "solver/tangent_hooks.hpp"

namespace tunica {

class MechanicalProblem : public NonlinearProblem {
public:
  /// u (all DOFs) is the state, moved in place; `loads` is read at every evaluation. `upper`:
  /// whether the tangent's upper triangle is assembled, for a consumer that reads it (System).
  MechanicalProblem(const System& system, const LoadState& loads, Eigen::VectorXd& u, bool upper = true);

  /// Appends a tangent modification; hooks are applied in the order added.
  void add_hook(std::unique_ptr<TangentHook> hook) { hooks_.push_back(std::move(hook)); }
  /// ‖R‖ over the free DOFs at the last evaluation (before any line-search step back).
  double last_residual_norm() const { return last_norm_; }

  int size() const override { return system_.num_free(); }
  double evaluate(Eigen::VectorXd& r) override;
  const TangentMatrix& jacobian(int iteration) override;
  void step(const Eigen::VectorXd& dx, double factor) override;
  void describe(IterationRecord& rec) override;
  int entering_contact() const override;
  double max_correction() const override { return max_correction_; }
  bool allows_factorization_reuse() const override { return true; }

  const System& system() const { return system_; }
  const LoadState& loads() const { return loads_; }
  Eigen::VectorXd& state() { return u_; }
  /// The free-DOF part of a vector over all DOFs.
  Eigen::VectorXd free_part(const Eigen::VectorXd& full) const;
  /// The contact active set the next kept evaluation's changes are counted from (a first
  /// correction that evaluated elsewhere, the tangent predictor at u_n, hands it over).
  void set_active_set(std::vector<char> set) { previous_set_ = std::move(set); }
  /// The Jacobian as evaluated, without the hooks (the tangent predictor assembles into it).
  TangentMatrix& raw_jacobian() { return K_; }

private:
  const System& system_;
  const LoadState& loads_;
  Eigen::VectorXd& u_;
  TangentMatrix K_;
  Eigen::VectorXd R_;  // all DOFs
  double last_norm_ = 0;
  std::vector<std::unique_ptr<TangentHook>> hooks_;
  double max_correction_ = 0;
  int active_contacts_ = 0;
  std::vector<char> active_set_, previous_set_;  // contact active set at this / the previous kept residual
  bool nodes_entered_ = false;                     // slave nodes entered contact at the last kept residual
};

}  // namespace tunica
