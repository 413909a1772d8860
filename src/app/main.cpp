// The `tunica` command line: run, check, reference and fit.
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <chrono>
#include <cstdio>
#include <exception>

#include "fit/fit_command.hpp"
#include "io/deck.hpp"
#include "io/reference.hpp"
#include "output/run_writer.hpp"
#include "solver/analysis.hpp"

namespace {

constexpr int kInputErrorExit = 2;
constexpr int kSolveErrorExit = 3;
constexpr int kOtherErrorExit = 4;

int run(const std::string& deck, const std::string& out, bool quiet) {
  const tunica::Model model = tunica::read_deck(deck);
  tunica::RunWriter writer(model, out, quiet ? nullptr : stdout);
  tunica::Analysis analysis(model);
  const auto t0 = std::chrono::steady_clock::now();
  analysis.run(writer);
  if (!quiet)
    std::printf("done in %.3f s; results in %s\n",
                std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), out.c_str());
  return 0;
}

int check(const std::string& deck) {
  const tunica::Model model = tunica::read_deck(deck);
  int elements = 0;
  for (const auto& p : model.parts) elements += static_cast<int>(p.elements.size());
  std::printf("%s: valid deck: %zu material(s), %zu part(s), %d node(s), %d element(s), %zu boundary set(s), "
              "%zu load(s), %zu step(s), %zu history column(s)\n",
              deck.c_str(), model.materials.size(), model.parts.size(), model.num_nodes(), elements,
              model.boundaries.size(), model.loads.size(), model.steps.size(), model.output.history.size());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Tunica: large-strain analysis of thin incompressible hyperelastic membranes"};
  app.set_version_flag("--version", std::string(TUNICA_VERSION));
  app.require_subcommand(1);
  std::string deck, out;
  bool quiet = false;
  auto* run_cmd = app.add_subcommand("run", "solve a deck and write results");
  run_cmd->add_option("deck", deck, "YAML deck")->required();
  run_cmd->add_option("-o,--output", out, "output directory")->required();
  run_cmd->add_flag("-q,--quiet", quiet, "no progress output");
  auto* check_cmd = app.add_subcommand("check", "validate a deck without solving");
  check_cmd->add_option("deck", deck, "YAML deck")->required();
  auto* ref_cmd = app.add_subcommand("reference", "print the deck reference (Markdown), generated from the declarations");
  tunica::FitCommand fit;
  auto* fit_cmd = app.add_subcommand("fit", "fit material constants to inflation–extension data (docs/fit.md)");
  fit_cmd->add_option("data", fit.data, "CSV data file (docs/fit.md, Data format)")->required();
  fit_cmd->add_option("-m,--model", fit.model, "fung2d, fung3d, neo_hookean or mooney_rivlin")->capture_default_str();
  fit_cmd->add_option("-o,--output", fit.output, "output directory")->required();
  fit_cmd->add_option("--specimen", fit.specimen, "specimen YAML file or inline map, instead of the file's '# specimen:' line");
  fit_cmd->add_option("--select", fit.select, "keep only rows with COLUMN=VALUE (repeatable), e.g. step=2")
      ->allow_extra_args(false);
  fit_cmd->add_option("--loss", fit.loss, "robust loss: none, huber, cauchy, soft_l1")->capture_default_str();
  fit_cmd->add_option("--loss-scale", fit.loss_scale, "where the robust loss bends (fraction of the data scale)")
      ->capture_default_str();
  fit_cmd->add_option("--starts", fit.starts, "use the first N built-in starting points (0 = all)")->capture_default_str();
  fit_cmd->add_option("--start", fit.start, "an extra starting point, e.g. '{c: 10 kPa, a1: 1, a2: 1, a4: 0}'");
  fit_cmd->add_option("--name", fit.material_name, "material name in material.yaml")->capture_default_str();
  fit_cmd->add_flag("--allow-non-monotone", fit.allow_non_monotone, "accept a size that turns back within one axial-stretch level");
  bool no_plot = false;
  fit_cmd->add_flag("--no-plot", no_plot, "do not run plot_fit.py");
  fit_cmd->add_flag("-q,--quiet", quiet, "no summary");
  std::string plan;
  auto* synth_cmd = app.add_subcommand("synthesize", "write synthetic inflation–extension data from a plan (docs/fit.md)");
  synth_cmd->group("");  // hidden: a tool for examples/fit and tests
  synth_cmd->add_option("plan", plan, "plan YAML")->required();
  synth_cmd->add_option("-o,--output", out, "CSV file to write")->required();
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version exit 0; a malformed command line is an input error (exit 2).
    const int code = app.exit(e);
    return code == 0 ? 0 : kInputErrorExit;
  }
  try {
    if (*run_cmd) return run(deck, out, quiet);
    if (*check_cmd) return check(deck);
    if (*fit_cmd) {
      fit.plot = !no_plot;
      return tunica::run_fit_command(fit, quiet ? nullptr : stdout);
    }
    if (*synth_cmd) return tunica::run_synthesize_command(plan, out, stdout);
    if (*ref_cmd) {
      std::fputs(tunica::deck_reference_markdown().c_str(), stdout);
      return 0;
    }
  } catch (const tunica::InputError& e) {
    std::fprintf(stderr, "tunica: input error: %s\n", e.what());
    return kInputErrorExit;
  } catch (const tunica::SolveError& e) {
    std::fprintf(stderr, "tunica: the run stopped: %s\n", e.what());
    return kSolveErrorExit;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tunica: error: %s\n", e.what());
    return kOtherErrorExit;
  }
  return 0;
}
