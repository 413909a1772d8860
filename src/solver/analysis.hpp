#pragma once
// Steps and increments: each step ramps its boundary and load targets
// linearly; each increment is solved by Newton. An increment that does not
// converge is halved and retried (at most `max_cutbacks` times in a row; from the
// stress-free state a failed stiffened start is first retried with the plain one), and
// the increment size grows back after two converged reduced increments.
// The whole progress state is a Checkpoint, so that a run can be resumed
// exactly where a converged increment left it.
//
// After an inverse step (Step::inverse, the first step; theory manual §13, (13.10)) the model's
// reference becomes the computed zero-pressure geometry X = x̂ + u and the state the displacement
// x̂ − X from it, at the inverse step's loads: the steps after it are ordinary forward steps on the
// new reference (Analysis::model() is then a copy of the deck's model with the new X, and
// system() is built on it). The checkpoint records the shift X − x̂ (Checkpoint::reference_shift),
// so that a run resumed past the inverse step continues on the same reference. An inverse step
// that is the deck's last step keeps its own state (u = X − x̂ on the deck's positions).
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "assembly/system.hpp"
#include "solver/increment.hpp"
#include "solver/step_trace.hpp"

namespace tunica {

struct IncrementInfo {
  int step = 0;            ///< 1-based
  std::string step_name;
  int increment = 0;       ///< 1-based converged increment within the step
  int attempt = 0;         ///< 0 for the first try of this increment, +1 per cut-back or retry
  double fraction = 0;     ///< fraction of the step done at the end of the increment
  double time = 0;         ///< step − 1 + fraction
  int iterations = 0;      ///< Newton iterations of the converged attempt
};

/// Everything needed to continue a run after a converged increment.
struct Checkpoint {
  int step = 0;              ///< 0-based index of the step in progress
  double fraction = 0;       ///< fraction of that step done
  double dt = 0;             ///< size of the next increment (0: the step's nominal size)
  int increment = 0;         ///< converged increments in the step so far
  int reduced_successes = 0; ///< converged increments since the last cut-back
  LoadState step_start;      ///< amplitudes at the start of the step
  LoadState loads;           ///< current amplitudes
  Eigen::VectorXd u;         ///< current displacements
  StepTrace trace;           ///< the step's converged states that the hints of a failure read
  /// After an inverse step: the shift of the reference it computed, X − x̂ (all DOFs; x̂ the deck's
  /// positions), which the model's reference has taken on (Analysis::model()); empty before.
  Eigen::VectorXd reference_shift;
  /// After a prestress step (Step::InverseMethod::prestress, theory manual §13.2): per membrane
  /// Gauss point of every part (parts in order, each in System::points order) its prestretch P
  /// (P₁₁, P₂₁, P₁₂, P₂₂) and stress-free thickness H̃, which the model's parts have taken on
  /// (Analysis::model()); empty before.
  std::vector<double> prestress;
  /// Per Model::contacts entry, the smoothing width δ the analysis switched on for it after an
  /// increment failed with a chattering active set (theory manual (9.2)), which the model's pairs
  /// have taken on (Analysis::model()); 0: the deck's law. Empty: none switched on.
  std::vector<double> contact_smoothing;
};

class Analysis;

/// One iteration of a fixed-point inverse step (Step::InverseMethod::fixed_point; theory manual
/// §13.1): the forward solve from the reference X_{k−1} to the imaged loads and its distance from x̂.
struct FixedPointRecord {
  int step = 0;                ///< 1-based
  std::string step_name;
  int iteration = 0;           ///< 1-based: the forward solve from X_{iteration−1}
  double max_distance = 0;     ///< max over the nodes of |x(X_{k−1}) − x̂| (model length, internal units)
  double rms_distance = 0;     ///< its root mean square over the nodes
  double goal = 0;             ///< the distance that stops the iteration: tolerance × bounding-box diagonal
  double relaxation = 0;       ///< ω_k applied after this iteration, (13.16)–(13.17)
  int increments = 0;          ///< converged forward increments of the solve
  int newton_iterations = 0;   ///< Newton iterations of its converged increments
  int cutbacks = 0;            ///< its cut-backs
  double seconds = 0;          ///< wall-clock time of the solve
};

/// What a run reports to (output writers, progress, tests).
class AnalysisObserver {
public:
  virtual ~AnalysisObserver() = default;
  virtual void on_iteration(const IncrementInfo&, const IterationRecord&) {}
  virtual void on_cutback(const IncrementInfo&, const std::string& /*why*/) {}
  /// A failed attempt retried at the same size another way (`how`).
  virtual void on_retry(const IncrementInfo&, const std::string& /*why*/, const std::string& /*how*/) {}
  /// After each converged increment, and once for the reference state (step 0).
  virtual void on_increment(const Analysis&, const IncrementInfo&) {}
  /// Asked after each converged increment: true stops the run (Interrupted).
  virtual bool stop_requested() { return false; }
  /// After each iteration of a fixed-point inverse step (the forward increments inside it report
  /// their Newton iterations, cut-backs and retries, but not on_increment: the step's one converged
  /// state is reported at its end, as the direct method's last increment).
  virtual void on_fixed_point(const FixedPointRecord&) {}
};

/// The run stopped on request (a signal) after a converged increment.
class Interrupted : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

class Analysis {
public:
  explicit Analysis(const Model& model);
  ~Analysis();
  /// Runs every step, from the reference state or from `resume`. Throws SolveError
  /// when an increment cannot converge and Interrupted when the observer asks to
  /// stop; every converged increment has been reported before.
  void run(AnalysisObserver& observer, const Checkpoint* resume = nullptr);

  /// The model the state refers to: the deck's, or after an inverse step its copy with the
  /// reference that step computed (Checkpoint::reference_shift).
  const Model& model() const { return *model_; }
  const System& system() const { return *system_; }
  const Eigen::VectorXd& displacement() const { return state_.u; }
  const LoadState& loads() const { return state_.loads; }
  /// Reaction forces: R = f_int − f_ext at prescribed DOFs (0 elsewhere), at the last converged state.
  const Eigen::VectorXd& reactions() const { return reactions_; }
  /// The progress state after the last converged increment.
  const Checkpoint& checkpoint() const { return state_; }
  /// Makes each step's linear solver from its `linear_solver` name (default make_linear_solver;
  /// tunica-bench wraps it to time a bare factorization next to each of the run's).
  using SolverFactory = std::function<std::unique_ptr<LinearSolver>(const std::string&)>;
  void set_solver_factory(SolverFactory factory) { solver_factory_ = std::move(factory); }

private:
  void update_reactions();
  /// Enclosed volumes of every load's surface at the current state (LoadState::volume).
  void update_volumes();
  /// Solves step `state_.step` from `state_.fraction` to its end (run_increments, switching on the
  /// automatic contact smoothing where it asks for it).
  void run_step(AnalysisObserver& observer);
  /// Empty, or why the converged state u is inadmissible: the enclosed volume of a load whose
  /// volume's sign is its surface's orientation (assembly/pressure_load_checks.hpp,
  /// volume_sign_is_orientation) has the other sign than at the last converged state, so the
  /// surface passed through itself. `load` receives that load.
  std::string eversion(const Eigen::VectorXd& u, int& load) const;
  /// The contact hints of a stopped increment (solver/failure_hints.hpp) at the last converged state:
  /// a slave coarser than its master, else what the failed attempt `last`'s active set did.
  std::string contact_hints(const NewtonResult& last, int step) const;
  /// Makes the model's reference the deck's positions shifted by `shift` (X = x̂ + shift, all DOFs):
  /// model() becomes a copy of the deck's model with that X and system() is rebuilt on it.
  /// `forward_of` ≥ 0: that inverse step of the copy becomes the forward problem of its fixed point
  /// (13.15): a forward step ramping the loads to their imaged values and each prescribed value v
  /// to the displacement −v, named after the fixed-point iteration `iteration`.
  void adopt_reference(const Eigen::VectorXd& shift, int forward_of = -1, int iteration = 0);
  /// Inverse step `state_.step` by the fixed point of theory manual §13.1: forward solves from
  /// X_k (run_step on the copy of adopt_reference) and X_{k+1} = X_k − ω_k (x(X_k) − x̂), (13.16);
  /// ends in the state the direct method ends in (u = X − x̂ on the deck's model, the step's loads).
  void run_fixed_point_step(AnalysisObserver& observer);
  /// Inverse step `state_.step` by the prestress method of theory manual §13.2: the imaged geometry
  /// stays the reference; forward solves from it (run_step on the copy of adopt_prestress) ramp the
  /// loads in the step's `increments` and then hold them, each followed by the update (13.21) of the
  /// prestretch, until a solve moves no node farther than the tolerance (13.24). Ends at the imaged
  /// loads on that copy, with the last solve's displacements.
  void run_prestress_step(AnalysisObserver& observer);
  /// Makes model() a copy of the deck's model whose membrane parts carry the prestretch and
  /// stress-free thickness `prestress` (Checkpoint::prestress layout) and rebuilds system() on it.
  /// `forward_of` ≥ 0: that prestress step of the copy becomes a forward step of one increment from
  /// the current loads to `to`, named after prestress iteration `iteration`.
  void adopt_prestress(const std::vector<double>& prestress, int forward_of = -1, int iteration = 0,
                       const LoadState* to = nullptr);
  /// The end of an iterative inverse step (fixed point, prestress) at state_.u: the loads `end`, the
  /// step done in one increment of `iterations` Newton iterations, reported to `observer`.
  void end_iterative_step(AnalysisObserver& observer, const LoadState& end, int iterations);
  /// The diagonal of the bounding box of the deck's (imaged) positions: the model's size.
  double imaged_diagonal() const;
  /// Solves step `state_.step` from `state_.fraction` on. Returns false, with the pairs in `smooth`,
  /// when an increment failed at its smallest size with a chattering active set on pairs that
  /// take the automatic smoothing (solver/contact_chatter.hpp): the state is the last converged
  /// one, with the failed increment's first size as the next (Checkpoint::dt).
  bool run_increments(AnalysisObserver& observer, std::vector<int>& smooth);
  /// What the progress log says of switching on the automatic smoothing of `pairs`.
  std::string smoothing_retry_text(const std::vector<int>& pairs) const;
  /// Switches on the automatic smoothing (theory manual (9.2)) of contact pairs `pairs` (and their
  /// reverse passes): records it in Checkpoint::contact_smoothing and rebuilds model() and system()
  /// with it.
  void smooth_contacts(const std::vector<int>& pairs);
  /// Makes `m` the model (model() and a system() built on it) with the volumes that go with it; the
  /// smoothing of Checkpoint::contact_smoothing on it (on a copy of the deck's model for nullptr).
  void install_model(std::unique_ptr<Model> m);
  /// The end of inverse step `s`: the reference becomes the computed X (adopt_reference), the
  /// state u = x̂ − X and the prescribed values the same displacements on the new reference,
  /// at the step's loads (theory manual (13.10)).
  void leave_inverse_step();

  const Model& deck_model_;
  const Model* model_;            ///< deck_model_, or own_model_ after an inverse step
  std::unique_ptr<Model> own_model_;
  std::unique_ptr<System> system_;
  Checkpoint state_;
  Eigen::VectorXd reactions_;
  std::vector<char> orientation_volume_;  ///< per load: volume_sign_is_orientation
  std::vector<double> reference_volume_;  ///< per load: its enclosed volume at the stress-free reference
  SolverFactory solver_factory_ = make_linear_solver;
  /// The attempts of an increment that run_increments gave up for the automatic smoothing: its
  /// retry's attempts count on from them (newton.csv's attempt column stays unique).
  int carried_attempts_ = 0;
};

}  // namespace tunica
