// The prestress inverse step (`type: inverse`, `method: prestress`; theory manual §13.2): the imaged
// geometry stays the reference and each Gauss point carries the prestretch P that balances the
// loads, (13.20)–(13.24).
//  - Agreement: imaged from a forward run, the prestressed imaged state has the forward run's
//    stresses there, and a forward step back to zero load reaches the forward run's reference
//    (axisymmetric neo-Hookean sphere, 3-D octant of quadrilaterals, the rat aorta's Fung tube at an
//    axial stretch of 1, compared with the direct method); the iterations and their distances are
//    printed.
//  - Its keys, its refusal of a prescribed value, and a completed prestress run resumed with a
//    forward step added (in-process and with `tunica run --restart`).
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>

#include "../support/capture.hpp"
#include "../support/cli.hpp"
#include "../support/scratch.hpp"
#include "core/errors.hpp"

using namespace tunica;
using namespace tunica::test;

namespace {

const std::string kAxisym = std::string(TUNICA_SOURCE_DIR) + "/examples/balloon-sphere.yaml";
const std::string k3d = std::string(TUNICA_SOURCE_DIR) + "/examples/balloon-sphere-3d.yaml";
const std::string kRatInverse = std::string(TUNICA_SOURCE_DIR) + "/examples/rat-aorta-inverse.yaml";
const char* kTight = "\nsolver: {residual_tolerance: 1e-12}\n";

std::string axisym_deck(int elements, double p, int increments) {
  std::string t = replace(read_text(kAxisym), "elements: 100", "elements: " + std::to_string(elements));
  t = replace(t, "increments: 20", "increments: " + std::to_string(increments));
  return replace(t, "set: {inflation: 0.0118 MPa}", fmt::format("set: {{inflation: {} MPa}}", p)) + kTight;
}

std::string octant_deck(int n, double p) {
  std::string t = replace(read_text(k3d), "n: 8}", "n: " + std::to_string(n) + "}");
  t = replace(t, "increments: 40\n    volume_control: {load: inflation, volume: 4.45 mm^3}   # 8.5 × π/6 mm³",
              fmt::format("increments: 10\n    set: {{inflation: {} MPa}}", p));
  return t + kTight;
}

/// `deck`'s step `step_name` made a prestress inverse step with `keys`, and a forward step `unload`
/// to zero pressure after it.
std::string prestress_of(const std::string& deck, const std::string& step_name, const std::string& keys) {
  std::string t = replace(deck, "name: " + step_name,
                          "name: prestress\n    type: inverse\n    method: prestress" +
                              (keys.empty() ? std::string() : "\n    " + keys));
  return replace(t, "\noutput:", "\n  - name: unload\n    increments: 8\n    set: {inflation: 0 MPa}\noutput:");
}

std::vector<Eigen::Vector3d> positions(const Model& m, const Eigen::VectorXd& u) {
  std::vector<Eigen::Vector3d> x = m.X;
  const int d = m.dofs_per_node();
  for (int n = 0; n < m.num_nodes(); ++n)
    for (int c = 0; c < d; ++c) x[n](c) += u(d * n + c);
  return x;
}

double max_distance(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b) {
  double d = 0;
  for (std::size_t n = 0; n < a.size(); ++n) d = std::max(d, (a[n] - b[n]).norm());
  return d;
}

double max_norm(const std::vector<Eigen::Vector3d>& a) {
  double d = 0;
  for (const auto& x : a) d = std::max(d, x.norm());
  return d;
}

/// The Gauss-point Cauchy stresses (in global axes) of every membrane part at the current state.
std::vector<Eigen::Matrix3d> stresses(const Analysis& a) {
  std::vector<Eigen::Matrix3d> out;
  for (int p = 0; p < static_cast<int>(a.model().parts.size()); ++p)
    for (const MembranePoint& q : a.system().points(a.displacement(), p, a.checkpoint().step)) out.push_back(q.cauchy);
  return out;
}

/// Keeps the fixed-point records, the end-of-step states of step 1 and the last state.
class PrestressCapture final : public AnalysisObserver {
public:
  std::vector<FixedPointRecord> records;
  std::vector<Eigen::Matrix3d> step1_stress;
  std::vector<Eigen::Vector3d> step1_x;
  Checkpoint step1;
  void on_increment(const Analysis& a, const IncrementInfo& i) override {
    if (i.step == 1 && i.fraction >= 1.0 - 1e-12) {
      step1_stress = stresses(a);
      step1_x = positions(a.model(), a.displacement());
      step1 = a.checkpoint();
    }
  }
  void on_fixed_point(const FixedPointRecord& r) override {
    records.push_back(r);
  }
};

void print_history(const char* what, const std::vector<FixedPointRecord>& records) {
  std::printf("%s: %zu prestress solves\n", what, records.size());
  for (const FixedPointRecord& r : records)
    std::printf("  solve %2d: max |u| %.3e, rms %.3e, %d increment(s), %d Newton iterations, %d cut-back(s), %.3f s\n",
                r.iteration, r.max_distance, r.rms_distance, r.increments, r.newton_iterations, r.cutbacks, r.seconds);
}

struct Comparison {
  double stress = 0;    ///< max |σ_prestress − σ_forward| / max |σ_forward| at the imaged state
  double unloaded = 0;  ///< max |x_unloaded − X| / max |X|, X the forward run's reference
  double imaged = 0;    ///< max |x_prestress − x̂| / max |X| at the end of the prestress step
  std::size_t solves = 0;
  double seconds = 0;
};

/// A forward run of `forward` (its one step `step_name`) gives x̂ and its stresses; the prestress
/// step from x̂ and the unloading after it are compared with them and with the forward reference.
Comparison compare(const std::string& forward, const std::string& file, const std::string& step_name,
                   const std::string& keys, const char* what) {
  const Model f = read_deck_text(forward, file);
  Capture cap;
  Analysis a(f);
  a.run(cap);
  const std::vector<Eigen::Vector3d> imaged = positions(f, a.displacement());
  const std::vector<Eigen::Matrix3d> sigma = stresses(a);
  Model m = read_deck_text(prestress_of(forward, step_name, keys), file);
  m.X = imaged;
  PrestressCapture pc;
  Analysis b(m);
  const auto t0 = std::chrono::steady_clock::now();
  b.run(pc);
  Comparison c;
  c.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  c.solves = pc.records.size();
  double worst = 0, scale = 0;
  EXPECT_EQ(pc.step1_stress.size(), sigma.size());
  for (std::size_t q = 0; q < std::min(sigma.size(), pc.step1_stress.size()); ++q) {
    worst = std::max(worst, (pc.step1_stress[q] - sigma[q]).cwiseAbs().maxCoeff());
    scale = std::max(scale, sigma[q].cwiseAbs().maxCoeff());
  }
  c.stress = worst / scale;
  c.unloaded = max_distance(positions(b.model(), b.displacement()), f.X) / max_norm(f.X);
  c.imaged = max_distance(pc.step1_x, imaged) / max_norm(f.X);
  print_history(what, pc.records);
  std::printf("  imaged state within %.2e of x^, stresses within %.2e of the forward run's; unloaded within %.2e of "
              "the forward reference (relative); %.3f s\n",
              c.imaged, c.stress, c.unloaded, c.seconds);
  return c;
}

}  // namespace

TEST(PrestressInverse, AxisymmetricSphereHasTheForwardStressesAndUnloadsToItsReference) {
  for (const double p : {0.004, 0.008, 0.0118}) {
    const Comparison c = compare(axisym_deck(40, p, 10), kAxisym, "inflate", "fixed_point_tolerance: 1e-6\n    acceleration: aitken",
                                 fmt::format("axisymmetric sphere, 40 elements, {} MPa", p).c_str());
    // The imaged state is as close to x̂ as the tolerance asks; its stresses, and so the reference the
    // unloading reaches, are one of the prestress fields in equilibrium there (more Gauss-point
    // stresses than nodal equations, theory manual §13.2): within 0.1 % of the forward run's.
    EXPECT_LT(c.imaged, 2e-6) << p;
    EXPECT_LT(c.stress, 2e-3) << p;
    EXPECT_LT(c.unloaded, 5e-4) << p;
  }
}

TEST(PrestressInverse, OctantHasTheForwardStressesAndUnloadsToItsReference) {
  const Comparison c = compare(octant_deck(6, 0.008), k3d, "inflate", "fixed_point_tolerance: 1e-6\n    acceleration: aitken",
                               "3-D octant n = 6, 0.008 MPa");
  EXPECT_LT(c.imaged, 2e-6);
  EXPECT_LT(c.stress, 1e-3);
  EXPECT_LT(c.unloaded, 2e-4);
}

TEST(PrestressInverse, RatAortaTubeAtAnAxialStretchOfOneUnloadsToTheDirectMethodsReference) {
  // examples/rat-aorta-inverse.yaml with the ends held where they are imaged (no axial prestretch:
  // the prestress method balances loads, and an axial stretch held by the ends is none): the
  // direct method's zero-pressure radius, and the prestress run unloaded to 0 mmHg.
  std::string base = replace(read_text(kRatInverse), "stretch: -0.6 mm", "stretch: 0 mm");
  const Model md = read_deck_text(base, kRatInverse);
  Capture cd;
  Analysis ad(md);
  ad.run(cd);
  const auto end_of_step_1 = [](const Row& r) { return r.info.step == 1 && r.info.fraction >= 1 - 1e-12; };
  const Row& end_direct = *std::find_if(cd.rows.begin(), cd.rows.end(), end_of_step_1);
  const double R_direct = end_direct.values[Capture::column(md, "radius_mm")];
  std::string text = replace(base, "    type: inverse ", "    method: prestress\n    fixed_point_tolerance: 1e-12\n    type: inverse ");
  text = replace(text, "  - name: systolic", "  - name: unload\n    increments: 4\n    set: {lumen: 0 mmHg}\n  - name: systolic");
  const Model mp = read_deck_text(text, kRatInverse);
  PrestressCapture pc;
  Capture cp;
  Analysis ap(mp);
  ap.run(cp);
  const Row& unloaded = *std::find_if(cp.rows.begin(), cp.rows.end(), [](const Row& r) { return r.info.step == 2 && r.info.fraction >= 1 - 1e-12; });
  const Row& imaged = *std::find_if(cp.rows.begin(), cp.rows.end(), end_of_step_1);
  const double R = unloaded.values[Capture::column(mp, "radius_mm")];
  const double sd = end_direct.values[Capture::column(md, "sigma_theta_imaged_kPa")];
  const double sp = imaged.values[Capture::column(mp, "sigma_theta_imaged_kPa")];
  std::printf("rat aorta at an axial stretch of 1, 120 mmHg: direct R = %.12f mm, prestress unloaded R = %.12f mm; "
              "hoop stress at 120 mmHg %.9f kPa (direct) and %.9f kPa (prestress)\n",
              R_direct, R, sd, sp);
  EXPECT_NEAR(R, R_direct, 1e-9);
  EXPECT_NEAR(sp, sd, 1e-7 * std::abs(sd));
  // After unloading, the forward steps from the unloaded state match the direct run's (160 mmHg, 80 mmHg).
  const Row& last_d = cd.rows.back();
  const Row& last_p = cp.rows.back();
  const double r_d = last_d.values[Capture::column(md, "radius_mm")], r_p = last_p.values[Capture::column(mp, "radius_mm")];
  std::printf("  at 80 mmHg: radius %.12f mm (direct) and %.12f mm (prestress)\n", r_d, r_p);
  EXPECT_NEAR(r_p, r_d, 1e-9);
}

TEST(PrestressInverse, KeysAndAPrescribedValueAreChecked) {
  const std::string forward = axisym_deck(20, 0.006, 5);
  try {
    read_deck_text(replace(prestress_of(forward, "inflate", ""), "method: prestress", "method: prestress\n    relaxation: 0.5"),
                   kAxisym);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("`method: prestress` takes `fixed_point_tolerance`, `fixed_point_iterations` and `acceleration` only"),
              std::string::npos)
        << e.what();
  }
  const Model m = read_deck_text(prestress_of(forward, "inflate", "fixed_point_iterations: 7"), kAxisym);
  EXPECT_EQ(m.steps[0].inverse_method, Step::InverseMethod::prestress);
  EXPECT_EQ(m.steps[0].fixed_point.max_iterations, 7);
  EXPECT_FALSE(m.steps[0].moves_reference());
  try {
    read_deck_text(replace(read_text(kRatInverse), "    type: inverse ", "    method: prestress\n    type: inverse "),
                   kRatInverse);
    FAIL();
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("boundary 'stretch' would move its nodes off it"), std::string::npos) << what;
    EXPECT_NE(what.find("rat-aorta-inverse.yaml:"), std::string::npos) << what;
  }
}

TEST(PrestressInverse, TooFewIterationsStopNamingTheDistanceAndTheKey) {
  std::string deck = prestress_of(axisym_deck(20, 0.008, 2), "inflate", "fixed_point_iterations: 1");
  const Model m = read_deck_text(deck, kAxisym);
  PrestressCapture pc;
  Analysis a(m);
  try {
    a.run(pc);
    FAIL();
  } catch (const SolveError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("method: prestress"), std::string::npos) << what;
    EXPECT_NE(what.find("`fixed_point_iterations`"), std::string::npos) << what;
    EXPECT_NE(what.find("fixed_point.csv"), std::string::npos) << what;
  }
  EXPECT_EQ(pc.records.size(), 3u);
}

TEST(PrestressInverse, ACompletedPrestressRunContinuesWithAForwardStepAdded) {
  // The checkpoint at the end of the prestress step resumed with a deck that adds a forward step: no
  // prestress solve is redone, and the run ends as the whole deck does.
  const std::string forward = axisym_deck(40, 0.008, 10);
  const std::string keys = "fixed_point_tolerance: 1e-6\n    acceleration: aitken";
  const std::string only =
      replace(forward, "name: inflate", "name: prestress\n    type: inverse\n    method: prestress\n    " + keys);
  const Model f = read_deck_text(forward, kAxisym);
  Capture c0;
  Analysis a0(f);
  a0.run(c0);
  const std::vector<Eigen::Vector3d> imaged = positions(f, a0.displacement());
  Model first = read_deck_text(only, kAxisym);
  first.X = imaged;
  PrestressCapture keep;
  Analysis a1(first);
  a1.run(keep);
  ASSERT_EQ(keep.step1.fraction, 1.0);
  ASSERT_FALSE(keep.step1.prestress.empty());
  Model m = read_deck_text(prestress_of(forward, "inflate", keys), kAxisym);
  m.X = imaged;
  PrestressCapture c2;
  Analysis resumed(m);
  resumed.run(c2, &keep.step1);
  EXPECT_TRUE(c2.records.empty());
  PrestressCapture c3;
  Analysis whole(m);
  whole.run(c3);
  EXPECT_FALSE(c3.records.empty());
  EXPECT_EQ(resumed.displacement(), whole.displacement());
}

TEST(PrestressInverse, AFinishedPrestressOnlyRunRestartsWithAForwardStepAddedOnTheCommandLine) {
  // `tunica run` of the prestress step alone, then `--restart` with the deck that adds the forward
  // steps: accepted, and the same history as the whole deck run at once.
  const std::string dir = scratch("prestress-restart", "cli").string();
  const std::string base = replace(replace(read_text(kRatInverse), "stretch: -0.6 mm", "stretch: 0 mm"),
                                   "    type: inverse ", "    method: prestress\n    type: inverse ");
  const std::string only = base.substr(0, base.find("  - name: systolic")) + base.substr(base.find("\noutput:") + 1);
  std::ofstream(dir + "/only.yaml") << only;
  std::ofstream(dir + "/whole.yaml") << base;
  ASSERT_EQ(run_cli("run " + dir + "/only.yaml -o " + dir + "/resumed -q -j 1").exit_code, 0);
  const Outcome resumed = run_cli("run " + dir + "/whole.yaml --restart " + dir + "/resumed -q -j 1");
  EXPECT_EQ(resumed.exit_code, 0) << resumed.output;
  ASSERT_EQ(run_cli("run " + dir + "/whole.yaml -o " + dir + "/whole -q -j 1").exit_code, 0);
  EXPECT_EQ(read_text(dir + "/resumed/history.csv"), read_text(dir + "/whole/history.csv"));
}
