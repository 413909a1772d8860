#include "fit/inflation_fit.hpp"

#include <ceres/ceres.h>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "core/errors.hpp"

namespace tunica {

namespace {

/// The normalised residuals r(θ) of inflation_fit.hpp, with a central-difference Jacobian.
class TubeResiduals {
public:
  TubeResiduals(const InflationData& data, const MaterialParametrization& model, double p_scale, double f_scale)
      : data_(data), model_(model), p_scale_(p_scale), f_scale_(f_scale) {}

  int size() const { return 2 * static_cast<int>(data_.points.size()); }

  /// r(θ): (r_p,i, r_F,i) interleaved. False if the material cannot be evaluated (e.g. exp overflow).
  bool residuals(const Eigen::VectorXd& theta, Eigen::VectorXd& r) const {
    r.resize(size());
    try {
      const auto material = model_.make_material(model_.constants_of(theta));
      for (std::size_t i = 0; i < data_.points.size(); ++i) {
        const InflationPoint& pt = data_.points[i];
        const TubeState s = tube_state(*material, data_.specimen.geometry, pt.lambda_theta, pt.lambda_z);
        r(2 * i) = (s.pressure - pt.pressure) / p_scale_;
        r(2 * i + 1) = (s.axial_force - pt.axial_force) / f_scale_;
      }
    } catch (const std::exception&) {
      return false;
    }
    return r.allFinite();
  }

  /// J = ∂r/∂θ by central differences, step 1e-6 max(1, |θj|).
  bool jacobian(const Eigen::VectorXd& theta, Eigen::MatrixXd& J) const {
    J.resize(size(), theta.size());
    Eigen::VectorXd rp, rm;
    for (int j = 0; j < theta.size(); ++j) {
      const double h = 1e-6 * std::max(1.0, std::abs(theta(j)));
      Eigen::VectorXd a = theta, b = theta;
      a(j) += h;
      b(j) -= h;
      if (!residuals(a, rp) || !residuals(b, rm)) return false;
      J.col(j) = (rp - rm) / (2.0 * h);
    }
    return true;
  }

private:
  const InflationData& data_;
  const MaterialParametrization& model_;
  double p_scale_, f_scale_;
};

/// r(θ) and J(θ) at the last θ asked for: every residual block of one Ceres evaluation
/// sees the same θ, so the tube is evaluated once per θ, not once per block.
class SharedEvaluation {
public:
  SharedEvaluation(const TubeResiduals& r, int num_parameters) : r_(r), n_(num_parameters) {}

  /// Residuals (and J if `with_jacobian`) at θ; false if the model cannot be evaluated there.
  bool at(const double* theta, bool with_jacobian) const {
    const Eigen::Map<const Eigen::VectorXd> t(theta, n_);
    if (!(has_ && theta_ == t)) {
      theta_ = t;
      has_ = true;
      has_jacobian_ = false;
      ok_ = r_.residuals(theta_, residuals_);
    }
    if (ok_ && with_jacobian && !has_jacobian_) {
      ok_ = r_.jacobian(theta_, jacobian_);
      has_jacobian_ = true;
    }
    return ok_;
  }
  double residual(int i) const { return residuals_(i); }
  const Eigen::MatrixXd& jacobian() const { return jacobian_; }

private:
  const TubeResiduals& r_;
  int n_;
  mutable Eigen::VectorXd theta_, residuals_;
  mutable Eigen::MatrixXd jacobian_;
  mutable bool has_ = false, has_jacobian_ = false, ok_ = false;
};

/// One residual r_i(θ) as a Ceres cost function, so that a robust loss ρ acts on each
/// residual alone (Ceres applies ρ to the squared norm of a whole block).
class TubeResidualCost final : public ceres::CostFunction {
public:
  TubeResidualCost(const SharedEvaluation& e, int index, int num_parameters) : e_(e), i_(index), n_(num_parameters) {
    set_num_residuals(1);
    mutable_parameter_block_sizes()->push_back(num_parameters);
  }
  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    const bool with_jacobian = jacobians && jacobians[0];
    if (!e_.at(parameters[0], with_jacobian)) return false;
    residuals[0] = e_.residual(i_);
    if (with_jacobian)
      for (int j = 0; j < n_; ++j) jacobians[0][j] = e_.jacobian()(i_, j);
    return true;
  }

private:
  const SharedEvaluation& e_;
  int i_, n_;
};

ceres::LossFunction* make_loss(RobustLoss loss, double a) {
  switch (loss) {
    case RobustLoss::none: return nullptr;
    case RobustLoss::huber: return new ceres::HuberLoss(a);
    case RobustLoss::cauchy: return new ceres::CauchyLoss(a);
    case RobustLoss::soft_l1: return new ceres::SoftLOneLoss(a);
  }
  return nullptr;
}

/// R² = 1 − Σ (pred − meas)² / Σ (meas − mean)² (NaN if the measurements are constant).
double r_squared(const std::vector<double>& meas, const std::vector<double>& pred) {
  double mean = 0;
  for (double m : meas) mean += m;
  mean /= static_cast<double>(meas.size());
  double ss_res = 0, ss_tot = 0;
  for (std::size_t i = 0; i < meas.size(); ++i) {
    ss_res += (pred[i] - meas[i]) * (pred[i] - meas[i]);
    ss_tot += (meas[i] - mean) * (meas[i] - mean);
  }
  return ss_tot > 0 ? 1.0 - ss_res / ss_tot : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

const char* robust_loss_name(RobustLoss loss) {
  switch (loss) {
    case RobustLoss::none: return "none";
    case RobustLoss::huber: return "huber";
    case RobustLoss::cauchy: return "cauchy";
    case RobustLoss::soft_l1: return "soft_l1";
  }
  return "?";
}

RobustLoss parse_robust_loss(const std::string& name) {
  for (RobustLoss l : {RobustLoss::none, RobustLoss::huber, RobustLoss::cauchy, RobustLoss::soft_l1})
    if (name == robust_loss_name(l)) return l;
  throw InputError({"--loss", 0, 0, name}, "unknown loss '" + name + "' (known: none, huber, cauchy, soft_l1)");
}

std::vector<TubeState> predict_points(const InflationData& data, const MembraneMaterial& material) {
  std::vector<TubeState> out;
  for (const InflationPoint& pt : data.points)
    out.push_back(tube_state(material, data.specimen.geometry, pt.lambda_theta, pt.lambda_z));
  return out;
}

FitResult fit_inflation_data(const InflationData& data, const FitOptions& options) {
  const MaterialParametrization& model = material_parametrization(options.model);
  const int n = static_cast<int>(model.theta_names.size());
  const int points = static_cast<int>(data.points.size());
  if (points <= n)
    throw InputError({data.file, data.points.empty() ? data.header_line : data.points.back().line, 0, ""},
                     fmt::format("too few points for model {}: {} point(s) for {} parameters ({}); need at least {}",
                                 model.model, points, n, fmt::join(model.theta_names, ", "), n + 1));

  // Data scales s_p, s_F (inflation_fit.hpp).
  const TubeGeometry& g = data.specimen.geometry;
  const double area = std::numbers::pi * g.R * g.R;
  double p_scale = 0, f_scale = 0;
  for (const InflationPoint& pt : data.points) {
    p_scale = std::max(p_scale, std::abs(pt.pressure));
    f_scale = std::max(f_scale, std::abs(pt.axial_force));
  }
  if (p_scale == 0 && f_scale == 0)
    throw InputError({data.file, data.header_line, 0, ""}, "all pressures and axial forces are zero: nothing to fit");
  if (p_scale == 0) p_scale = f_scale / area;
  if (f_scale == 0) f_scale = p_scale * area;

  const TubeResiduals residuals(data, model, p_scale, f_scale);

  // Starting points (θ), each with its scale set by linear least squares in exp θ(0).
  std::vector<std::pair<Eigen::VectorXd, bool>> starts;
  for (const Eigen::VectorXd& k : options.start_constants) {
    bool projected = false;
    const auto t = model.theta_of(k, &projected);
    if (!t)
      throw InputError({"--start", 0, 0, model.constants[0].name},
                       "the starting value of " + model.constants[0].name + " must be positive");
    starts.emplace_back(*t, projected);
  }
  if (options.use_builtin_starts) {
    const int count = options.max_starts > 0 ? std::min<int>(options.max_starts, model.starts.size())
                                             : static_cast<int>(model.starts.size());
    for (int i = 0; i < count; ++i) starts.emplace_back(model.starts[i], false);
  }
  if (starts.empty()) throw InputError({"--starts", 0, 0, ""}, "no starting point");

  FitResult result;
  result.model = model.model;
  result.material_type = model.material_type;
  result.constant_names = model.constants;
  result.num_parameters = n;
  result.num_residuals = residuals.size();
  result.pressure_scale = p_scale;
  result.force_scale = f_scale;

  double best_cost = std::numeric_limits<double>::infinity();
  for (auto [theta, projected] : starts) {
    if (options.rescale_starts) {
      // Predictions are proportional to exp θ(0): fit the factor k to the data at θ(0) = 0.
      Eigen::VectorXd unit = theta, r0;
      unit(0) = 0;
      if (residuals.residuals(unit, r0)) {
        double num = 0, den = 0;
        for (int i = 0; i < points; ++i) {
          const double pp = r0(2 * i) + data.points[i].pressure / p_scale;  // k=1 prediction / s_p
          const double ff = r0(2 * i + 1) + data.points[i].axial_force / f_scale;
          num += pp * data.points[i].pressure / p_scale + ff * data.points[i].axial_force / f_scale;
          den += pp * pp + ff * ff;
        }
        const double k = num / den;
        if (k > 0 && std::isfinite(k)) theta(0) = std::clamp(std::log(k), model.lower(0), model.upper(0));
      }
    }
    StartOutcome out;
    out.start = model.constants_of(theta);
    out.projected = projected;

    const SharedEvaluation shared(residuals, n);
    ceres::Problem problem;  // owns the cost and loss functions
    for (int i = 0; i < residuals.size(); ++i)
      problem.AddResidualBlock(new TubeResidualCost(shared, i, n), make_loss(options.loss, options.loss_scale),
                               theta.data());
    for (int j = 0; j < n; ++j) {
      problem.SetParameterLowerBound(theta.data(), j, model.lower(j));
      problem.SetParameterUpperBound(theta.data(), j, model.upper(j));
    }
    ceres::Solver::Options so;
    so.linear_solver_type = ceres::DENSE_QR;
    so.max_num_iterations = options.max_iterations;
    so.function_tolerance = 1e-15;
    so.gradient_tolerance = 1e-16;
    so.parameter_tolerance = 1e-14;
    so.logging_type = ceres::SILENT;
    so.minimizer_progress_to_stdout = false;
    so.num_threads = 1;
    ceres::Solver::Summary summary;
    ceres::Solve(so, &problem, &summary);

    out.end = model.constants_of(theta);
    out.cost = summary.final_cost;
    out.iterations = static_cast<int>(summary.iterations.size()) - 1;
    out.termination = summary.message;
    out.usable = summary.IsSolutionUsable() && std::isfinite(summary.final_cost);
    out.converged = summary.termination_type == ceres::CONVERGENCE;
    result.starts.push_back(out);
    if (out.usable && out.cost < best_cost) {
      best_cost = out.cost;
      result.theta = theta;
      result.best_start = static_cast<int>(result.starts.size()) - 1;
    }
  }
  if (result.best_start < 0) throw SolveError("fit: no starting point gave a usable solution");

  // Statistics at the optimum (inflation_fit.hpp).
  const Eigen::VectorXd& theta = result.theta;
  result.constants = model.constants_of(theta);
  result.cost = best_cost;
  Eigen::VectorXd r;
  Eigen::MatrixXd J;
  if (!residuals.residuals(theta, r) || !residuals.jacobian(theta, J))
    throw SolveError("fit: the model cannot be evaluated at the optimum");
  const int m = result.num_residuals;
  result.residual_std = std::sqrt(r.squaredNorm() / (m - n));
  const Eigen::VectorXd col_norm = J.colwise().norm().transpose();
  const int nk = static_cast<int>(model.constants.size());
  result.covariance = Eigen::MatrixXd::Constant(nk, nk, std::numeric_limits<double>::quiet_NaN());
  result.standard_errors = Eigen::VectorXd::Constant(nk, std::numeric_limits<double>::quiet_NaN());
  result.correlation = result.covariance;
  result.identifiable = (col_norm.array() > 0).all();
  if (result.identifiable) {
    // Column scaling D makes the conditioning test independent of the parameters' units.
    const Eigen::MatrixXd Js = J * col_norm.cwiseInverse().asDiagonal();
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(Js, Eigen::ComputeThinV);
    const Eigen::VectorXd sv = svd.singularValues();
    result.identifiable = sv(sv.size() - 1) > 1e-10 * sv(0);
    if (result.identifiable) {
      const Eigen::MatrixXd inv =
          svd.matrixV() * sv.cwiseInverse().cwiseAbs2().asDiagonal() * svd.matrixV().transpose();
      const Eigen::MatrixXd cov_theta = result.residual_std * result.residual_std *
                                        col_norm.cwiseInverse().asDiagonal() * inv *
                                        col_norm.cwiseInverse().asDiagonal();
      const Eigen::MatrixXd T = model.constants_jacobian(theta);
      result.covariance = T * cov_theta * T.transpose();
      result.standard_errors = result.covariance.diagonal().cwiseMax(0.0).cwiseSqrt();
      for (int i = 0; i < nk; ++i)
        for (int j = 0; j < nk; ++j)
          result.correlation(i, j) = result.covariance(i, j) / (result.standard_errors(i) * result.standard_errors(j));
    }
  }
  for (int j = 0; j < n; ++j) {
    const double tol = 1e-9 * std::max(1.0, std::abs(theta(j)));
    if (theta(j) - model.lower(j) <= tol || model.upper(j) - theta(j) <= tol)
      result.active_bounds.push_back(model.theta_names[j]);
  }

  const auto material = model.make_material(result.constants);
  result.fitted = predict_points(data, *material);
  std::vector<double> pm, pp, fm, fp;
  for (int i = 0; i < points; ++i) {
    pm.push_back(data.points[i].pressure);
    pp.push_back(result.fitted[i].pressure);
    fm.push_back(data.points[i].axial_force);
    fp.push_back(result.fitted[i].axial_force);
    result.rms_pressure += (pp[i] - pm[i]) * (pp[i] - pm[i]) / points;
    result.rms_force += (fp[i] - fm[i]) * (fp[i] - fm[i]) / points;
  }
  result.rms_pressure = std::sqrt(result.rms_pressure);
  result.rms_force = std::sqrt(result.rms_force);
  result.r2_pressure = r_squared(pm, pp);
  result.r2_force = r_squared(fm, fp);
  return result;
}

}  // namespace tunica
