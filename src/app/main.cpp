// The `tunica` command line: run, check, reference and fit.
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <map>
#include <memory>
#include <tuple>

#include "fit/fit_command.hpp"
#include "io/deck.hpp"
#include "io/reference.hpp"
#include "linalg/compute_threads.hpp"
#include "core/printable.hpp"
#include "assembly/pressure_load_checks.hpp"
#include "assembly/volume_control_checks.hpp"
#include "mesh/geo_mesher.hpp"
#include "mesh/gmsh_reader.hpp"
#include "output/atomic_file.hpp"
#include "output/output_lock.hpp"
#include "output/restart_file.hpp"
#include "output/restart_fit.hpp"
#include "output/run_writer.hpp"
#include "output/stop_signal.hpp"
#include "solver/analysis.hpp"

namespace {

/// A message for the terminal (core/printable.hpp): no byte quoted from an input file (a
/// control sequence in a physical group's name) reaches it raw.
std::string for_terminal(const std::string& message) { return tunica::terminal_safe(message); }

constexpr int kInputErrorExit = 2;
constexpr int kSolveErrorExit = 3;
constexpr int kOtherErrorExit = 4;

/// What the model reads as valid but is likely not meant (assembly/pressure_load_checks.hpp);
/// returns how many warnings were printed.
int print_warnings(const tunica::System& system) {
  int count = 0;
  const auto print = [&](const std::string& w) {
    std::fprintf(stderr, "tunica: warning: %s\n", for_terminal(w).c_str());
    ++count;
  };
  for (const std::string& w : system.model().warnings) print(w);
  for (const std::string& w : tunica::pressure_load_warnings(system)) print(w);
  for (const std::string& w : tunica::volume_control_warnings(system)) print(w);
  return count;
}

int run(const std::string& deck, std::string out, const std::string& restart, bool quiet,
        const tunica::ReadOptions& options) {
  const tunica::Model model = tunica::read_deck(deck, options);
  if (out.empty() && restart.empty()) throw tunica::InputError({deck, 0, 0, ""}, "the output directory (-o) is empty");
  std::unique_ptr<tunica::RestartRecord> resume;
  if (!restart.empty()) {
    if (!out.empty() && std::filesystem::path(out) != std::filesystem::path(restart))
      throw tunica::InputError({deck, 0, 0, ""}, "--restart DIR continues the run in DIR: leave out -o or give the same directory");
    out = restart;
  }
  // One run per folder, for the whole run: taken before anything in the folder is read or written.
  const tunica::OutputLock lock(out, /*create=*/restart.empty());
  if (!restart.empty()) {
    const std::string file = restart + "/restart.txt";
    // A folder without a run's restart file: what --restart needs, and how to start the run there.
    if (std::error_code ec; !std::filesystem::exists(file, ec))
      throw tunica::InputError(
          {file, 0, 0, ""},
          fmt::format("cannot read the restart file: no such file: --restart continues a run in the folder that run "
                      "wrote (it writes restart.txt after each converged increment), and {} holds none. Start the run "
                      "there first: tunica run {} -o {}",
                      restart, deck, restart));
    resume = std::make_unique<tunica::RestartRecord>(tunica::read_restart(file));
    if (const std::string warning = tunica::check_restart_fits(model, *resume, file); !warning.empty())
      std::fprintf(stderr, "tunica: warning: %s\n", for_terminal(warning).c_str());
    if (!quiet)
      std::printf("resuming from step %d, increment %d (step fraction %.6g) in %s\n", resume->checkpoint.step + 1,
                  resume->checkpoint.increment, resume->checkpoint.fraction, restart.c_str());
  }
  if (!quiet) std::printf("threads: %s\n", tunica::compute_threads_summary().c_str());
  tunica::RunWriter writer(model, out, quiet ? nullptr : stdout, resume.get());
  tunica::Analysis analysis(model);
  tunica::check_volume_control_sides(analysis.system());
  const int warnings = print_warnings(analysis.system());
  tunica::install_stop_handlers();
  const auto t0 = std::chrono::steady_clock::now();
  try {
    analysis.run(writer, resume ? &resume->checkpoint : nullptr);
  } catch (const tunica::SolveError& e) {
    writer.write_newton_log();  // keep the failed attempts for diagnosis
    writer.finish(analysis);    // the last converged state: its frame and its checkpoint
    // A stop without a hint of its own, in a deck that drew warnings: they are the first suspects.
    if (warnings > 0 && std::string(e.what()).find(" Hint:") == std::string::npos)
      throw tunica::SolveError(fmt::format(
          "{} Hint: the deck drew {} warning(s) before the run (above); a stop without other evidence often follows "
          "from one of them (a boundary on the wrong set, a load on the wrong side): check them first.",
          e.what(), warnings));
    throw;
  } catch (const tunica::Interrupted& e) {
    const int sig = tunica::stop_signal();
    std::fprintf(stderr, "tunica: interrupted by signal %d: %s; every converged increment is kept. Continue with:\n"
                         "  tunica run %s --restart %s\n", sig, e.what(), deck.c_str(), out.c_str());
    return 128 + sig;
  }
  writer.note_untouched_contacts();
  if (!quiet)
    std::printf("done in %.3f s; results in %s\n",
                std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), out.c_str());
  return 0;
}

int check(const std::string& deck, const tunica::ReadOptions& options) {
  const tunica::Model model = tunica::read_deck(deck, options);
  const tunica::System system(model);
  tunica::check_volume_control_sides(system);
  int elements = 0;
  for (const auto& p : model.parts) elements += p.num_elements();
  std::printf("%s: valid deck: %zu material(s), %zu part(s), %d node(s), %d element(s), %zu boundary set(s), "
              "%zu load(s), %zu step(s), %zu history column(s)\n",
              deck.c_str(), model.materials.size() + model.solid_materials.size(), model.parts.size(), model.num_nodes(), elements,
              model.boundaries.size(), model.loads.size(), model.steps.size(), model.output.history.size());
  std::fflush(stdout);
  print_warnings(system);
  return 0;
}

/// `tunica mesh`: meshes a Gmsh script into a .msh file that Tunica's reader accepts.
int mesh(const std::string& geo, const std::string& msh, const tunica::GeoMeshFormat& format) {
  namespace fs = std::filesystem;
  const auto fail = [](const std::string& file, const std::string& what) {
    throw tunica::InputError({file, 0, 0, ""}, what);
  };
  if (!tunica::is_gmsh_script(geo))
    fail(geo, "tunica mesh runs a Gmsh script, and this file is not named .geo (a .msh needs no meshing: decks "
              "read it as it is)");
  if (fs::path(msh).extension() != ".msh") fail(msh, "the output of tunica mesh must be named .msh");
  std::error_code ec;
  if (fs::exists(msh, ec) && !fs::is_regular_file(msh, ec))
    fail(msh, "the output exists and is not a regular file (a device, pipe, socket or directory)");
  if (fs::exists(msh, ec) && fs::equivalent(geo, msh, ec)) fail(msh, "the output is the script itself");
  // On failure the output is not touched: an earlier mesh there stays as it was, and a deck that
  // names it reads that one, which the message says.
  const std::string untouched =
      fs::exists(msh, ec) ? fmt::format("; nothing was written: the earlier {} is left unchanged (a deck that names it "
                                        "still reads that earlier mesh)",
                                        msh)
                          : fmt::format("; nothing was written ({} was not created)", msh);
  std::string bytes;
  try {
    bytes = tunica::mesh_geo_script(geo, format);
  } catch (const tunica::InputError& e) {
    throw tunica::InputError(e.where(), e.reason() + untouched);
  }
  // What it wrote must be a mesh that decks can use: refused here, not when a deck reads it.
  try {
    tunica::read_script_mesh(geo, bytes);
  } catch (const tunica::InputError& e) {
    throw tunica::InputError(e.where(), e.reason() + untouched);
  }
  tunica::write_file_atomically(msh, bytes);
  std::printf("%s: meshed into %s\n", geo.c_str(), msh.c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  // Progress and messages written to a pipe whose reader has gone (`tunica run … | head`) are dropped
  // (the write fails with EPIPE) rather than ending the run by SIGPIPE: the run and its files finish.
  std::signal(SIGPIPE, SIG_IGN);
  CLI::App app{"Tunica: large-strain analysis of thin incompressible hyperelastic membranes"};
  app.set_version_flag("--version", std::string(TUNICA_VERSION));
  app.require_subcommand(1);
  std::string deck, out, restart;
  bool quiet = false;
  auto* run_cmd = app.add_subcommand("run", "solve a deck and write results");
  run_cmd->add_option("deck", deck, "YAML deck")->required();
  auto* out_opt = run_cmd->add_option("-o,--output", out, "output directory");
  auto* restart_opt = run_cmd->add_option("--restart", restart,
                                          "continue the run in DIR from its last converged increment (writes into DIR)");
  run_cmd->callback([&] {
    if (out_opt->count() == 0 && restart_opt->count() == 0) throw CLI::RequiredError("-o,--output or --restart");
  });
  run_cmd->add_flag("-q,--quiet", quiet, "no progress output");
  tunica::ReadOptions read_options;
  const char* scripts_help = "mesh the Gmsh scripts (.geo) the deck names; a script can run commands";
  run_cmd->add_flag("--allow-scripts", read_options.allow_scripts, scripts_help);
  int threads = 0;
  run_cmd->add_option("-j,--threads", threads,
                      "threads to compute on (default: OMP_NUM_THREADS, else the CPUs this process may run on): the "
                      "element loops take them, the BLAS and CHOLMOD one; results do not depend on it")
      ->check(CLI::Range(1, 1024));
  auto* check_cmd = app.add_subcommand("check", "validate a deck without solving");
  check_cmd->add_option("deck", deck, "YAML deck")->required();
  check_cmd->add_flag("--allow-scripts", read_options.allow_scripts, scripts_help);
  std::string geo, msh;
  tunica::GeoMeshFormat msh_format;
  auto* mesh_cmd = app.add_subcommand("mesh", "mesh a Gmsh script (.geo) into a .msh file, which decks then read as data; "
                                              "the script runs, and can run commands");
  mesh_cmd->add_option("script", geo, "Gmsh script (.geo)")->required();
  mesh_cmd->add_option("-o,--output", msh, ".msh file to write")->required();
  mesh_cmd->add_option("--msh-version", msh_format.version, "format version, 4.1 or 2.2")
      ->check(CLI::IsMember({4.1, 2.2}))
      ->capture_default_str();
  mesh_cmd->add_flag("--binary", msh_format.binary, "binary instead of ASCII");
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
    const int compute_threads = threads > 0 ? threads : tunica::default_compute_threads();
    // The commands that compute (assembly, factorizations, fits) start again with the thread limits
    // in the environment (linalg/compute_threads.hpp).
    if (*run_cmd || *check_cmd || *fit_cmd) tunica::start_with_thread_environment(compute_threads, argv);
    tunica::set_compute_threads(compute_threads);
    if (*run_cmd) {
      return run(deck, out, restart, quiet, read_options);
    }
    if (*check_cmd) return check(deck, read_options);
    if (*mesh_cmd) return mesh(geo, msh, msh_format);
    if (*fit_cmd) {
      fit.plot = !no_plot;
      return tunica::run_fit_command(fit, quiet ? nullptr : stdout);
    }
    if (*synth_cmd) return tunica::run_synthesize_command(plan, out, stdout);
    if (*ref_cmd) {
      std::fputs(tunica::deck_reference_markdown().c_str(), stdout);
      return 0;
    }
  } catch (const tunica::MeshingInterrupted& e) {
    // Only the deck or the script was being read: nothing was written yet.
    std::fprintf(stderr, "tunica: %s; nothing was written\n", for_terminal(e.what()).c_str());
    return 128 + e.signal();
  } catch (const tunica::InputError& e) {
    std::fprintf(stderr, "tunica: input error: %s\n", for_terminal(e.what()).c_str());
    return kInputErrorExit;
  } catch (const tunica::SolveError& e) {
    std::fprintf(stderr, "tunica: the run stopped: %s\n", for_terminal(e.what()).c_str());
    return kSolveErrorExit;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tunica: error: %s\n", for_terminal(e.what()).c_str());
    return kOtherErrorExit;
  }
  return 0;
}
