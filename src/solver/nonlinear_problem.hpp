#pragma once
// What Newton's method sees of a problem (theory manual §7): a state it can move, the residual
// there, its Jacobian, whether the state is admissible, and a diagnostics record. What a
// particular problem adds — the free-DOF numbering, the contact active set, the volume
// constraint's border, the stiffened first correction, the symmetrized tangent, the tangent
// predictor — lives in the problem (solver/mechanical_problem.hpp, solver/bordered_problem.hpp,
// solver/tangent_hooks.hpp, solver/tangent_predictor.hpp), never in solver/newton.cpp.
#include <Eigen/Core>

#include "linalg/tangent_matrix.hpp"

namespace tunica {

struct IterationRecord;

class NonlinearProblem {
public:
  virtual ~NonlinearProblem() = default;

  /// The number of unknowns of a correction (rows of the Jacobian).
  virtual int size() const = 0;

  /// Evaluates the residual r (size()) and the Jacobian at the current state and returns the
  /// force scale of r (the forces that cancel in it; ‖r‖ at a small multiple of it is round-off).
  /// Throws std::domain_error, whose message says where, when the state is not admissible
  /// (an inverted element, a non-positive thickness).
  virtual double evaluate(Eigen::VectorXd& r) = 0;

  /// The norm of r that the tolerances test, (7.2): of the equilibrium equations only.
  virtual double residual_norm(const Eigen::VectorXd& r) const { return r.norm(); }

  /// dx · r: the work of the residual along a correction, (7.2) and the line search (7.4).
  virtual double work(const Eigen::VectorXd& dx, const Eigen::VectorXd& r) const { return dx.dot(r); }

  /// Whether the equations besides equilibrium (a volume constraint) hold to `tolerance`.
  virtual bool side_conditions_hold(double /*tolerance*/) const { return true; }

  /// The matrix the correction of iteration `iteration` is solved with: the Jacobian of the last
  /// evaluate() with the problem's tangent modifications (solver/tangent_hooks.hpp) applied.
  virtual const TangentMatrix& jacobian(int iteration) = 0;

  /// Moves the state by factor · dx (dx of size()).
  virtual void step(const Eigen::VectorXd& dx, double factor) = 0;

  /// After the evaluation Newton keeps (the last of a line search): fills the problem's own
  /// columns of the record (active contact nodes and their changes).
  virtual void describe(IterationRecord& /*rec*/) {}

  /// The largest credible component of a correction; a larger one comes from a near-singular
  /// tangent (solver/perturbed_solve.hpp).
  virtual double max_correction() const = 0;

  /// Slave nodes in contact at the latest evaluation that were not at the last kept one (nodes
  /// entering contact); 0 for a problem without contact.
  virtual int entering_contact() const { return 0; }

  /// False when a correction must be taken whole: no line search (7.4).
  virtual bool allows_backtracking() const { return true; }
  /// False when a singular Jacobian must not be solved with a perturbed diagonal.
  virtual bool allows_perturbation() const { return true; }
  /// False when a correction must not be solved with the factorization of an earlier iteration's
  /// Jacobian (modified Newton, (7.5)): where the matrix factorized is not the Jacobian alone.
  virtual bool allows_factorization_reuse() const { return false; }
  /// True when R₀ says nothing of the scale of the problem (the volume constraint's start, where
  /// only the target moved): the first corrected residual is the yardstick of the tolerances too.
  virtual bool yardstick_after_first_correction() const { return false; }
};

}  // namespace tunica
