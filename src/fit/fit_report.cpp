#include "fit/fit_report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tunica {

namespace {

const UnitSystem& internal_units() {
  static const UnitSystem u("mm", "N");
  return u;
}

double to_unit(double v, const std::string& unit, Dimension d) {
  return unit.empty() ? v : internal_units().from_internal(v, unit, d);
}

/// Distinct axial stretches in order of appearance, and each point's level index.
std::vector<double> stretch_levels(const InflationData& data, std::vector<int>* level_of = nullptr) {
  std::vector<double> levels;
  if (level_of) level_of->clear();
  for (const InflationPoint& pt : data.points) {
    int found = -1;
    for (std::size_t l = 0; l < levels.size(); ++l)
      if (std::abs(levels[l] - pt.lambda_z) <= 1e-6 * pt.lambda_z) found = static_cast<int>(l);
    if (found < 0) {
      found = static_cast<int>(levels.size());
      levels.push_back(pt.lambda_z);
    }
    if (level_of) level_of->push_back(found);
  }
  return levels;
}

std::string size_name(const InflationData& data) {
  return data.size == SizeMeasure::mid_radius ? "radius" : "outer_diameter";
}

/// Measured stresses of a point (fit_report.hpp): (Sθ, Sz).
std::pair<double, double> measured_stresses(const InflationData& data, const InflationPoint& pt) {
  const TubeGeometry& g = data.specimen.geometry;
  const double r = pt.mid_radius, h = g.H / (pt.lambda_theta * pt.lambda_z);
  const double N = g.ends == TubeEnds::open ? pt.axial_force : pt.axial_force + std::numbers::pi * r * r * pt.pressure;
  const double sigma_theta = pt.pressure * r / h, sigma_z = N / (2.0 * std::numbers::pi * r * h);
  return {sigma_theta / (pt.lambda_theta * pt.lambda_theta), sigma_z / (pt.lambda_z * pt.lambda_z)};
}

std::string fmt_or_nan(double v, const char* spec = "{:.3g}") {
  return std::isfinite(v) ? fmt::format(fmt::runtime(spec), v) : std::string("n/a");
}

/// Text for a Markdown table cell ('|' escaped).
std::string markdown_cell(const std::string& text) {
  std::string out;
  for (char ch : text) out += ch == '|' ? std::string("\\|") : std::string(1, ch);
  return out;
}

}  // namespace

std::vector<ReportedConstant> reported_constants(const FitResult& fit) {
  std::vector<ReportedConstant> out;
  for (std::size_t i = 0; i < fit.constant_names.size(); ++i) {
    const FittedConstant& c = fit.constant_names[i];
    const std::string unit = c.dim == Dimension::pressure ? "kPa" : "";
    out.push_back({c.name, to_unit(fit.constants(i), unit, c.dim), to_unit(fit.standard_errors(i), unit, c.dim), unit});
  }
  return out;
}

std::string fitted_material_yaml(const InflationData& data, const FitResult& fit, const std::string& name) {
  std::string s = fmt::format(
      "# Fitted by `tunica fit --model {}` to {} ({} points):\n"
      "# R²(pressure) = {}, R²(axial force) = {}; ± one standard error.\n"
      "materials:\n  {}:\n    type: {}\n",
      fit.model, data.file, data.points.size(), fmt_or_nan(fit.r2_pressure, "{:.6f}"),
      fmt_or_nan(fit.r2_force, "{:.6f}"), name, fit.material_type);
  for (const ReportedConstant& c : reported_constants(fit)) {
    const std::string value = fmt::format("{:.8g}{}", c.value, c.unit.empty() ? "" : " " + c.unit);
    s += fmt::format("    {}: {:<22}# ± {}{}\n", c.name, value, fmt_or_nan(c.standard_error),
                     c.unit.empty() ? "" : " " + c.unit);
  }
  return s;
}

std::string fit_summary_text(const InflationData& data, const FitResult& fit) {
  std::string s = fmt::format("{}: {} points, model {}\n", data.file, data.points.size(), fit.model);
  for (const ReportedConstant& c : reported_constants(fit))
    s += fmt::format("  {:<3} = {:<14.8g} ± {:<10} {:<4} ({}%)\n", c.name, c.value, fmt_or_nan(c.standard_error),
                     c.unit, fmt_or_nan(100.0 * c.standard_error / std::abs(c.value), "{:.2g}"));
  s += fmt::format("  R²(pressure) = {}, R²(axial force) = {}\n", fmt_or_nan(fit.r2_pressure, "{:.6f}"),
                   fmt_or_nan(fit.r2_force, "{:.6f}"));
  if (!fit.starts[fit.best_start].converged)
    s += "  warning: the best start stopped without converging (" + fit.starts[fit.best_start].termination + ")\n";
  if (!fit.identifiable)
    s += "  warning: JᵀJ is singular at the optimum: the constants are not identifiable from these data\n";
  if (!fit.active_bounds.empty())
    s += fmt::format("  note: at a bound of the admissible set: {}\n", fmt::join(fit.active_bounds, ", "));
  return s;
}

std::string fit_report_markdown(const InflationData& data, const FitResult& fit, const FitOptions& options) {
  const TubeGeometry& g = data.specimen.geometry;
  std::vector<int> level_of;
  const std::vector<double> levels = stretch_levels(data, &level_of);
  std::string s = fmt::format("# tunica fit: {} to {}\n\n", fit.model, data.file);
  s += fmt::format("- data: {} points (lines {}–{}), {} axial-stretch level(s): {:.6g}\n", data.points.size(),
                   data.points.front().line, data.points.back().line, levels.size(), fmt::join(levels, ", "));
  s += fmt::format(
      "- specimen: load-free mid-surface radius R = {:.6g} mm (outer diameter {:.6g} mm), wall thickness "
      "H = {:.6g} mm, {} ends\n",
      g.R, 2 * g.R + g.H, g.H, tube_ends_name(g.ends));
  s += fmt::format("- model: {} → deck material `{}`; {} parameters, {} residuals\n", fit.model, fit.material_type,
                   fit.num_parameters, fit.num_residuals);
  s += fmt::format(
      "- residuals: (p_model − p)/s_p and (F_model − F)/s_F at the measured stretches, s_p = {:.6g} {}, "
      "s_F = {:.6g} {}; loss {}{}\n",
      to_unit(fit.pressure_scale, data.pressure_unit, Dimension::pressure), data.pressure_unit,
      to_unit(fit.force_scale, data.force_unit, Dimension::force), data.force_unit, robust_loss_name(options.loss),
      options.loss == RobustLoss::none ? "" : fmt::format(" (scale {:g})", options.loss_scale));
  s += "\n## Constants\n\n| constant | value | standard error | relative |\n|---|---|---|---|\n";
  for (const ReportedConstant& c : reported_constants(fit))
    s += fmt::format("| {} | {:.8g}{} | {}{} | {}% |\n", c.name, c.value, c.unit.empty() ? "" : " " + c.unit,
                     fmt_or_nan(c.standard_error), c.unit.empty() ? "" : " " + c.unit,
                     fmt_or_nan(100.0 * c.standard_error / std::abs(c.value), "{:.3g}"));
  s += "\n## Correlation matrix\n\n|   |";
  for (const auto& c : fit.constant_names) s += fmt::format(" {} |", c.name);
  s += "\n|---|";
  for (std::size_t i = 0; i < fit.constant_names.size(); ++i) s += "---|";
  s += "\n";
  for (std::size_t i = 0; i < fit.constant_names.size(); ++i) {
    s += fmt::format("| {} |", fit.constant_names[i].name);
    for (std::size_t j = 0; j < fit.constant_names.size(); ++j)
      s += fmt::format(" {} |", fmt_or_nan(fit.correlation(i, j), "{:+.4f}"));
    s += "\n";
  }
  s += fmt::format(
      "\n## Fit quality\n\n| quantity | R² | rms misfit |\n|---|---|---|\n| pressure | {} | {:.4g} {} |\n"
      "| axial force | {} | {:.4g} {} |\n\nResidual standard deviation s = {:.4g} (fraction of the data scale); "
      "cost ½Σρ(r²) = {:.6g}.\n",
      fmt_or_nan(fit.r2_pressure, "{:.6f}"), to_unit(fit.rms_pressure, data.pressure_unit, Dimension::pressure),
      data.pressure_unit, fmt_or_nan(fit.r2_force, "{:.6f}"), to_unit(fit.rms_force, data.force_unit, Dimension::force),
      data.force_unit, fit.residual_std, fit.cost);
  s += "\n## Starting points\n\n| # | start | end | cost | iterations | Ceres |\n|---|---|---|---|---|---|\n";
  for (std::size_t i = 0; i < fit.starts.size(); ++i) {
    const StartOutcome& o = fit.starts[i];
    auto list = [&](const Eigen::VectorXd& k) {
      std::string t;
      for (std::size_t j = 0; j < fit.constant_names.size(); ++j) {
        const auto& c = fit.constant_names[j];
        t += fmt::format("{}{} = {:.4g}{}", t.empty() ? "" : ", ", c.name,
                         to_unit(k(j), c.dim == Dimension::pressure ? "kPa" : "", c.dim),
                         c.dim == Dimension::pressure ? " kPa" : "");
      }
      return t;
    };
    s += fmt::format("| {}{}{} | {}{} | {} | {:.6g} | {} | {} |\n", i + 1,
                     static_cast<int>(i) == fit.best_start ? " (best)" : "", o.usable ? "" : " (failed)", list(o.start),
                     o.projected ? " (projected onto the admissible set)" : "", list(o.end), o.cost, o.iterations,
                     markdown_cell(o.termination));
  }
  s += "\n## Notes\n\n";
  s += "- Standard errors and correlations come from the Jacobian at the optimum, Cov = s² (JᵀJ)⁻¹ mapped to the "
       "constants by the delta method; they assume independent errors of equal size in the scaled residuals.\n";
  if (options.loss != RobustLoss::none)
    s += "- A robust loss was used: the standard errors are those of the plain least-squares problem at the optimum.\n";
  if (!fit.starts[fit.best_start].converged)
    s += "- The best start stopped without meeting Ceres' convergence tests: the constants may still be moving "
         "(typically towards a limit the model cannot reach, such as Fung's c → ∞, a → 0 for data without "
         "exponential stiffening).\n";
  if (!fit.identifiable)
    s += "- JᵀJ is numerically singular at the optimum: some combination of the constants is not determined by these "
         "data (no standard errors).\n";
  if (!fit.active_bounds.empty())
    s += fmt::format(
        "- At a bound of the admissible box: {} (the optimum lies on the edge of the convex set; the "
        "standard errors assume an interior optimum).\n",
        fmt::join(fit.active_bounds, ", "));
  s += "- The fitted material is built by the same factory as a deck's, which checks convexity.\n";
  return s;
}

std::string fit_points_csv(const InflationData& data, const FitResult& fit) {
  const std::string pu = data.pressure_unit, fu = data.force_unit, lu = data.length_unit;
  const std::string sz = size_name(data);
  std::string s = fmt::format(
      "line,level,lambda_z,lambda_theta,E_theta,E_z,pressure_measured_{0},pressure_fitted_{0},axial_force_measured_{1},"
      "axial_force_fitted_{1},{2}_measured_{3},S_theta_measured_kPa,S_theta_fitted_kPa,S_z_measured_kPa,"
      "S_z_fitted_kPa\n",
      pu, fu, sz, lu);
  std::vector<int> level_of;
  stretch_levels(data, &level_of);
  for (std::size_t i = 0; i < data.points.size(); ++i) {
    const InflationPoint& pt = data.points[i];
    const TubeState& f = fit.fitted[i];
    const auto [st, sz_] = measured_stresses(data, pt);
    s += fmt::format(
        "{},{},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g}"
        "\n",
        pt.line, level_of[i], pt.lambda_z, pt.lambda_theta, f.E_theta, f.E_z,
        to_unit(pt.pressure, pu, Dimension::pressure), to_unit(f.pressure, pu, Dimension::pressure),
        to_unit(pt.axial_force, fu, Dimension::force), to_unit(f.axial_force, fu, Dimension::force),
        to_unit(pt.measured_size, lu, Dimension::length), to_unit(st, "kPa", Dimension::pressure),
        to_unit(f.S_theta, "kPa", Dimension::pressure), to_unit(sz_, "kPa", Dimension::pressure),
        to_unit(f.S_z, "kPa", Dimension::pressure));
  }
  return s;
}

std::string fit_curves_csv(const InflationData& data, const FitResult& fit) {
  const std::string pu = data.pressure_unit, fu = data.force_unit, lu = data.length_unit;
  const std::string sz = size_name(data);
  std::string s = fmt::format(
      "level,lambda_z,lambda_theta,E_theta,pressure_{0},{2}_{3},axial_force_{1},S_theta_kPa,S_z_kPa\n", pu, fu, sz, lu);
  const auto material = material_parametrization(fit.model).make_material(fit.constants);
  std::vector<int> level_of;
  const std::vector<double> levels = stretch_levels(data, &level_of);
  for (std::size_t l = 0; l < levels.size(); ++l) {
    double lo = HUGE_VAL, hi = -HUGE_VAL;
    int count = 0;
    for (std::size_t i = 0; i < data.points.size(); ++i)
      if (level_of[i] == static_cast<int>(l)) {
        lo = std::min(lo, data.points[i].lambda_theta);
        hi = std::max(hi, data.points[i].lambda_theta);
        ++count;
      }
    if (count < 2 || !(hi > lo)) continue;  // a single point draws no curve
    constexpr int kSamples = 100;
    for (int k = 0; k <= kSamples; ++k) {
      const double lt = lo + (hi - lo) * k / kSamples;
      const TubeState t = tube_state(*material, data.specimen.geometry, lt, levels[l]);
      const double size = data.size == SizeMeasure::mid_radius ? t.r : t.outer_diameter;
      s += fmt::format("{},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g}\n", l, levels[l], lt,
                       t.E_theta, to_unit(t.pressure, pu, Dimension::pressure), to_unit(size, lu, Dimension::length),
                       to_unit(t.axial_force, fu, Dimension::force), to_unit(t.S_theta, "kPa", Dimension::pressure),
                       to_unit(t.S_z, "kPa", Dimension::pressure));
    }
  }
  return s;
}

}  // namespace tunica
