// The prestress method of an inverse step (Step::InverseMethod::prestress, theory manual §13.2):
// the imaged geometry stays the reference and each membrane Gauss point carries a prestretch P
// (Part::point_prestretch) and a stress-free thickness H̃ (Part::point_thickness), updated after
// each forward solve, (13.20)–(13.24).
#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "contributions/element_type.hpp"
#include "solver/analysis.hpp"
#include "solver/forward_solve_counter.hpp"

namespace tunica {

namespace {

constexpr int kPerPoint = 5;  // P₁₁, P₂₁, P₁₂, P₂₂, H̃ (Checkpoint::prestress)

/// The membrane Gauss points of a part, in System::points order.
std::size_t points_of(const Part& part) {
  std::size_t n = 0;
  for (const ElementBlock& b : part.blocks)
    n += static_cast<std::size_t>(b.size()) * static_cast<std::size_t>(element_type(b.kind).points_per_element(part));
  return n;
}

/// No prestretch (P = I) and the stress-free thickness H̃ = H (13.22): the part's `thickness`, or
/// with `thickness_at: imaged` the imaged thickness h, at P = I the same.
std::vector<double> initial_prestress(const Model& m) {
  std::vector<double> out;
  for (const Part& part : m.parts) {
    const std::size_t n = points_of(part);
    for (std::size_t q = 0; q < n; ++q) {
      const double H = part.imaged_point_thickness.empty() ? part.thickness : part.imaged_point_thickness.at(q);
      out.insert(out.end(), {1.0, 0.0, 0.0, 1.0, H});
    }
  }
  return out;
}

/// A^(ω/2) of a symmetric positive definite 2 × 2 matrix A: its principal square root for ω = 1.
Eigen::Matrix2d spd_power(const Eigen::Matrix2d& A, double omega) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(A);
  const Eigen::Vector2d d = eig.eigenvalues().array().pow(0.5 * omega);
  return eig.eigenvectors() * d.asDiagonal() * eig.eigenvectors().transpose();
}

}  // namespace

void Analysis::adopt_prestress(const std::vector<double>& prestress, int forward_of, int iteration,
                               const LoadState* to) {
  auto m = std::make_unique<Model>(deck_model_);
  std::size_t k = 0;
  for (Part& part : m->parts) {
    const std::size_t n = points_of(part);
    if ((k + n) * kPerPoint > prestress.size()) break;
    part.point_prestretch.resize(n);
    part.point_thickness.resize(n);
    for (std::size_t q = 0; q < n; ++q, ++k) {
      const double* v = prestress.data() + kPerPoint * k;
      part.point_prestretch[q] << v[0], v[2], v[1], v[3];
      part.point_thickness[q] = v[4];
    }
  }
  if (k * kPerPoint != prestress.size())
    throw std::invalid_argument(fmt::format("a prestress of {} values for a model of {} membrane Gauss points ({} each)",
                                            prestress.size(), k, kPerPoint));
  // The copy's prestress step is the forward problem of the iteration: its element is the forward one
  // on the prestretched reference (System::inverse is false for it in any case).
  const int s = forward_of >= 0 ? forward_of : 0;
  for (int t = 0; t < static_cast<int>(m->steps.size()); ++t)
    if (m->steps[t].inverse_method == Step::InverseMethod::prestress) m->steps[t].inverse = false;
  if (forward_of >= 0 && to) {
    Step& step = m->steps[s];
    step.name = fmt::format("{} (prestress iteration {})", step.name, iteration);
    step.increments = 1;
    for (std::size_t l = 0; l < m->loads.size(); ++l) step.targets[m->loads[l].name] = to->pressure[l];
    // Only the first solve starts from a stress-free state (7.6)–(7.8); later ones start prestressed.
    if (iteration > 1) step.solver.stiffen_stress_free_start = false;
  }
  install_model(std::move(m));
}

void Analysis::run_prestress_step(AnalysisObserver& observer) {
  // Resumed from the checkpoint at the step's end: the prestress is in place already (run()).
  if (state_.fraction >= 1.0 - 1e-12) return;
  const int s = state_.step;
  const Model& deck = deck_model_;
  const Step& step = deck.steps[s];
  const Step::FixedPoint& fp = step.fixed_point;
  const Checkpoint start = state_;
  LoadState end = start.step_start;
  end.step = s;
  for (std::size_t k = 0; k < deck.loads.size(); ++k)
    if (auto it = step.targets.find(deck.loads[k].name); it != step.targets.end()) end.pressure[k] = it->second;
  const auto level = [&](int i) {  // the loads after i of the step's n increments
    LoadState l = start.step_start;
    l.step = s;
    const double t = std::min(1.0, static_cast<double>(i) / step.increments);
    for (std::size_t k = 0; k < l.pressure.size(); ++k)
      l.pressure[k] += t * (end.pressure[k] - start.step_start.pressure[k]);
    return l;
  };
  const double diagonal = imaged_diagonal();
  const double goal = fp.tolerance * diagonal;
  const int dim = deck.dofs_per_node(), nodes = deck.num_nodes();
  const auto back_to_deck = [&] { install_model(nullptr); };
  std::vector<double> prestress = initial_prestress(deck);
  const int most = step.increments + fp.max_iterations;
  int iterations = 0;
  // The relaxation of the update (13.21) at the imaged loads: 1 on the ramp, then, under Aitken's
  // acceleration, from the last two solves' displacements (13.24).
  double omega = 1;
  Eigen::VectorXd previous;
  for (int k = 1;; ++k) {
    const auto t0 = std::chrono::steady_clock::now();
    const LoadState from = level(k - 1), to = level(k);
    adopt_prestress(prestress, s, k, &to);
    state_ = start;
    state_.u.setZero(model_->num_dofs());
    state_.loads = from;
    state_.step_start = from;
    update_volumes();
    state_.step_start.volume = state_.loads.volume;
    state_.trace = StepTrace();
    ForwardSolveCounter counter(observer);
    try {
      run_step(counter);
    } catch (const SolveError& e) {
      back_to_deck();
      state_ = start;
      throw SolveError(std::string(e.what()) +
                       fmt::format(" (Iteration {} of the prestress method, theory manual §13.2: a forward solve from "
                                   "the imaged geometry with the prestretch of the iterations before it{}.)",
                                   k,
                                   k <= step.increments
                                       ? "; more `increments` make each load step of the ramp smaller"
                                       : ", at the imaged loads"));
    } catch (...) {
      back_to_deck();
      state_ = start;
      throw;
    }
    iterations = counter.newton_iterations;
    // The solve's distance from the imaged positions: max_n |u_n| (13.24).
    double sum = 0, max_distance = 0;
    for (int n = 0; n < nodes; ++n) {
      double d2 = 0;
      for (int c = 0; c < dim; ++c) d2 += std::pow(state_.u(deck.node_dof(n, c)), 2);
      sum += d2;
      max_distance = std::max(max_distance, std::sqrt(d2));
    }
    const bool converged = k >= step.increments && max_distance <= goal;
    FixedPointRecord rec;
    rec.step = s + 1;
    rec.step_name = step.name;
    rec.iteration = k;
    rec.max_distance = max_distance;
    rec.rms_distance = std::sqrt(sum / nodes);
    rec.goal = goal;
    // Aitken's Δ² on the solves at the imaged loads (13.24), as (13.17) on the fixed point's residual.
    if (!converged && fp.aitken && k > step.increments && previous.size() > 0) {
      const Eigen::VectorXd du = state_.u - previous;
      const double dd = du.squaredNorm();
      if (dd > 0) omega = std::max(-omega * previous.dot(du) / dd, 0.05);
    }
    if (k >= step.increments) previous = state_.u;
    rec.relaxation = converged ? 0 : omega;
    rec.increments = counter.increments;
    rec.newton_iterations = counter.newton_iterations;
    rec.cutbacks = counter.cutbacks;
    rec.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    observer.on_fixed_point(rec);
    if (converged) break;
    if (k >= most) {
      back_to_deck();
      state_ = start;
      const std::string unit = deck.units.display_unit(Dimension::length);
      const auto len = [&](double v) { return deck.units.from_internal(v, unit, Dimension::length); };
      throw SolveError(fmt::format(
          "step {} '{}' (inverse, method: prestress): after the {} increment(s) of the load ramp and {} iteration(s) "
          "at the imaged loads (fixed_point_iterations), a forward solve from the prestressed imaged geometry still "
          "moves a node by {:.4g} {} ({:.4g} {} root mean square), above the tolerance {:.4g} {} "
          "(fixed_point_tolerance {:g} × the imaged bounding-box diagonal {:.6g} {}). The files of the run so far are "
          "kept; fixed_point.csv lists the distance per iteration. If it is still falling, raise "
          "`fixed_point_iterations`; if it stagnates, the imaged shape may not be an equilibrium shape of the "
          "discrete membrane (theory manual §13.2), and a larger `fixed_point_tolerance` accepts the nearest state",
          s + 1, step.name, step.increments, k - step.increments, len(max_distance), unit, len(rec.rms_distance), unit,
          len(goal), unit, fp.tolerance, len(diagonal), unit));
    }
    // (13.21): P ← U^ω P with U = (P⁻ᵀ C P⁻¹)^½ the stretch of the solve from the imaged geometry, C the
    // Gauss point's C from the stress-free state; H̃ ← h det P for an imaged thickness h = H̃ / det P (13.22).
    std::size_t q0 = 0;
    for (int p = 0; p < static_cast<int>(model_->parts.size()); ++p) {
      const Part& part = model_->parts[p];
      const std::vector<MembranePoint> points = system_->points(state_.u, p, s);
      if (points.size() != part.point_prestretch.size())
        throw std::logic_error(fmt::format("part '{}': {} Gauss points and {} prestretches", part.name, points.size(),
                                           part.point_prestretch.size()));
      for (std::size_t q = 0; q < points.size(); ++q) {
        const Eigen::Vector3d& E = points[q].E;
        Eigen::Matrix2d C;
        C << 1 + 2 * E(0), 2 * E(2), 2 * E(2), 1 + 2 * E(1);
        const Eigen::Matrix2d& P = part.point_prestretch[q];
        const Eigen::Matrix2d Pinv = P.inverse();
        const Eigen::Matrix2d Cinc = Pinv.transpose() * C * Pinv;
        const Eigen::Matrix2d next = spd_power(0.5 * (Cinc + Cinc.transpose()), omega) * P;
        double* v = prestress.data() + kPerPoint * (q0 + q);
        if (part.imaged_thickness) v[4] *= next.determinant() / P.determinant();
        v[0] = next(0, 0);
        v[1] = next(1, 0);
        v[2] = next(0, 1);
        v[3] = next(1, 1);
      }
      q0 += points.size();
    }
  }
  // The run continues on the copy with the last prestress, at the imaged loads, from the last
  // solve's state (within the tolerance of the imaged positions).
  state_.prestress = prestress;
  state_.step_start = start.step_start;
  end_iterative_step(observer, end, iterations);
}

}  // namespace tunica
