#pragma once
// Nonlinear least-squares identification of a material's constants from
// inflation–extension data (theory manual §8, §12.1), with Ceres Solver.
//
// The measured deformation (λθ from the size, λz) is taken as exact; the thin-tube
// model predicts the loads, and the residuals are their misfits scaled by the data:
//     r_p,i = (p(λθi, λzi; k) − p_i) / s_p,   r_F,i = (F(λθi, λzi; k) − F_i) / s_F,
//     s_p = max_i |p_i|,  s_F = max_i |F_i|   (either falls back on the other via π R²
//     if the data never load it),
// minimised over θ (material_parametrization.hpp) in its box, optionally through a
// robust loss ρ: min ½ Σ ρ(r²). Several starting points; for each, the stress-like
// scale θ(0) is first set by the 1-D least squares that is linear in it.
// At the optimum (n parameters, m = 2·points residuals, J = ∂r/∂θ):
//     s² = Σ r² / (m − n),  Cov_θ = s² (JᵀJ)⁻¹,  Cov_k = T Cov_θ Tᵀ  (T = ∂k/∂θ, delta method),
// standard errors √diag Cov_k, correlations Cov_k,ij / (SE_i SE_j), and per measured quantity
//     R² = 1 − Σ (pred − meas)² / Σ (meas − mean)².
#include <Eigen/Dense>
#include <string>
#include <vector>

#include "fit/inflation_data.hpp"
#include "fit/material_parametrization.hpp"

namespace tunica {

/// A robust loss applied to each residual.
enum class RobustLoss { none, huber, cauchy, soft_l1 };

/// "none", "huber", ... ; parse_robust_loss throws InputError({"--loss"}) on an unknown name.
const char* robust_loss_name(RobustLoss loss);
RobustLoss parse_robust_loss(const std::string& name);

/// Options of a fit.
struct FitOptions {
  std::string model = "fung2d";
  RobustLoss loss = RobustLoss::none;
  double loss_scale = 0.05;  ///< residual size (in units of the data scale) where the robust loss bends
  int max_starts = 0;        ///< use the first N built-in starting points (0 = all)
  /// Starting points given as constants (internal units); projected onto the admissible set.
  std::vector<Eigen::VectorXd> start_constants;
  bool rescale_starts = true;  ///< set each start's scale θ(0) by linear least squares first
  bool use_builtin_starts = true;
  int max_iterations = 400;
};

/// What became of one starting point.
struct StartOutcome {
  Eigen::VectorXd start;  ///< constants at the start (after scaling)
  Eigen::VectorXd end;    ///< constants where it stopped
  double cost = 0;        ///< ½ Σ ρ(r²) at the end
  int iterations = 0;
  std::string termination;  ///< Ceres' message
  bool usable = false;      ///< Ceres ended without failure
  bool converged = false;   ///< by one of Ceres' convergence tests (not the iteration limit)
  bool projected = false;   ///< the given start was not admissible and was projected
};

/// The outcome of a fit.
struct FitResult {
  std::string model;
  std::string material_type;
  std::vector<FittedConstant> constant_names;
  Eigen::VectorXd theta;            ///< internal variables at the optimum
  Eigen::VectorXd constants;        ///< fitted constants (internal units)
  Eigen::VectorXd standard_errors;  ///< NaN where J is rank deficient
  Eigen::MatrixXd covariance;       ///< of the constants
  Eigen::MatrixXd correlation;
  double cost = 0;  ///< ½ Σ ρ(r²)
  int num_residuals = 0;
  int num_parameters = 0;
  double residual_std = 0;  ///< s (normalised residuals)
  double pressure_scale = 0, force_scale = 0;
  double r2_pressure = 0, r2_force = 0;
  double rms_pressure = 0, rms_force = 0;  ///< root-mean-square misfits, internal units
  bool identifiable = true;                ///< JᵀJ numerically invertible
  std::vector<std::string> active_bounds;  ///< θ names at a bound of their box
  std::vector<TubeState> fitted;           ///< the tube at each point with the fitted constants
  std::vector<StartOutcome> starts;
  int best_start = -1;
};

/// The thin-tube state at each point's measured (λθ, λz) for a material.
std::vector<TubeState> predict_points(const InflationData& data, const MembraneMaterial& material);

/// Fits `options.model` to `data`. Throws InputError if the data have too few
/// points for the model (points ≤ parameters) or carry no load at all, and
/// SolveError if no starting point leads anywhere.
FitResult fit_inflation_data(const InflationData& data, const FitOptions& options);

}  // namespace tunica
