// tunica-bench: speed of Tunica's Newton iterations on generated 3-D problems
// (docs/performance.md). Not a test: it times, it does not check beyond the
// closed form it prints for the sphere.
//
//   tunica-bench tube   --triangles N [--increments 6] [--prestretch-increments 4]
//   tunica-bench sphere --n N        [--increments 10] [--element quad4|tri3|tri6] [--lattice cube|octahedron]
//                                    [--write-deck DIR]
//   common: [--solver auto|cholmod|umfpack|sparse_lu] [--symmetrized] [--threads T] [--csv FILE] [--paired]
//           [--residual-tolerance R] [--energy-tolerance E]   (Newton tests; deck defaults 1e-9, 1e-12)
//
// tube:   a closed circular Fung tube (the rat aorta of theory manual §12.1: R = 0.763 mm,
//         H = 0.122 mm), length 2πR, ends free to slide radially (held on the planes
//         x = 0 and y = 0 against rigid motion), circumferential/axial frame,
//         staggered triangles (around = along), stretched axially to λz = 1.3 with
//         40 mmHg in 4 increments (an in-vivo-like prestretch keeps the wall in tension), then
//         inflated to 120 mmHg in 6 increments (--prestretch-increments, --increments).
// sphere: the thin neo-Hookean sphere octant of theory manual (8.3) (R = 1 mm, H = 0.01 mm,
//         μ = 1 MPa), pressure to the closed-form value at λ = 1.2. --element quad4 (default): the
//         deck's octant generator, n × n quads per patch (3n²); tri3 / tri6: 3-node / 6-node
//         triangles written as a Gmsh 2.2 file, mid-edge nodes on the exact sphere, on the
//         --lattice cube (the same patches, each quad split in two: 6n²; default) or octahedron
//         (the face x + y + z = R projected: n²) (tests/support/sphere_octant.hpp). The error
//         printed is p's against the closed form at the mean radius of all nodes (mid-edge nodes
//         included), the measure of bench/peers/ for every code.
//         --write-deck DIR writes DIR/sphere.yaml (and DIR/octant.msh) for `tunica run` and exits:
//         one VTK frame of the reference state and one of the last increment (raw binary), the
//         applied pressure in history.csv (bench/peers/equal_accuracy.py).
//
// Per run it prints the mean time per Newton iteration split into assembly,
// numeric factorization and solve, the iterations per increment, the peak
// resident memory, and the floor: one bare numeric factorization of the last
// tangent with the same solver (its symbolic analysis done beforehand).
#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "fit/thin_tube.hpp"
#include "io/deck.hpp"
#include "linalg/compute_threads.hpp"
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
  int prestretch_increments = 4;  // tube: the prestretch step's
  std::string element = "quad4";
  std::string lattice = "cube";
  std::string write_deck;
  std::string solver = "auto";
  bool symmetrized = false;
  double residual_tolerance = 1e-9;  // the deck defaults
  double energy_tolerance = 1e-12;
  std::string reuse;  // reuse_factorization; empty: the deck default
  int threads = 0;
  bool paired = false;
  std::string csv;
};

std::string solver_block(const Options& o) {
  return fmt::format(
      "solver: {{linear_solver: {}, pressure_stiffness: {}, residual_tolerance: {:.3g}, energy_tolerance: {:.3g}{}}}\n",
      o.solver, o.symmetrized ? "symmetrized" : "exact", o.residual_tolerance, o.energy_tolerance,
      o.reuse.empty() ? "" : ", reuse_factorization: " + o.reuse);
}

/// Tube deck: around = along so that the split quads are near-square (length 2πR).
std::string tube_deck(const Options& o, int& around) {
  around = std::max(4, 4 * static_cast<int>(std::lround(std::sqrt(o.triangles / 2.0) / 4)));  // x0, y0 sets
  return tunica::test::fung_tube_deck(around, solver_block(o), o.increments > 0 ? o.increments : 6,
                                      o.prestretch_increments);
}

/// The sphere octant's deck; a triangle mesh is written to `dir`/octant.msh (the deck names it by
/// its path relative to the deck when `relative`, else by its absolute path).
std::string sphere_deck(const Options& o, const std::filesystem::path& dir, bool relative, const std::string& output) {
  namespace t = tunica::test;
  t::OctantMesh mesh;
  if (o.element == "quad4") {
    mesh = t::octant_generator_mesh(o.n);
  } else {
    const std::filesystem::path msh = dir / "octant.msh";
    mesh = t::octant_msh_mesh(msh.string(), relative ? std::string("octant.msh") : std::filesystem::absolute(msh).string(),
                              o.n, o.element == "tri6" ? 2 : 1, t::octant_lattice(o.lattice));
  }
  const std::string title = fmt::format("bench neo-Hookean sphere octant, {} n = {}{}", o.element, o.n,
                                        o.element == "quad4" ? "" : " (" + o.lattice + " lattice)");
  return t::sphere_octant_deck(title, mesh, solver_block(o), o.increments > 0 ? o.increments : 10, output);
}

std::string size_label(const Options& o, int around) {
  if (o.problem == "tube") return fmt::format("{}x{}", around, around);
  if (o.element == "quad4") return fmt::format("n={}", o.n);
  return fmt::format("{}-{}-n={}", o.element, o.lattice, o.n);
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
  tunica::set_compute_threads(o.threads);
  std::printf("threads: %s\n", tunica::compute_threads_summary().c_str());
  std::fflush(stdout);
  int around = 0;
  std::filesystem::path scratch;
  if (o.problem == "sphere" && o.element != "quad4") {
    scratch = std::filesystem::temp_directory_path() / fmt::format("tunica-bench-{}", ::getpid());
    std::filesystem::create_directories(scratch);
  }
  const std::string deck = o.problem == "tube" ? tube_deck(o, around) : sphere_deck(o, scratch, false, "{vtk: false}");
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
  int solves = 0, factorizations = 0;
  std::string used;
  std::vector<double> times;  // per iteration: assembly + factorization + solve
  for (const auto& r : rec.records)
    if (!r.solver.empty()) {
      times.push_back(r.assembly_seconds + r.factor_seconds + r.solve_seconds);
      assembly += r.assembly_seconds;
      factor += r.factor_seconds;
      solve += r.solve_seconds;
      ++solves;
      if (r.solver.find(tunica::kReusedFactorization) == std::string::npos) {
        ++factorizations;
        used = r.solver;
      }
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
  // The floor of the run's own sequence: one bare factorization per factorization the run made, with
  // that iteration's solver (a correction solved with an earlier factorization adds none), plus one
  // symbolic analysis per solver (the retries of a "+shift" iteration count as overhead).
  double floor = 0;
  for (const auto& r : rec.records)
    if (!r.solver.empty() && r.solver.find(tunica::kReusedFactorization) == std::string::npos)
      floor += bare_by[base_name(r.solver)].numeric;
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
    const Eigen::VectorXd& u = analysis.displacement();
    accuracy = fmt::format("{:+.3e}", tunica::test::sphere_octant_p_error(model.num_nodes(), [&](int n) {
                             return Eigen::Vector3d(model.X[n] + u.segment<3>(3 * n));
                           }));
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
  if (!scratch.empty()) std::filesystem::remove_all(scratch);
  const std::string size = size_label(o, around);
  std::printf("%-7s %-9s elements %ld  nodes %d  unknowns %d  nonzeros %ld  threads %d  solver %s%s\n", o.problem.c_str(),
              size.c_str(), elements, model.num_nodes(), system.num_free(), nonzeros,
              tunica::compute_threads(), used.c_str(), o.symmetrized ? " (symmetrized)" : "");
  std::printf("  tangent asymmetry max|K - K^T| / max|K| = %.2e\n", asym / kmax);
  std::printf("  increments %zu  Newton iterations %d  factorizations %d  max per increment %d  cut-backs %d\n",
              rec.iterations_per_increment.size(), solves, factorizations, max_its, rec.cutbacks);
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
  std::printf("  run's factorization floor %.2f s (a bare factorization for each of the run's %d, with its solver; one "
              "analysis each): iterations / floor %.2f\n",
              floor, factorizations, (assembly + factor + solve) / floor);
  {  // where the factorization time went, by the solver each iteration used ("+shift": retried, linalg/perturbed_solve.hpp)
    std::map<std::string, std::pair<int, double>> by;
    for (const auto& r : rec.records)
      if (!r.solver.empty()) {
        by[r.solver].first += 1;
        by[r.solver].second += r.factor_seconds;
      }
    std::printf("  corrections by solver (+reused: an earlier factorization, none new):");
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
             "first_factor_s,setup_s,run_s,peak_rss_MB,closed_form_error,median_iteration_s,floor_s,iterations_over_floor,paired_bare_factor_s,factorizations,reuse_factorization\n";
    csv << fmt::format("{},{},{},{},{},{},{},{},{},{:.3g},{:.3g},{},{},{},{},{:.5g},{:.5g},{:.5g},{:.5g},{:.5g},{:.5g},{:.4g},{:.4g},{:.0f},{},{:.5g},{:.5g},{:.4f},{:.5g},{},{}\n",
                       o.problem, size, elements, model.num_nodes(), system.num_free(), nonzeros,
                       tunica::compute_threads(), used, o.symmetrized ? 1 : 0, o.residual_tolerance, o.energy_tolerance,
                       rec.iterations_per_increment.size(), solves,
                       max_its, rec.cutbacks, per_iteration, assembly / solves, factor / solves, solve / solves, t_bare,
                       t_first, t_setup, t_run, peak_rss_mb(), accuracy, median, floor,
                       (assembly + factor + solve) / floor, paired_n ? paired_sum / paired_n : 0.0, factorizations,
                       o.reuse.empty() ? "last" : o.reuse);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"tunica-bench: time per Newton iteration on generated 3-D membrane problems"};
  Options o;
  app.add_option("problem", o.problem, "tube or sphere")->required()->check(CLI::IsMember({"tube", "sphere"}));
  app.add_option("--triangles", o.triangles, "tube: about this many triangles")->check(CLI::Range(100L, 100000000L));
  app.add_option("--n", o.n, "sphere: elements per patch edge (quad4: 3n² quads; tri on the cube lattice: 6n², octahedron: n²)")
      ->check(CLI::Range(1, 10000));
  app.add_option("--element", o.element, "sphere: quad4 (the octant generator), tri3 or tri6 (a Gmsh file)")
      ->check(CLI::IsMember({"quad4", "tri3", "tri6"}));
  app.add_option("--lattice", o.lattice, "sphere, tri3/tri6: the cube-projection patches or the octahedron face")
      ->check(CLI::IsMember({"cube", "octahedron"}));
  app.add_option("--write-deck", o.write_deck, "sphere: write DIR/sphere.yaml (and octant.msh) for `tunica run`, and exit");
  app.add_option("--increments", o.increments, "load increments (tube: of the inflation, 6; sphere 10)")
      ->check(CLI::Range(1, 1000));
  app.add_option("--prestretch-increments", o.prestretch_increments, "tube: increments of the prestretch step")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  app.add_option("--solver", o.solver, "linear solver")->check(CLI::IsMember({"auto", "cholmod", "umfpack", "sparse_lu"}));
  app.add_flag("--symmetrized", o.symmetrized, "symmetrized pressure stiffness");
  app.add_option("--residual-tolerance", o.residual_tolerance, "Newton: ‖R‖/‖R₀‖ (deck default 1e-9)")
      ->check(CLI::PositiveNumber);
  app.add_option("--energy-tolerance", o.energy_tolerance, "Newton: |Δu·R| relative to the first (deck default 1e-12)")
      ->check(CLI::PositiveNumber);
  app.add_option("--reuse-factorization", o.reuse, "Newton: when to reuse an earlier factorization (deck default last)")
      ->check(CLI::IsMember({"last", "basin", "never"}));
  app.add_flag("--paired", o.paired, "time a bare factorization of the same matrix next to each of the run's");
  app.add_option("--threads", o.threads,
                 "threads to compute on (default: OMP_NUM_THREADS, else the CPUs this process may run on): the element "
                 "loops take them, the BLAS and CHOLMOD one")->check(CLI::Range(1, 1024));
  app.add_option("--csv", o.csv, "append a row to this CSV file");
  CLI11_PARSE(app, argc, argv);
  if (o.threads <= 0) o.threads = tunica::default_compute_threads();
  tunica::start_with_thread_environment(o.threads, argv);
  try {
    if (!o.write_deck.empty()) {
      if (o.problem != "sphere") throw std::invalid_argument("--write-deck: sphere only");
      const std::filesystem::path dir(o.write_deck);
      std::filesystem::create_directories(dir);
      const std::string deck = sphere_deck(
          o, dir, true,
          "\n  vtk_format: binary\n  vtk_every: 1000000\n  history:\n    - {quantity: pressure, load: inflation}");
      std::ofstream(dir / "sphere.yaml") << deck;
      const tunica::Model model = tunica::read_deck_text(deck, (dir / "sphere.yaml").string());
      const tunica::Analysis analysis(model);
      long elements = 0;
      for (const auto& part : model.parts)
        for (const auto& b : part.blocks) elements += b.size();
      std::printf("%s: elements %ld nodes %d unknowns %d\n", (dir / "sphere.yaml").string().c_str(), elements,
                  model.num_nodes(), analysis.system().num_free());
      return 0;
    }
    return run(o);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tunica-bench: %s\n", e.what());
    return 1;
  }
}
