#include "solver/analysis.hpp"

#include "assembly/pressure_load_checks.hpp"
#include "solver/contact_chatter.hpp"
#include "solver/failure_hints.hpp"
#include "solver/shell_fold_hint.hpp"
#include "solver/forward_solve_counter.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace tunica {

namespace {

/// Some contact pair carries the smoothing the analysis switched on (Checkpoint::contact_smoothing).
bool any_smoothing(const std::vector<double>& widths) {
  return std::any_of(widths.begin(), widths.end(), [](double d) { return d > 0; });
}

}  // namespace

Analysis::Analysis(const Model& model)
    : deck_model_(model), model_(&model), system_(std::make_unique<System>(model)) {
  state_.u.setZero(model.num_dofs());
  state_.loads.boundary.assign(model.boundaries.size(), 0.0);
  state_.loads.pressure.assign(model.loads.size(), 0.0);
  update_volumes();
  reference_volume_ = state_.loads.volume;
  state_.step_start = state_.loads;
  reactions_.setZero(model.num_dofs());
  for (int l = 0; l < static_cast<int>(model.loads.size()); ++l)
    orientation_volume_.push_back(volume_sign_is_orientation(model, l));
}

Analysis::~Analysis() = default;

void Analysis::adopt_reference(const Eigen::VectorXd& shift, int forward_of, int iteration) {
  if (shift.size() != deck_model_.num_dofs())
    throw std::invalid_argument(fmt::format("a reference shift of {} values for a model of {} DOFs", shift.size(),
                                            deck_model_.num_dofs()));
  // The element blocks keep reference data of their own (System), so the system is rebuilt on
  // the new reference rather than the positions moved under it.
  auto m = std::make_unique<Model>(deck_model_);
  for (int n = 0; n < m->num_nodes(); ++n)
    for (int d = 0; d < m->dofs_per_node(); ++d) m->X[n](d) += shift(m->node_dof(n, d));
  // A part whose `thickness` is the imaged one, h: its reference thickness at each Gauss point is
  // the inverse step's H = h λ₁λ₂ at X = x̂ + shift (13.12), which the forward elements on X read
  // (13.14). The Gauss-point states of the inverse problem give it, in System::points order.
  int inverse_step = -1;
  for (int s = 0; s < static_cast<int>(deck_model_.steps.size()); ++s)
    if (deck_model_.steps[s].moves_reference()) inverse_step = s;
  std::unique_ptr<System> deck_system;
  for (int p = 0; p < static_cast<int>(m->parts.size()); ++p) {
    if (!m->parts[p].imaged_thickness || inverse_step < 0) continue;
    if (model_ != &deck_model_ && !deck_system) deck_system = std::make_unique<System>(deck_model_);
    const System& on_deck = deck_system ? *deck_system : *system_;
    std::vector<double>& H = m->parts[p].point_thickness;
    H.clear();
    for (const MembranePoint& q : on_deck.points(shift, p, inverse_step)) H.push_back(q.reference_thickness);
  }
  if (forward_of >= 0) {
    // The forward problem of the fixed point (13.15): the loads to their imaged values, a prescribed
    // value v of the inverse step (X = x̂ + v) to the displacement x̂ − X = −v.
    Step& step = m->steps[forward_of];
    step.inverse = false;
    step.name = fmt::format("{} (fixed-point iteration {})", step.name, iteration);
    for (const Boundary& b : m->boundaries)
      if (auto it = step.targets.find(b.name); it != step.targets.end()) it->second = -it->second;
  }
  install_model(std::move(m));
}

void Analysis::install_model(std::unique_ptr<Model> m) {
  system_.reset();
  // The smoothing the analysis switched on (Checkpoint::contact_smoothing) holds on every model it
  // installs: the deck's gets a copy that carries it.
  const std::vector<double>& smooth = state_.contact_smoothing;
  if (!m && any_smoothing(smooth)) m = std::make_unique<Model>(deck_model_);
  if (m)
    for (std::size_t c = 0; c < smooth.size() && c < m->contacts.size(); ++c)
      if (smooth[c] > 0) m->contacts[c].law.smoothing = smooth[c];
  own_model_ = std::move(m);
  model_ = own_model_ ? own_model_.get() : &deck_model_;
  system_ = std::make_unique<System>(*model_);
  orientation_volume_.clear();
  reference_volume_.clear();
  for (int l = 0; l < static_cast<int>(model_->loads.size()); ++l) {
    orientation_volume_.push_back(volume_sign_is_orientation(*model_, l));
    reference_volume_.push_back(system_->volume(Eigen::VectorXd::Zero(model_->num_dofs()), l));
  }
}

void Analysis::leave_inverse_step() {
  // The inverse step's unknowns are the reference's shift from the imaged positions, X = x̂ + u
  // (13.1). On the reference X the imaged state x̂ is the displacement x̂ − X = −u, in equilibrium
  // with the loads at their imaged values, which the next step starts from (13.10).
  state_.reference_shift = state_.u;
  adopt_reference(state_.reference_shift);
  state_.u = -state_.reference_shift;
  // A prescribed value b of the inverse step held X = x̂ + b: the same DOF has the displacement −b
  // on the new reference, and later steps ramp it from there.
  for (double& b : state_.loads.boundary) b = -b;
  // The loads are the next step's starting values: the forward problem's (System::inverse).
  state_.loads.step = state_.step + 1;
  update_volumes();
  update_reactions();
}


void Analysis::run_fixed_point_step(AnalysisObserver& observer) {
  // Resumed from the checkpoint at the step's end: X is in state_.u already.
  if (state_.fraction >= 1.0 - 1e-12) return;
  const int s = state_.step;
  const Step& step = deck_model_.steps[s];
  const Step::FixedPoint& fp = step.fixed_point;
  const Checkpoint start = state_;
  const Model& deck = deck_model_;
  // The end of the step as the direct method reaches it: the loads at their imaged values, a
  // prescribed value v holding X = x̂ + v (13.1).
  LoadState end = start.step_start;
  end.step = s;
  for (std::size_t k = 0; k < deck.boundaries.size(); ++k)
    if (auto it = step.targets.find(deck.boundaries[k].name); it != step.targets.end()) end.boundary[k] = it->second;
  for (std::size_t k = 0; k < deck.loads.size(); ++k)
    if (auto it = step.targets.find(deck.loads[k].name); it != step.targets.end()) end.pressure[k] = it->second;
  // The model's size: the diagonal of the imaged bounding box.
  const double diagonal = imaged_diagonal();
  const double goal = fp.tolerance * diagonal;
  const int dim = deck.dofs_per_node(), nodes = deck.num_nodes();
  const auto back_to_deck = [&] { install_model(nullptr); };
  // X_0 = x̂ (shift 0); X_k = x̂ + shift.
  Eigen::VectorXd shift = Eigen::VectorXd::Zero(deck.num_dofs()), previous;
  double omega = fp.relaxation, max_distance = 0;
  std::vector<double> distances;  // max_n |r_n| of each iteration
  for (int k = 1;; ++k) {
    const auto t0 = std::chrono::steady_clock::now();
    try {
      adopt_reference(shift, s, k);
    } catch (const std::domain_error& e) {
      // The update (13.16) folded an element of the reference: the run stops as a failed solve does.
      back_to_deck();
      state_ = start;
      throw SolveError(fmt::format(
          "step {} '{}', fixed-point iteration {}: the reference the update (13.16) gave is inadmissible ({}). A "
          "`relaxation` below 1 (now {:g}{}) keeps the updates shorter",
          s + 1, deck.steps[s].name, k, e.what(), fp.relaxation,
          fp.aitken ? fmt::format(", and the last Aitken factor was {:g}", omega) : std::string()));
    }
    state_ = start;
    state_.u.setZero(model_->num_dofs());
    state_.loads = start.step_start;
    state_.loads.step = state_.step_start.step = s;
    update_volumes();
    state_.step_start.volume = state_.loads.volume;
    ForwardSolveCounter counter(observer);
    try {
      run_step(counter);
    } catch (const SolveError& e) {
      // The message names the iteration (the copy's step name, adopt_reference); the state is the
      // step's start again, on the deck's model.
      back_to_deck();
      state_ = start;
      // The forward solve's increments are the fixed point's trial, never the run's: none is kept.
      std::string inner = e.what();
      if (const std::string kept = "Results of the converged increments are kept.";
          inner.find(kept) != std::string::npos)
        inner.replace(inner.find(kept), kept.size(),
                      "The forward solve's increments are discarded; the files of the run before the step are kept.");
      if (k == 1)
        throw SolveError(inner +
                         " The first forward solve of the fixed point takes the imaged geometry itself as the reference "
                         "(X₀ = x̂, theory manual §13.1), which must carry the imaged loads: a shape imaged near a load "
                         "maximum (a neo-Hookean sphere near its pressure maximum) cannot, and `method: direct` takes "
                         "no such detour");
      // Past the first iteration the forward solve starts from a reference the update (13.16) gave: the
      // hints of a solve from a deck's own reference do not apply, the course of the distance does.
      std::string what = inner;
      if (const auto h = what.find(" Hint:"); h != std::string::npos) what.erase(h);
      const auto smallest = std::min_element(distances.begin(), distances.end());
      const std::string unit = deck.units.display_unit(Dimension::length);
      const auto len = [&](double v) { return deck.units.from_internal(v, unit, Dimension::length); };
      const bool growing = distances.size() >= 2 && distances.back() > distances[distances.size() - 2] &&
                           distances.back() > 2 * *smallest;
      throw SolveError(fmt::format(
          "{} The forward solve of fixed-point iteration {} starts from the reference the update (13.16) gave. The "
          "largest distance from the imaged positions was {:.4g} {} after iteration 1, {:.4g} {} at its smallest "
          "(iteration {}) and {:.4g} {} after iteration {}{}. Hint: {} keeps the updates shorter; an imaged mesh that is no equilibrium shape of the discrete membrane (a surface laid on "
          "an ideal or segmented shape) has no exact fixed point, and `method: prestress` (theory manual §13.2), "
          "which keeps the imaged geometry as the reference, converges on such meshes (its mean stress is right, its "
          "peak can be off: user guide §3.5)",
          what, k, len(distances.front()), unit, len(*smallest), unit, smallest - distances.begin() + 1,
          len(distances.back()), unit, k - 1, growing ? ": the iteration was diverging" : "",
          fp.aitken ? fmt::format("`acceleration: none` with a `relaxation` below 1 (Aitken's last factor was {:.3g})",
                                  omega)
                    : fmt::format("a `relaxation` below 1 (now {:g}) or `acceleration: aitken`", fp.relaxation)));
    } catch (...) {
      back_to_deck();
      state_ = start;
      throw;
    }
    // r_k = x(X_k) − x̂ = (X_k + u) − x̂ = shift + u, the fixed point's residual (13.15).
    const Eigen::VectorXd r = shift + state_.u;
    double sum = 0;
    max_distance = 0;
    for (int n = 0; n < nodes; ++n) {
      double d2 = 0;
      for (int c = 0; c < dim; ++c) d2 += r(deck.node_dof(n, c)) * r(deck.node_dof(n, c));
      sum += d2;
      max_distance = std::max(max_distance, std::sqrt(d2));
    }
    const bool converged = max_distance <= goal;
    distances.push_back(max_distance);
    // Aitken's Δ² on the relaxation (13.17), from the second iteration on.
    if (!converged && fp.aitken && previous.size() > 0) {
      const Eigen::VectorXd dr = r - previous;
      const double dd = dr.squaredNorm();
      // Kept above 0.05: a factor at or below 0 stalls or reverses the update (slow modes may ask for
      // factors well above 1, which Aitken's estimate gives them).
      if (dd > 0) omega = std::max(-omega * previous.dot(dr) / dd, 0.05);
    }
    FixedPointRecord rec;
    rec.step = s + 1;
    rec.step_name = step.name;
    rec.iteration = k;
    rec.max_distance = max_distance;
    rec.rms_distance = std::sqrt(sum / nodes);
    rec.goal = goal;
    rec.relaxation = converged ? 0 : omega;
    rec.increments = counter.increments;
    rec.newton_iterations = counter.newton_iterations;
    rec.cutbacks = counter.cutbacks;
    rec.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    observer.on_fixed_point(rec);
    if (converged) break;
    if (k >= fp.max_iterations) {
      back_to_deck();
      state_ = start;
      const std::string unit = deck.units.display_unit(Dimension::length);
      const auto len = [&](double v) { return deck.units.from_internal(v, unit, Dimension::length); };
      throw SolveError(fmt::format(
          "step {} '{}' (inverse, method: fixed_point): after {} iteration(s) (fixed_point_iterations), the forward "
          "solution from the last reference is still {:.4g} {} from the imaged positions at its farthest node "
          "({:.4g} {} root mean square), above the tolerance {:.4g} {} (fixed_point_tolerance {:g} × the imaged "
          "bounding-box diagonal {:.6g} {}). The files of the run so far are kept; fixed_point.csv lists the distance "
          "per iteration. If it is still falling, raise `fixed_point_iterations`{}; if it stagnates, the imaged shape may not be an equilibrium shape "
          "of the discrete membrane (theory manual §13), and a larger `fixed_point_tolerance` accepts the "
          "nearest reference found, or `method: prestress` (§13.2) reaches the imaged geometry itself (user guide "
          "§3.5 on its peak stresses)",
          s + 1, step.name, k, len(max_distance), unit, len(rec.rms_distance), unit, len(goal), unit, fp.tolerance,
          len(diagonal), unit,
          fp.aitken ? " (Aitken's acceleration is on; if it oscillates, `acceleration: none` with a `relaxation` below 1)"
                    : " or try `acceleration: aitken` (or a `relaxation` below 1 if it oscillates)"));
    }
    previous = r;
    // X_{k+1} = X_k − ω_k r_k (13.16); a prescribed DOF keeps X = x̂ + v exactly.
    shift -= omega * r;
    system_->apply_boundary(end, shift);
  }
  // The state the direct method ends in: u = X − x̂ on the deck's positions, at the step's loads.
  back_to_deck();
  state_ = start;
  state_.u = shift;
  end_iterative_step(observer, end, 0);
}

void Analysis::end_iterative_step(AnalysisObserver& observer, const LoadState& end, int iterations) {
  state_.loads = end;
  update_volumes();
  state_.trace.restart_at(state_.step_start);
  state_.trace.push(state_.loads);
  state_.fraction = 1;
  state_.increment = 1;
  update_reactions();
  IncrementInfo info;
  info.step = state_.step + 1;
  info.step_name = deck_model_.steps[state_.step].name;
  info.increment = 1;
  info.fraction = 1;
  info.time = static_cast<double>(state_.step) + 1;
  info.iterations = iterations;
  observer.on_increment(*this, info);
}

double Analysis::imaged_diagonal() const {
  Eigen::Vector3d lo = deck_model_.X.front(), hi = deck_model_.X.front();
  for (const auto& x : deck_model_.X) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  return (hi - lo).norm();
}

std::string Analysis::eversion(const Eigen::VectorXd& u, int& load) const {
  for (int l = 0; l < static_cast<int>(model_->loads.size()); ++l) {
    if (!orientation_volume_[l] || l >= static_cast<int>(state_.loads.volume.size())) continue;
    const double before = state_.loads.volume[l], now = system_->volume(u, l);
    if (!(before * now < 0)) continue;
    load = l;
    const PressureLoad& p = model_->loads[l];
    const std::string unit = model_->units.display_unit(Dimension::volume);
    return fmt::format(
        "the converged state is inadmissible: the enclosed volume of load '{}' changed sign, from {:.4g} {} to {:.4g} {}, "
        "so part '{}' passed through itself (or through its mirror image at a symmetry plane) and is turned inside "
        "out, a state its strains cannot tell from the right one",
        p.name, before, unit, now, unit, model_->parts[p.part].name);
  }
  return "";
}

void Analysis::update_volumes() {
  state_.loads.volume.resize(model_->loads.size());
  for (std::size_t l = 0; l < model_->loads.size(); ++l)
    state_.loads.volume[l] = system_->volume(state_.u, static_cast<int>(l));
}

void Analysis::update_reactions() {
  Eigen::VectorXd R;
  system_->assemble(state_.u, state_.loads, R, nullptr);
  reactions_.setZero(model_->num_dofs());
  for (int d : system_->prescribed_dofs()) reactions_(d) = R(d);
}

void Analysis::run(AnalysisObserver& observer, const Checkpoint* resume) {
  if (resume) {
    state_ = *resume;
    // Past an inverse step: the reference it computed, or the prestress (the restart file records them).
    if (state_.reference_shift.size() > 0) adopt_reference(state_.reference_shift);
    if (!state_.prestress.empty()) adopt_prestress(state_.prestress);
    // The contact smoothing the run switched on before the restart file was written.
    if (state_.reference_shift.size() == 0 && state_.prestress.empty() && any_smoothing(state_.contact_smoothing))
      install_model(nullptr);
    // Which parts are active follows from the step (restart files do not store it).
    state_.loads.step = state_.step_start.step = state_.step;
    update_reactions();
  } else {
    update_reactions();
    observer.on_increment(*this, IncrementInfo{});
  }
  for (; state_.step < static_cast<int>(model_->steps.size()); ++state_.step) {
    const Step& step = model_->steps[state_.step];
    if (step.inverse && step.inverse_method == Step::InverseMethod::fixed_point)
      run_fixed_point_step(observer);
    else if (step.inverse && step.inverse_method == Step::InverseMethod::prestress)
      run_prestress_step(observer);
    else
      run_step(observer);
    // An inverse step that is the last step keeps its own state (u = X − x̂ on the deck's positions);
    // a prestress step's state is already one of the steps after it (on the prestressed copy).
    if (deck_model_.steps[state_.step].moves_reference() && state_.step + 1 < static_cast<int>(model_->steps.size()))
      leave_inverse_step();
    state_.step_start = state_.loads;
    state_.fraction = 0;
    state_.dt = 0;
    state_.increment = 0;
    state_.reduced_successes = 0;
    state_.trace = StepTrace();
  }
}

std::string Analysis::contact_hints(const NewtonResult& last, int step) const {
  // A slave coarser than its master where they touch is the more specific cause; else what the
  // failed attempt's active set did (failure_hints.hpp).
  const std::string coarse = contact_resolution_hints(*system_, state_.u, step);
  return coarse.empty() ? contact_convergence_hint(*system_, state_.u, model_->steps[step], step, last) : coarse;
}

std::string Analysis::smoothing_retry_text(const std::vector<int>& pairs) const {
  const Model& m = *model_;
  const std::string lu = m.units.display_unit(Dimension::length);
  std::string named;
  for (std::size_t k = 0; k < pairs.size(); ++k)
    named += fmt::format("{}`smoothing: {:.2g} {}` on pair '{}'", k == 0 ? "" : k + 1 == pairs.size() ? " and " : ", ",
                         m.units.from_internal(auto_smoothing_width(m, pairs[k]), lu, Dimension::length), lu,
                         m.contacts[pairs[k]].name);
  return fmt::format(
      "the contact active set chattered: retrying the increment from its first size with {} (10⁻³ of the slave's "
      "element length, theory manual (9.2)) for the rest of the run; `smoothing: 0` on the pair keeps the plain law",
      named);
}

void Analysis::smooth_contacts(const std::vector<int>& pairs) {
  const Model& m = *model_;
  state_.contact_smoothing.resize(m.contacts.size(), 0.0);
  for (int c : pairs) {
    state_.contact_smoothing[c] = auto_smoothing_width(m, c);
    if (const int r = m.contacts[c].reverse; r >= 0) state_.contact_smoothing[r] = auto_smoothing_width(m, r);
  }
  install_model(own_model_ ? std::make_unique<Model>(*own_model_) : nullptr);
}

void Analysis::run_step(AnalysisObserver& observer) {
  std::vector<int> smooth;
  while (!run_increments(observer, smooth)) smooth_contacts(smooth);
}

bool Analysis::run_increments(AnalysisObserver& observer, std::vector<int>& smooth) {
  const int s = state_.step;
  const Step& step = model_->steps[s];
  // Each amplitude ramps from its value at the start of the step to the step's target.
  const LoadState start = state_.step_start;
  LoadState end = start;
  for (std::size_t k = 0; k < model_->boundaries.size(); ++k)
    if (auto it = step.targets.find(model_->boundaries[k].name); it != step.targets.end()) end.boundary[k] = it->second;
  for (std::size_t k = 0; k < model_->loads.size(); ++k)
    if (auto it = step.targets.find(model_->loads[k].name); it != step.targets.end()) end.pressure[k] = it->second;
  const auto at = [&](double t) {
    LoadState l = start;
    l.step = s;
    for (std::size_t k = 0; k < l.boundary.size(); ++k) l.boundary[k] += t * (end.boundary[k] - start.boundary[k]);
    for (std::size_t k = 0; k < l.pressure.size(); ++k) l.pressure[k] += t * (end.pressure[k] - start.pressure[k]);
    return l;
  };
  // Volume control: the load's pressure is an unknown (starting from the last converged value)
  // and the enclosed volume is ramped from its value at the start of the step to the target.
  const VolumeControl& vc = step.volume_control;
  const auto volume_at = [&](double t) {
    return start.volume[vc.load] + t * (vc.target - start.volume[vc.load]);
  };

  auto solver = solver_factory_(step.solver.linear_solver);
  // The hints of a failure (failure_hints.hpp) read the step's converged states, kept in the
  // checkpoint: a step resumed from a restart file continues its trace (an older file has none).
  if (state_.trace.count() == 0) state_.trace.restart_at(state_.loads);
  const double nominal = 1.0 / step.increments;
  double t = state_.fraction;
  double dt = state_.dt > 0 ? state_.dt : nominal;
  while (t < 1.0) {
    if (t + dt > 1.0 - 1e-9 * nominal) dt = 1.0 - t;
    // From the stress-free state the stiffened first correction is the default, (7.6)–(7.8) and,
    // under volume control, (7.10);
    // an attempt it fails is retried once at the same size with the plain tangent before any
    // cut-back, so that the default is never worse than `stress_free_start: exact`.
    // The first increment of a step that raises a pressure from zero, after steps without one (a
    // prestretch alone), starts as from rest too: the wall may carry no tension across the coming
    // load (a tube stretched axially alone has no hoop tension) and ovalizes freely (user guide §3.1).
    bool pressure_from_zero = t == 0 && vc.load < 0;
    if (pressure_from_zero) {
      bool raised = false;
      for (std::size_t k = 0; k < start.pressure.size(); ++k) {
        if (start.pressure[k] != 0) pressure_from_zero = false;
        if (end.pressure[k] != 0) raised = true;
      }
      pressure_from_zero = pressure_from_zero && raised;
    }
    SolverSettings settings = step.solver;
    const bool stiffened_start =
        settings.stiffen_stress_free_start && ((state_.u.array() == 0.0).all() || pressure_from_zero);
    IncrementInfo info;
    info.step = s + 1;
    info.step_name = step.name;
    info.increment = state_.increment + 1;
    int cutbacks = 0;
    const double first_dt = dt;
    // A retry after the automatic smoothing (run_step) numbers its attempts on from the failed ones.
    for (int attempt = std::exchange(carried_attempts_, 0);; ++attempt) {
      info.attempt = attempt;
      info.fraction = t + dt;
      info.time = static_cast<double>(s) + info.fraction;
      LoadState trial = at(info.fraction);
      VolumeConstraint constraint;
      if (vc.load >= 0) {
        trial.pressure[vc.load] = state_.loads.pressure[vc.load];
        constraint = {vc.load, volume_at(info.fraction)};
      }
      Eigen::VectorXd u = state_.u;
      system_->apply_boundary(trial, u);
      NewtonResult r = solve_increment(*system_, *solver, trial, u, settings,
                                    [&](const IterationRecord& rec) { observer.on_iteration(info, rec); },
                                    vc.load >= 0 ? &constraint : nullptr, &state_.u,
                                    stiffened_start && settings.stiffen_stress_free_start);
      // A converged state whose enclosed volume changed sign is rejected like any inadmissible
      // state: the increment is cut back.
      int everted_load = -1;
      if (r.converged) {
        if (std::string e = eversion(u, everted_load); !e.empty()) {
          r.converged = false;
          r.failure = std::move(e);
        }
      }
      if (r.converged) {
        state_.u = u;
        state_.loads = trial;
        update_volumes();
        state_.trace.push(state_.loads);
        info.iterations = r.iterations;
        break;
      }
      const std::string why = everted_load >= 0 ? r.failure
                                                : fmt::format("{} (last relative residual {:.3e})", r.failure,
                                                              r.last_relative_residual);
      // Only an attempt that took the stiffened start has a plain one to try: any other would repeat it.
      if (r.stiffened_start && settings.stiffen_stress_free_start) {
        settings.stiffen_stress_free_start = false;
        observer.on_retry(info, why, "retrying with the plain start (stress_free_start: exact)");
        continue;
      }
      settings.stiffen_stress_free_start = step.solver.stiffen_stress_free_start;
      // The increment may shrink to nominal / 2^max_cutbacks and no further, counting the
      // halvings carried over from earlier increments: time always advances.
      const double min_dt = nominal * std::ldexp(1.0, -step.solver.max_cutbacks);
      if (cutbacks >= step.solver.max_cutbacks || 0.5 * dt < min_dt * (1 - 1e-12)) {
        // A contact front that chattered down to the smallest increment: the penalty law of the
        // pairs involved is smoothed (theory manual (9.2)) and the increment tried again from its
        // first size, once per pair and run.
        if (everted_load < 0) {
          smooth = pairs_to_smooth(*system_, state_.u, s, r);
          if (!smooth.empty()) {
            observer.on_retry(info, why, smoothing_retry_text(smooth));
            state_.dt = first_dt;
            state_.reduced_successes = 0;
            carried_attempts_ = attempt + 1;
            return false;
          }
        }
        // With `max_cutbacks: 0` nothing was cut back: the increment is the step's nominal one.
        const std::string size =
            step.solver.max_cutbacks == 0
                ? fmt::format("no convergence with the step's increment of {:.3g} of the step (`max_cutbacks: 0` in "
                              "`solver` allows no cut-back: a positive value halves a failed increment)",
                              dt)
                : fmt::format("no convergence with the increment cut back to {:.3g} of the step ({} cut-back(s) "
                              "allowed)",
                              dt, step.solver.max_cutbacks);
        // A shell bent through its thickness first: no load path or iteration count passes it.
        std::string hint = shell_fold_hint(*system_, state_.u, s, r.failure);
        if (!hint.empty()) hint = " Hint: " + hint;
        else
          hint = everted_load >= 0 ? eversion_hint(*model_, everted_load, step, s, state_.trace)
                                   : failure_hints(*model_, step, r, state_.trace, trial, reference_volume_);
        const std::string contact = contact_hints(r, s);
        // No other evidence: the last converged state's compression, theory manual (7.13).
        if (hint.empty() && contact.empty()) hint = compression_hint(*system_, state_.u, step, s, state_.trace);
        throw SolveError(fmt::format(
            "step {} '{}', increment {} (step fraction {:.9g} + {:.3g}): {}; {}. Results of the converged increments "
            "are kept.{}",
            info.step, step.name, info.increment, t, dt, why, size, hint + contact));
      }
      observer.on_cutback(info, why);
      ++cutbacks;
      dt *= 0.5;
      state_.reduced_successes = 0;
    }
    t = info.fraction;
    ++state_.increment;
    if (dt < nominal * (1 - 1e-12) && ++state_.reduced_successes >= 2) {
      dt = std::min(2.0 * dt, nominal);
      state_.reduced_successes = 0;
    }
    state_.fraction = t;
    state_.dt = dt;
    update_reactions();
    observer.on_increment(*this, info);
    if (observer.stop_requested())
      throw Interrupted(fmt::format("stopped on request after step {} '{}', increment {} (step fraction {:.9g})",
                                    info.step, step.name, info.increment, t));
  }
  return true;
}

}  // namespace tunica
