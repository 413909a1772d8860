// tunica-bench: speed of Tunica's Newton iterations on generated 3-D problems
// (docs/performance.md). Not a test: it times, it does not check beyond the
// closed form it prints for the sphere.
//
//   tunica-bench tube   --triangles N [--increments 6]
//   tunica-bench sphere --n N        [--increments 10]
//   common: [--solver auto|cholmod|umfpack|sparse_lu] [--symmetrized] [--threads T] [--csv FILE] [--paired]
//           [--residual-tolerance R] [--energy-tolerance E]   (Newton tests; deck defaults 1e-9, 1e-12)
//
// tube:   a closed circular Fung tube (the rat aorta of theory manual §12.1: R = 0.763 mm,
//         H = 0.122 mm), length 2πR, ends free to slide radially (held on the planes
//         x = 0 and y = 0 against rigid motion), circumferential/axial frame,
//         staggered triangles (around = along), stretched axially to λz = 1.3 with
//         40 mmHg in 4 increments (an in-vivo-like prestretch keeps the wall in tension), then
//         inflated to 120 mmHg in 6 increments.
// sphere: the thin neo-Hookean sphere octant of theory manual (8.3) (R = 1 mm, H = 0.01 mm,
//         μ = 1 MPa), n × n quads per patch, pressure to the closed-form value at λ = 1.2.
//
// Per run it prints the mean time per Newton iteration split into assembly,
// numeric factorization and solve, the iterations per increment, the peak
// resident memory, and the floor: one bare numeric factorization of the last
// tangent with the same solver (its symbolic analysis done beforehand).
#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <omp.h>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "fit/thin_tube.hpp"
#include "io/deck.hpp"
#include "solver/analysis.hpp"
#include "linalg/linear_solver.hpp"
#include "../tests/support/fung_tube.hpp"
#include "../tests/support/sphere_octant.hpp"

namespace {

double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

double peak_rss_mb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_maxrss) / 1024.0;  // kB on Linux
}

struct Options {
  std::string problem;
  long triangles = 10000;
  int n = 41;
  int increments = 0;
  std::string solver = "auto";
  bool symmetrized = false;
  double residual_tolerance = 1e-9;  // the deck defaults
  double energy_tolerance = 1e-12;
  int threads = 0;
  bool paired = false;
  std::string csv;
};

std::string solver_block(const Options& o) {
  return fmt::format(
      "solver: {{linear_solver: {}, pressure_stiffness: {}, residual_tolerance: {:.3g}, energy_tolerance: {:.3g}}}\n",
      o.solver, o.symmetrized ? "symmetrized" : "exact", o.residual_tolerance, o.energy_tolerance);
}

/// Tube deck: around = along so that the split quads are near-square (length 2πR).
std::string tube_deck(const Options& o, int& around) {
  around = std::max(4, 4 * static_cast<int>(std::lround(std::sqrt(o.triangles / 2.0) / 4)));  // x0, y0 sets
  return tunica::test::fung_tube_deck(around, solver_block(o), o.increments > 0 ? o.increments : 6);
}

std::string sphere_deck(const Options& o) {
  return tunica::test::sphere_octant_deck(fmt::format("bench neo-Hookean sphere octant n = {}", o.n), o.n,
                                          solver_block(o), o.increments > 0 ? o.increments : 10);
}

/// --paired: the bare factorizations timed next to the run's own. After each successful
/// factorization of the run, the same matrix is factorized again by a separate solver of the
/// same kind (its symbolic analysis done on its first call, untimed) and that numeric
/// factorization is timed: the floor measured at the same moment as the iteration, free of the
/// drift of a shared machine's speed between a run and a floor timed after it. Everything the
/// pairing adds is subtracted from the iteration's factorization time.
struct PairedLog {
  double added = 0;  ///< seconds the pairing added since the last iteration record
  double bare = 0;   ///< of which the timed bare factorizations
  int count = 0;
};

class PairedSolver final : public tunica::LinearSolver {
public:
  PairedSolver(std::unique_ptr<tunica::LinearSolver> inner, PairedLog& log) : inner_(std::move(inner)), log_(log) {}
  bool factorize(const tunica::TangentMatrix& K) override {
    const bool ok = inner_->factorize(K);
    if (!ok) return false;
    const double t0 = now();
    std::string name = inner_->used();
    auto& bare = bare_[name];
    if (!bare) {
      bare = tunica::make_linear_solver(name);
      bare->factorize(K);  // the symbolic analysis (and a first numeric factorization): untimed
    }
    const double t1 = now();
    bare->factorize(K);
    const double t2 = now();
    log_.bare += t2 - t1;
    log_.added += t2 - t0;
    ++log_.count;
    return true;
  }
  Eigen::VectorXd solve(const Eigen::VectorXd& b) override { return inner_->solve(b); }
  const char* used() const override { return inner_->used(); }
  bool reads_upper() const override { return inner_->reads_upper(); }  // the bare solver is of a kind the inner one uses

private:
  std::unique_ptr<tunica::LinearSolver> inner_;
  PairedLog& log_;
  std::map<std::string, std::unique_ptr<tunica::LinearSolver>> bare_;
};

/// Collects the Newton records of the run.
struct Recorder : tunica::AnalysisObserver {
  PairedLog paired;
  std::vector<double> paired_bare;  ///< per record: the bare factorizations timed next to it (--paired)
  std::vector<int> paired_count;    ///< per record: how many (more than one after a "+shift" retry)
  std::vector<tunica::IterationRecord> records;
  std::vector<int> iterations_per_increment;
  int cutbacks = 0;
  void on_iteration(const tunica::IncrementInfo&, const tunica::IterationRecord& r) override {
    records.push_back(r);
    // The run's own factorization only. (A tangent predictor that factorized but then gave up
    // reports no record: its pairing is not in this record's time, hence the bound.)
    records.back().factor_seconds -= std::min(paired.added, r.factor_seconds);
    paired_bare.push_back(paired.bare);
    paired_count.push_back(paired.count);
    paired = PairedLog{};
  }
  void on_cutback(const tunica::IncrementInfo&, const std::string&) override { ++cutbacks; }
  void on_increment(const tunica::Analysis&, const tunica::IncrementInfo& i) override {
    if (i.step > 0) iterations_per_increment.push_back(i.iterations);
  }
};

int run(const Options& o) {
  if (o.threads > 0) omp_set_num_threads(o.threads);
  int around = 0;
  const std::string deck = o.problem == "tube" ? tube_deck(o, around) : sphere_deck(o);
  const double t_start = now();
  const tunica::Model model = tunica::read_deck_text(deck, o.problem + ".yaml");
  tunica::Analysis analysis(model);
  const double t_setup = now() - t_start;
  Recorder rec;
  if (o.paired)
    analysis.set_solver_factory([&rec](const std::string& name) -> std::unique_ptr<tunica::LinearSolver> {
      return std::make_unique<PairedSolver>(tunica::make_linear_solver(name), rec.paired);
    });
  const double t_run0 = now();
  analysis.run(rec);
  const double t_run = now() - t_run0;

  // Per-iteration times: iterations followed by a solve.
  double assembly = 0, factor = 0, solve = 0;
  int solves = 0;
  std::string used;
  std::vector<double> times;  // per iteration: assembly + factorization + solve
  for (const auto& r : rec.records)
    if (!r.solver.empty()) {
      times.push_back(r.assembly_seconds + r.factor_seconds + r.solve_seconds);
      assembly += r.assembly_seconds;
      factor += r.factor_seconds;
      solve += r.solve_seconds;
      ++solves;
      used = r.solver;
    }
  // The floor: one bare numeric factorization of the last tangent with the solver the run used.
  const tunica::System& system = analysis.system();
  Eigen::VectorXd R;
  tunica::TangentMatrix K = system.tangent(true);  // both triangles: any solver's input, and the asymmetry
  system.assemble(analysis.displacement(), analysis.loads(), R, &K);
  const long nonzeros = static_cast<long>(system.pattern().nonZeros());
  double asym = 0, kmax = 0;
  {
    const tunica::SparseMatrix full = K.full();
    const tunica::SparseMatrix Kt = full.transpose();
    const tunica::SparseMatrix D = full - Kt;
    asym = D.coeffs().abs().maxCoeff();
    kmax = full.coeffs().abs().maxCoeff();
  }
  // The floor: bare numeric factorizations of the last tangent, with each solver the run used
  // (CHOLMOD for the symmetric positive definite iterations, UMFPACK for the others: a stress-free
  // start under pressure is indefinite). For each: the first call (with UMFPACK's symbolic analysis,
  // or CHOLMOD's copy of the system's) and the best of five more (two above 5 s).
  struct Bare {
    double first = 0, numeric = 1e300;
  };
  std::map<std::string, Bare> bare_by;  // by base solver name ("cholmod+shift" counts as cholmod)
  const auto base_name = [](const std::string& label) { return label.substr(0, label.find('+')); };
  for (const auto& r : rec.records)
    if (!r.solver.empty()) bare_by[base_name(r.solver)];
  for (auto& [name, b] : bare_by) {
    auto bare = tunica::make_linear_solver(name);
    const double t0 = now();
    bare->factorize(K);
    b.first = now() - t0;
    const int repeats = b.first < 5.0 ? 5 : 2;  // the best of several: timings on a shared machine vary by ±20 %
    for (int k = 0; k < repeats; ++k) {
      const double t1 = now();
      bare->factorize(K);
      b.numeric = std::min(b.numeric, now() - t1);
    }
  }
  const std::string main_solver = base_name(used);
  const double t_bare = bare_by.count(main_solver) ? bare_by[main_solver].numeric : 0.0;
  const double t_first = bare_by.count(main_solver) ? bare_by[main_solver].first : 0.0;
  // The floor of the run's own sequence: one bare factorization per iteration with that iteration's
  // solver, plus one symbolic analysis per solver (the retries of a "+shift" iteration count as overhead).
  double floor = 0;
  for (const auto& r : rec.records)
    if (!r.solver.empty()) floor += bare_by[base_name(r.solver)].numeric;
  for (const auto& [name, b] : bare_by) floor += std::max(0.0, b.first - b.numeric);

  // --paired: the mean iteration against the mean bare factorization timed next to it (per factorization).
  double paired_sum = 0;
  int paired_n = 0;
  for (std::size_t k = 0; k < rec.records.size(); ++k)
    if (!rec.records[k].solver.empty() && rec.paired_count[k] > 0) {
      paired_sum += rec.paired_bare[k];
      paired_n += rec.paired_count[k];
    }
  int max_its = 0;
  for (int i : rec.iterations_per_increment) max_its = std::max(max_its, i);
  const double per_iteration = (assembly + factor + solve) / solves;
  // The median iteration: the mean also carries the first factorization of each step (with a
  // symbolic analysis, or its copy) and UMFPACK factorizations of indefinite tangents (a stress-free start).
  std::sort(times.begin(), times.end());
  const double median = times.empty() ? 0.0 : times[times.size() / 2];
  long elements = 0;
  for (const auto& part : model.parts)
    for (const auto& b : part.blocks) elements += b.size();

  std::string accuracy = "-";
  if (o.problem == "sphere") {
    // Mean nodal radius against the closed form: error of p at the λ reached.
    double r = 0;
    for (int n = 0; n < model.num_nodes(); ++n) r += (model.X[n] + analysis.displacement().segment<3>(3 * n)).norm();
    const double l = r / model.num_nodes();
    const double p_closed = 2.0 * 0.01 * (1.0 / l - std::pow(l, -7));
    accuracy = fmt::format("{:+.3e}", tunica::test::sphere_octant_pressure() / p_closed - 1.0);
  } else {
    // Mean nodal radius against the thin-tube closed form (theory manual (8.1)) at 120 mmHg and λz = 1.3:
    // the error of the hoop stretch λθ = r/R reached.
    double r = 0;
    for (int n = 0; n < model.num_nodes(); ++n)
      r += (model.X[n] + analysis.displacement().segment<3>(3 * n)).head<2>().norm();
    const tunica::TubeGeometry g{0.763, 0.122};
    const double p = 120.0 * 101325.0 / 760.0 * 1e-6;  // 120 mmHg in N/mm²
    const double closed = tunica::hoop_stretch_at_pressure(*model.materials.at("aorta"), g, p, 1.3);
    accuracy = fmt::format("{:+.3e}", r / model.num_nodes() / g.R / closed - 1.0);
  }
  const std::string size = o.problem == "tube" ? fmt::format("{}x{}", around, around) : fmt::format("n={}", o.n);
  std::printf("%-7s %-9s elements %ld  nodes %d  unknowns %d  nonzeros %ld  threads %d  solver %s%s\n", o.problem.c_str(),
              size.c_str(), elements, model.num_nodes(), system.num_free(), nonzeros,
              omp_get_max_threads(), used.c_str(), o.symmetrized ? " (symmetrized)" : "");
  std::printf("  tangent asymmetry max|K - K^T| / max|K| = %.2e\n", asym / kmax);
  std::printf("  increments %zu  Newton iterations %d  max per increment %d  cut-backs %d\n",
              rec.iterations_per_increment.size(), solves, max_its, rec.cutbacks);
  std::printf("  per iteration %.4f s = assembly %.4f + factorization %.4f + solve %.4f  (assembly %.1f %%)\n",
              per_iteration, assembly / solves, factor / solves, solve / solves, 100.0 * assembly / solves / per_iteration);
  std::printf("  bare factorization %.4f s (first, with the solver's own setup: %.4f s)  iteration / factorization %.2f"
              " (median iteration %.4f s: %.2f)\n",
              t_bare, t_first, per_iteration / t_bare, median, median / t_bare);
  for (const auto& [name, b] : bare_by)
    if (name != main_solver) std::printf("  bare factorization with %s %.4f s (first %.4f s)\n", name.c_str(), b.numeric, b.first);
  if (o.paired)
    std::printf("  paired: bare factorization timed next to each iteration's, mean %.4f s over %d: iteration / "
                "paired factorization %.2f (peak RSS below includes the pairing's second factor)\n",
                paired_n ? paired_sum / paired_n : 0.0, paired_n,
                paired_n ? per_iteration / (paired_sum / paired_n) : 0.0);
  std::printf("  run's factorization floor %.2f s (each iteration's solver, one analysis each): iterations / floor %.2f\n",
              floor, (assembly + factor + solve) / floor);
  {  // where the factorization time went, by the solver each iteration used ("+shift": retried, linalg/perturbed_solve.hpp)
    std::map<std::string, std::pair<int, double>> by;
    for (const auto& r : rec.records)
      if (!r.solver.empty()) {
        by[r.solver].first += 1;
        by[r.solver].second += r.factor_seconds;
      }
    std::printf("  factorizations by solver:");
    for (const auto& [name, v] : by) std::printf("  %s %d (mean %.4f s)", name.c_str(), v.first, v.second / v.first);
    std::printf("\n");
  }
  std::printf("  setup %.2f s  run %.2f s  peak RSS %.0f MB  %s vs closed form %s\n", t_setup, t_run, peak_rss_mb(),
              o.problem == "sphere" ? "p error" : "hoop stretch error", accuracy.c_str());
  if (!o.csv.empty()) {
    const bool header = !std::ifstream(o.csv).good();
    std::ofstream csv(o.csv, std::ios::app);
    if (header)
      csv << "problem,size,elements,nodes,unknowns,nonzeros,threads,solver,symmetrized,residual_tolerance,"
             "energy_tolerance,increments,iterations,"
             "max_iterations_per_increment,cutbacks,iteration_s,assembly_s,factor_s,solve_s,bare_factor_s,"
             "first_factor_s,setup_s,run_s,peak_rss_MB,closed_form_error,median_iteration_s,floor_s,iterations_over_floor,paired_bare_factor_s\n";
    csv << fmt::format("{},{},{},{},{},{},{},{},{},{:.3g},{:.3g},{},{},{},{},{:.5g},{:.5g},{:.5g},{:.5g},{:.5g},{:.5g},{:.4g},{:.4g},{:.0f},{},{:.5g},{:.5g},{:.4f},{:.5g}\n",
                       o.problem, size, elements, model.num_nodes(), system.num_free(), nonzeros,
                       omp_get_max_threads(), used, o.symmetrized ? 1 : 0, o.residual_tolerance, o.energy_tolerance,
                       rec.iterations_per_increment.size(), solves,
                       max_its, rec.cutbacks, per_iteration, assembly / solves, factor / solves, solve / solves, t_bare,
                       t_first, t_setup, t_run, peak_rss_mb(), accuracy, median, floor,
                       (assembly + factor + solve) / floor, paired_n ? paired_sum / paired_n : 0.0);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"tunica-bench: time per Newton iteration on generated 3-D membrane problems"};
  Options o;
  app.add_option("problem", o.problem, "tube or sphere")->required()->check(CLI::IsMember({"tube", "sphere"}));
  app.add_option("--triangles", o.triangles, "tube: about this many triangles")->check(CLI::Range(100L, 100000000L));
  app.add_option("--n", o.n, "sphere: octant patches of n × n quads")->check(CLI::Range(2, 10000));
  app.add_option("--increments", o.increments, "load increments (tube 6, sphere 10)")->check(CLI::Range(1, 1000));
  app.add_option("--solver", o.solver, "linear solver")->check(CLI::IsMember({"auto", "cholmod", "umfpack", "sparse_lu"}));
  app.add_flag("--symmetrized", o.symmetrized, "symmetrized pressure stiffness");
  app.add_option("--residual-tolerance", o.residual_tolerance, "Newton: ‖R‖/‖R₀‖ (deck default 1e-9)")
      ->check(CLI::PositiveNumber);
  app.add_option("--energy-tolerance", o.energy_tolerance, "Newton: |Δu·R| relative to the first (deck default 1e-12)")
      ->check(CLI::PositiveNumber);
  app.add_flag("--paired", o.paired, "time a bare factorization of the same matrix next to each of the run's");
  app.add_option("--threads", o.threads, "threads of the element loops")->check(CLI::Range(1, 1024));
  app.add_option("--csv", o.csv, "append a row to this CSV file");
  CLI11_PARSE(app, argc, argv);
  try {
    return run(o);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tunica-bench: %s\n", e.what());
    return 1;
  }
}
