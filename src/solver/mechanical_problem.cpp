#include "solver/mechanical_problem.hpp"

#include "solver/newton.hpp"

namespace tunica {

namespace {
/// Ten times the diagonal of the model's bounding box (current positions do not matter for a
/// bound this loose): no Newton correction of a sound tangent moves a node that far.
double step_bound(const Model& m) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
  for (const auto& X : m.X) {
    lo = lo.cwiseMin(X);
    hi = hi.cwiseMax(X);
  }
  return m.X.empty() ? 1e300 : 10.0 * std::max((hi - lo).norm(), 1e-300);
}
}  // namespace

MechanicalProblem::MechanicalProblem(const System& system, const LoadState& loads, Eigen::VectorXd& u, bool upper)
    : system_(system), loads_(loads), u_(u), K_(system.tangent(upper)), max_correction_(step_bound(system.model())) {}

Eigen::VectorXd MechanicalProblem::free_part(const Eigen::VectorXd& full) const {
  Eigen::VectorXd f(system_.num_free());
  for (int i = 0; i < system_.num_dofs(); ++i)
    if (system_.equation(i) >= 0) f(system_.equation(i)) = full(i);
  return f;
}

double MechanicalProblem::evaluate(Eigen::VectorXd& r) {
  double scale = 0;
  system_.assemble(u_, loads_, R_, &K_, &scale, &active_contacts_, &active_set_);
  r = free_part(R_);
  last_norm_ = r.norm();
  return scale;
}

const TangentMatrix& MechanicalProblem::jacobian(int iteration) {
  // Slave nodes that entered contact at this evaluation came in by a correction that did not see
  // them, often deep: the Gauss–Newton contact tangent, theory manual (9.10).
  if (nodes_entered_) system_.add_contact_curvature(u_, loads_, -1.0, K_);
  for (auto& hook : hooks_) hook->apply(iteration, K_);
  return K_;
}

void MechanicalProblem::step(const Eigen::VectorXd& dx, double factor) {
  for (int i = 0; i < system_.num_dofs(); ++i)
    if (system_.equation(i) >= 0) u_(i) += factor * dx(system_.equation(i));
}

void MechanicalProblem::describe(IterationRecord& rec) {
  rec.active_contacts = active_contacts_;
  // The active set's changes since the previous kept residual (nodes entering plus leaving).
  if (previous_set_.size() == active_set_.size())
    for (std::size_t i = 0; i < active_set_.size(); ++i) rec.active_changes += active_set_[i] != previous_set_[i];
  nodes_entered_ = entering_contact() > 0;
  previous_set_.swap(active_set_);
}

int MechanicalProblem::entering_contact() const {
  int entering = 0;
  if (previous_set_.size() == active_set_.size())
    for (std::size_t i = 0; i < active_set_.size(); ++i) entering += active_set_[i] && !previous_set_[i];
  return entering;
}

}  // namespace tunica
