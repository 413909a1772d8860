#include "fit/fit_command.hpp"

#include <fmt/format.h>

#include <filesystem>

#include "fit/fit_plot.hpp"
#include "fit/fit_report.hpp"
#include "fit/synthetic_data.hpp"
#include "output/atomic_file.hpp"

namespace tunica {

namespace {

/// `--start "{c: 10 kPa, a1: 1, a2: 1, a4: 0}"`: read against the material's declared
/// parameters (names, units), then ordered as the model's constants.
Eigen::VectorXd read_start(const std::string& text, const MaterialParametrization& model) {
  YAML::Node n;
  try {
    n = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw InputError({"--start", 0, e.mark.is_null() ? 0 : e.mark.column + 1, ""}, "YAML syntax error: " + e.msg);
  }
  const DeckNode node(n, "--start", "start", {"--start", 0, 0, "start"});
  if (!node.is_map()) node.fail("expected a map of the model's constants, e.g. {c: 10 kPa, a1: 1, a2: 1, a4: 0}");
  const Params p = read_params(node, material_types().at(model.material_type).spec, UnitSystem("mm", "N"));
  Eigen::VectorXd k(model.constants.size());
  for (std::size_t i = 0; i < model.constants.size(); ++i) k(i) = p.number(model.constants[i].name);
  return k;
}

}  // namespace

int run_fit_command(const FitCommand& c, std::FILE* log) {
  const MaterialParametrization& model = material_parametrization(c.model);
  FitOptions options;
  options.model = c.model;
  options.loss = parse_robust_loss(c.loss);
  if (!(c.loss_scale > 0)) throw InputError({"--loss-scale", 0, 0, ""}, "the loss scale must be positive");
  options.loss_scale = c.loss_scale;
  if (c.starts < 0) throw InputError({"--starts", 0, 0, ""}, "the number of starting points must be ≥ 0");
  options.max_starts = c.starts;
  if (!c.start.empty()) options.start_constants.push_back(read_start(c.start, model));

  InflationDataOptions read;
  if (!c.specimen.empty()) read.specimen = specimen_node_from_argument(c.specimen);
  for (const auto& s : c.select) read.select.push_back(parse_row_selection(s));
  read.allow_non_monotone = c.allow_non_monotone;
  const InflationData data = read_inflation_data(c.data, read);

  const FitResult fit = fit_inflation_data(data, options);

  std::filesystem::create_directories(c.output);
  const std::filesystem::path dir(c.output);
  write_file_atomically((dir / "report.md").string(), fit_report_markdown(data, fit, options));
  write_file_atomically((dir / "material.yaml").string(), fitted_material_yaml(data, fit, c.material_name));
  write_file_atomically((dir / "points.csv").string(), fit_points_csv(data, fit));
  write_file_atomically((dir / "curves.csv").string(), fit_curves_csv(data, fit));
  std::string plot_problem;
  if (c.plot) {
    std::string title = fmt::format("{}: {} fitted to {}", c.model, model.material_type,
                                    std::filesystem::path(c.data).filename().string());
    for (const ReportedConstant& k : reported_constants(fit))
      title += fmt::format("{} {} = {:.5g}{}", k.name == fit.constant_names[0].name ? "\n" : ",", k.name, k.value,
                           k.unit.empty() ? "" : " " + k.unit);
    plot_problem = plot_fit(c.output, title);
  }
  if (log) {
    std::fputs(fit_summary_text(data, fit).c_str(), log);
    std::fprintf(log, "results in %s: report.md, material.yaml, points.csv, curves.csv%s\n", c.output.c_str(),
                 c.plot && plot_problem.empty() ? ", fit.png" : "");
  }
  if (!plot_problem.empty()) std::fprintf(stderr, "tunica: warning: no fit.png: %s\n", plot_problem.c_str());
  return 0;
}

int run_synthesize_command(const std::string& plan, const std::string& output_csv, std::FILE* log) {
  const std::string csv = synthesize_from_plan(plan);
  write_file_atomically(output_csv, csv);
  if (log) std::fprintf(log, "wrote %s\n", output_csv.c_str());
  return 0;
}

}  // namespace tunica
