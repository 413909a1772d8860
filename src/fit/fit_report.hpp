#pragma once
// What `tunica fit` writes (docs/fit.md, "Outputs"):
//   report.md    constants ± standard errors, correlation matrix, R² per measured quantity,
//                starting points, notes (active bounds, identifiability, robust loss)
//   material.yaml  a `materials:` block ready to paste into a deck
//   points.csv   per point: measured and fitted pressure and axial force, and the
//                "measured" stresses  Sθ = p r/(h λθ²),  Sz = N/(2π r h λz²)
//                (N = F, or F + π r² p for closed ends; r, h from the measured λθ, λz)
//                beside the fitted S1, S2
//   curves.csv   the fitted tube along each axial-stretch level (for the figure)
#include <string>

#include "fit/inflation_fit.hpp"

namespace tunica {

/// The `materials:` YAML block of the fitted constants (stresses in kPa), named `name`,
/// with the standard errors and R² as comments.
std::string fitted_material_yaml(const InflationData& data, const FitResult& fit, const std::string& name);

/// The Markdown report.
std::string fit_report_markdown(const InflationData& data, const FitResult& fit, const FitOptions& options);

/// points.csv and curves.csv (columns named with their units, as history.csv).
std::string fit_points_csv(const InflationData& data, const FitResult& fit);
std::string fit_curves_csv(const InflationData& data, const FitResult& fit);

/// A few lines for the terminal: constants ± SE and R².
std::string fit_summary_text(const InflationData& data, const FitResult& fit);

/// The constants of a fit in deck units: (name, value, standard error, unit) with
/// stresses in kPa.
struct ReportedConstant {
  std::string name;
  double value = 0, standard_error = 0;
  std::string unit;
};
std::vector<ReportedConstant> reported_constants(const FitResult& fit);

}  // namespace tunica
