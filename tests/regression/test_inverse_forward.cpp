// Forward steps after an inverse step (theory manual §13, (13.10); solver/analysis.hpp): the
// reference becomes the zero-pressure geometry X the inverse step computed and the state the
// displacement x̂ − X at the imaged loads, and the steps after it are ordinary forward steps.
//  - Round trips: a forward run from a known reference R0 to p1 gives the imaged x1; a deck with x1
//    as its geometry, an inverse step at p1 and a forward step to p2 ends in the state of a forward
//    run from R0 straight to p2 (axisymmetric sphere, the rat aorta tube with its prescribed axial
//    stretch, the 3-D octant of quadrilaterals and of triangles), to 1e-10 relative: forward and
//    inverse solve the same discrete equations (theory manual §13), so only the solvers' tolerance
//    separates them.
//  - A forward step back to zero load (and to zero prescribed displacement) lands on X itself.
//  - A restart past the inverse step continues on the reference it computed (restart.txt records
//    it as `reference_shift`), to the same results bit for bit, in process and through `tunica run
//    --restart`; a restart file past an inverse step without it is refused naming the key; a
//    completed inverse-only run continues with a forward step added to the deck.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "../support/capture.hpp"
#include "../support/scratch.hpp"
#include "core/errors.hpp"
#include "output/restart_file.hpp"
#include "output/restart_fit.hpp"

using namespace tunica;
using namespace tunica::test;

namespace {

const std::string kAxisym = std::string(TUNICA_SOURCE_DIR) + "/examples/balloon-sphere.yaml";
const std::string k3d = std::string(TUNICA_SOURCE_DIR) + "/examples/balloon-sphere-3d.yaml";
const std::string kRat = std::string(TUNICA_SOURCE_DIR) + "/examples/rat-aorta-inflation.yaml";
const char* kTight = "\nsolver: {residual_tolerance: 1e-12}\n";

/// The axisymmetric balloon example with 40 elements, its step `inflate` to p (MPa) in `increments`.
std::string axisym_deck(double p, int increments) {
  std::string t = replace(read_text(kAxisym), "elements: 100", "elements: 40");
  t = replace(t, "increments: 20", "increments: " + std::to_string(increments));
  return replace(t, "set: {inflation: 0.0118 MPa}", fmt::format("set: {{inflation: {} MPa}}", p)) + kTight;
}

/// The 3-D octant example of 6 × 6 elements per face (`shape`: "" or ", shape: triangle"), its step
/// `inflate` to p (MPa) in `increments` rather than by volume control.
std::string octant_deck(double p, int increments, const std::string& shape) {
  std::string t = replace(read_text(k3d), "n: 8}", "n: 6" + shape + "}");
  t = replace(t, "increments: 40\n    volume_control: {load: inflation, volume: 4.45 mm^3}   # 8.5 × π/6 mm³",
              fmt::format("increments: {}\n    set: {{inflation: {} MPa}}", increments, p));
  return t + kTight;
}

/// `deck` (one step, `step_name`, setting `set`) with that step made an inverse one and `more`
/// (lines of further steps) after it.
std::string inverse_then(const std::string& deck, const std::string& step_name, const std::string& more) {
  std::string t = replace(deck, "name: " + step_name, "name: zero_pressure\n    type: inverse");
  return replace(t, "\noutput:", more + "\noutput:");
}

/// Positions X + u of every node of m.
std::vector<Eigen::Vector3d> positions(const Model& m, const Eigen::VectorXd& u) {
  std::vector<Eigen::Vector3d> x = m.X;
  const int d = m.dofs_per_node();
  for (int n = 0; n < m.num_nodes(); ++n)
    for (int c = 0; c < d; ++c) x[n](c) += u(d * n + c);
  return x;
}

/// Where a run ends: the reference of the model it ends on (Analysis::model(): after an inverse
/// step the computed one) and the positions and displacements on it.
struct End {
  std::vector<Eigen::Vector3d> X, x;
  Eigen::VectorXd u;
  int cutbacks = 0;
};

End run(const std::string& text, const std::string& file, const std::vector<Eigen::Vector3d>& imaged = {}) {
  Model m = read_deck_text(text, file);
  if (!imaged.empty()) m.X = imaged;
  Capture cap;
  Analysis a(m);
  a.run(cap);
  return {a.model().X, positions(a.model(), a.displacement()), a.displacement(), cap.cutbacks};
}

/// max_n |a_n − b_n| / max_n |b_n|.
double relative(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b) {
  double err = 0, scale = 0;
  for (std::size_t n = 0; n < b.size(); ++n) {
    err = std::max(err, (a[n] - b[n]).norm());
    scale = std::max(scale, b[n].norm());
  }
  return err / scale;
}

struct Agreement {
  double reference = 0;     ///< the computed X against R0
  double position = 0;      ///< x after the forward step against the direct forward run's
  double displacement = 0;  ///< u on the computed X against the direct run's u on R0 (max-norm relative)
};

/// forward_p1: R0 to p1 (the imaged state); workflow: its inverse step at p1 and the steps after
/// it, run on the imaged positions; direct: R0 straight to the workflow's last state.
Agreement round_trip(const std::string& forward_p1, const std::string& workflow, const std::string& direct,
                     const std::string& file) {
  const End imaged = run(forward_p1, file);
  const End w = run(workflow, file, imaged.x);
  const End d = run(direct, file);
  EXPECT_EQ(w.cutbacks, 0);
  Agreement a;
  a.reference = relative(w.X, d.X);
  a.position = relative(w.x, d.x);
  a.displacement = (w.u - d.u).lpNorm<Eigen::Infinity>() / d.u.lpNorm<Eigen::Infinity>();
  return a;
}

}  // namespace

TEST(InverseThenForward, AxisymmetricSphereInflatedOnTheComputedReferenceIsTheForwardRun) {
  // Neo-Hookean sphere R0 = 1 mm: imaged at 8 kPa, then inflated on the computed reference to 11 kPa.
  const std::string workflow =
      inverse_then(axisym_deck(0.008, 8), "inflate", "  - {name: systolic, increments: 6, set: {inflation: 0.011 MPa}}\n");
  const Agreement a = round_trip(axisym_deck(0.008, 8), workflow, axisym_deck(0.011, 11), kAxisym);
  std::printf("axisymmetric sphere, 8 → 11 kPa on the inverse step's reference: reference %.2e, positions %.2e, "
              "displacements %.2e (relative)\n",
              a.reference, a.position, a.displacement);
  EXPECT_LT(a.reference, 1e-10);
  EXPECT_LT(a.position, 1e-10);
  EXPECT_LT(a.displacement, 1e-10);
}

TEST(InverseThenForward, RatAortaTubeWithItsPrescribedStretchInflatedOnTheComputedReference) {
  // The paper's rat aorta (theory manual §12.1): prestretched to λz = 1.6 and imaged at 80 mmHg; the
  // inverse step undoes the stretch (the reference end 0.6 mm below its imaged position), so on the
  // computed reference the end's prescribed displacement is +0.6 mm, held while the lumen goes to
  // 120 mmHg: the state of the forward run prestretched and inflated straight to 120 mmHg.
  std::string base = replace(read_text(kRat), "elements: 1}", "elements: 4}");
  base = replace(base, "residual_tolerance: 1e-10", "residual_tolerance: 1e-12");
  const auto inflated_to = [&](int mmhg) {
    return replace(base, "increments: 20\n    set: {lumen: 200 mmHg}", fmt::format("increments: 12\n    set: {{lumen: {} mmHg}}", mmhg));
  };
  std::string workflow = replace(inflated_to(80), "  - name: prestretch\n    increments: 6\n    set: {stretch: 0.6 mm}",
                                 "  - name: zero_pressure\n    type: inverse\n    increments: 8\n    set: {stretch: -0.6 mm, lumen: 80 mmHg}");
  workflow = replace(workflow, "  - name: inflation\n    increments: 12\n    set: {lumen: 80 mmHg}",
                     "  - name: systolic\n    increments: 6\n    set: {lumen: 120 mmHg}");
  const Agreement a = round_trip(inflated_to(80), workflow, inflated_to(120), kRat);
  std::printf("rat aorta tube, λz = 1.6, 80 → 120 mmHg on the inverse step's reference: reference %.2e, positions "
              "%.2e, displacements %.2e (relative)\n",
              a.reference, a.position, a.displacement);
  EXPECT_LT(a.reference, 1e-10);
  EXPECT_LT(a.position, 1e-10);
  EXPECT_LT(a.displacement, 1e-10);
}

TEST(InverseThenForward, OctantInflatedOnTheComputedReferenceIsTheForwardRun) {
  for (const std::string shape : {"", ", shape: triangle"}) {
    const std::string workflow = inverse_then(octant_deck(0.008, 8, shape), "inflate",
                                              "  - {name: systolic, increments: 4, set: {inflation: 0.011 MPa}}\n");
    const Agreement a = round_trip(octant_deck(0.008, 8, shape), workflow, octant_deck(0.011, 10, shape), k3d);
    std::printf("3-D octant%s, n = 6, 8 → 11 kPa on the inverse step's reference: reference %.2e, positions %.2e, "
                "displacements %.2e (relative)\n",
                shape.c_str(), a.reference, a.position, a.displacement);
    EXPECT_LT(a.reference, 1e-10) << shape;
    EXPECT_LT(a.position, 1e-10) << shape;
    EXPECT_LT(a.displacement, 1e-10) << shape;
  }
}

TEST(InverseThenForward, UnloadingAfterTheInverseStepLandsOnTheZeroPressureGeometry) {
  // Axisymmetric sphere and 3-D octant imaged at 11 kPa: a forward step back to zero pressure ends at
  // displacement zero on the computed reference (the sphere of R0 = 1 mm).
  struct Case {
    const char* name;
    std::string imaged, workflow, file;
  };
  const std::string back = "  - {name: unload, increments: 4, set: {inflation: 0 MPa}}\n";
  const Case cases[] = {
      {"axisymmetric sphere", axisym_deck(0.011, 11), inverse_then(axisym_deck(0.011, 11), "inflate", back), kAxisym},
      {"3-D octant", octant_deck(0.011, 10, ""), inverse_then(octant_deck(0.011, 10, ""), "inflate", back), k3d},
  };
  for (const Case& c : cases) {
    const End imaged = run(c.imaged, c.file);
    const Model m0 = read_deck_text(c.imaged, c.file);
    const End w = run(c.workflow, c.file, imaged.x);
    double R = 0;
    for (const auto& X : m0.X) R = std::max(R, X.norm());
    const double u = w.u.lpNorm<Eigen::Infinity>() / R;
    std::printf("%s imaged at 11 kPa, unloaded on the inverse step's reference: max |u| / R = %.2e, reference against "
                "R0 %.2e\n",
                c.name, u, relative(w.X, m0.X));
    EXPECT_LT(u, 1e-10) << c.name;
    EXPECT_LT(relative(w.x, w.X), 1e-10) << c.name;
    EXPECT_LT(relative(w.X, m0.X), 1e-10) << c.name;
  }
}

namespace {

/// Keeps the checkpoint after increment `increment` of step `step` (1-based).
class KeepCheckpoint final : public AnalysisObserver {
public:
  KeepCheckpoint(int step, int increment) : step_(step), increment_(increment) {}
  void on_increment(const Analysis& a, const IncrementInfo& i) override {
    if (i.step == step_ && i.increment == increment_) kept = a.checkpoint();
  }
  Checkpoint kept;

private:
  int step_, increment_;
};

/// The axisymmetric sphere imaged at 8 kPa and its workflow: inverse at 8 kPa, 11 kPa, back to 0.
struct Workflow {
  std::string text;
  std::vector<Eigen::Vector3d> imaged;
};

Workflow sphere_workflow() {
  const std::string forward = axisym_deck(0.008, 8);
  return {inverse_then(forward, "inflate",
                       "  - {name: systolic, increments: 6, set: {inflation: 0.011 MPa}}\n"
                       "  - {name: unload, increments: 4, set: {inflation: 0 MPa}}\n"),
          run(forward, kAxisym).x};
}

}  // namespace

TEST(InverseThenForward, ARestartPastTheInverseStepContinuesOnItsReferenceBitForBit) {
  const Workflow w = sphere_workflow();
  Model m = read_deck_text(w.text, kAxisym);
  m.X = w.imaged;
  KeepCheckpoint keep(2, 3);  // mid-way through `systolic`
  Analysis whole(m);
  whole.run(keep);
  ASSERT_EQ(keep.kept.reference_shift.size(), m.num_dofs());
  // Through the restart file, as `tunica run --restart` reads it.
  RestartRecord rec{keep.kept, 0, 0, 0, "workflow.yaml", {}, m.fingerprint};
  const std::string file = (scratch("inverse-forward") / "restart.txt").string();
  std::ofstream(file) << restart_text(rec);
  const RestartRecord back = read_restart(file);
  EXPECT_EQ(check_restart_fits(m, back, file), "");
  Capture cap;
  Analysis resumed(m);
  resumed.run(cap, &back.checkpoint);
  EXPECT_EQ(resumed.displacement(), whole.displacement());
  EXPECT_EQ(resumed.model().X, whole.model().X);
  // Unloaded, on the computed reference: the resumed run lands on X.
  std::printf("sphere resumed mid-way through the step after the inverse step: max |u| at the end %.2e mm, "
              "bit for bit the uninterrupted run's\n",
              resumed.displacement().lpNorm<Eigen::Infinity>());
  EXPECT_LT(resumed.displacement().lpNorm<Eigen::Infinity>(), 1e-10);
}

TEST(InverseThenForward, ARestartFilePastTheInverseStepWithoutItsReferenceIsRefused) {
  const Workflow w = sphere_workflow();
  Model m = read_deck_text(w.text, kAxisym);
  m.X = w.imaged;
  KeepCheckpoint keep(2, 3);
  Analysis a(m);
  a.run(keep);
  RestartRecord rec{keep.kept, 0, 0, 0, "workflow.yaml", {}, m.fingerprint};
  rec.checkpoint.reference_shift.resize(0);  // as a file of format 5 has it
  try {
    check_restart_fits(m, rec, "out/restart.txt");
    FAIL() << "accepted a restart past the inverse step without its reference";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("past the inverse step 'zero_pressure'"), std::string::npos) << what;
    EXPECT_NE(what.find("`reference_shift`"), std::string::npos) << what;
    EXPECT_NE(what.find("imaged geometry"), std::string::npos) << what;
  }
}

TEST(InverseThenForward, ACompletedInverseRunContinuesWithAForwardStepAdded) {
  // The checkpoint at the end of the inverse step holds its unknowns: resumed with a deck that adds a
  // forward step, the reference is computed from them and the run continues as the whole deck does.
  const Workflow w = sphere_workflow();
  const std::string inverse_only = inverse_then(axisym_deck(0.008, 8), "inflate", "");
  Model first = read_deck_text(inverse_only, kAxisym);
  first.X = w.imaged;
  KeepCheckpoint keep(1, 8);  // the last increment of the inverse step: what its restart.txt holds
  Analysis a1(first);
  a1.run(keep);
  const Checkpoint& end_of_inverse = keep.kept;
  ASSERT_EQ(end_of_inverse.fraction, 1.0);
  EXPECT_EQ(end_of_inverse.reference_shift.size(), 0);  // the inverse step's own state
  Model m = read_deck_text(w.text, kAxisym);
  m.X = w.imaged;
  Capture c2;
  Analysis resumed(m);
  resumed.run(c2, &end_of_inverse);
  Capture c3;
  Analysis whole(m);
  whole.run(c3);
  EXPECT_EQ(resumed.displacement(), whole.displacement());
  EXPECT_EQ(resumed.model().X, whole.model().X);
}

TEST(InverseThenForward, RatAortaExampleLoadsItsZeroPressureTubeAsTheForwardRunDoes) {
  // examples/rat-aorta-inverse.yaml: imaged at 120 mmHg, its zero-pressure tube, then 160 mmHg and
  // 80 mmHg on it; examples/rat-aorta-inflation.yaml inflates the paper's tube (R = 0.763 mm,
  // λz = 1.6) forward through both pressures (10 mmHg per increment). A uniform tube: the radii agree
  // to the solvers' tolerance, with no discretization error between the meshes.
  const std::string file = std::string(TUNICA_SOURCE_DIR) + "/examples/rat-aorta-inverse.yaml";
  const Model m = read_deck_text(read_text(file), file);
  Capture cap;
  Analysis a(m);
  a.run(cap);
  EXPECT_EQ(cap.cutbacks, 0);
  const Model f = read_deck_text(replace(read_text(kRat), "residual_tolerance: 1e-10", "residual_tolerance: 1e-12"), kRat);
  Capture cf;
  Analysis af(f);
  af.run(cf);
  const auto radius_at = [](const Model& model, const Capture& c, const char* column, int step, double mmhg) {
    for (const Row& r : c.rows)
      if (r.info.step == step && std::abs(r.values[Capture::column(model, "pressure_mmHg")] - mmhg) < 1e-9)
        return r.values[Capture::column(model, column)];
    ADD_FAILURE() << "no row at " << mmhg << " mmHg in step " << step;
    return 0.0;
  };
  for (const auto& [step, mmhg] : {std::pair{2, 160.0}, std::pair{3, 80.0}}) {
    const double r = radius_at(m, cap, "radius_mm", step, mmhg);
    const double expected = radius_at(f, cf, "radius_mm", 2, mmhg);
    std::printf("examples/rat-aorta-inverse.yaml, step %d at %.0f mmHg: radius %.12f mm, the forward inflation's %.12f "
                "mm (difference %.2e)\n",
                step, mmhg, r, expected, r - expected);
    EXPECT_NEAR(r, expected, 1e-9 * expected) << step;
  }
}

TEST(InverseThenForward, TunicaRunRestartedPastTheInverseStepEndsAsTheWholeRun) {
  // Through the command line: the example run to its end, restarted with a step added that unloads
  // the tube (lumen and axial displacement back to 0 on the zero-pressure reference), ends with the
  // history.csv of the whole deck run at once, bit for bit, on the load-free tube R = 0.763 mm over 1 mm.
  const std::string example = std::string(TUNICA_SOURCE_DIR) + "/examples/rat-aorta-inverse.yaml";
  const std::filesystem::path dir = scratch("inverse-forward", "cli");
  const std::string deck = (dir / "deck.yaml").string(), longer = (dir / "longer.yaml").string();
  std::ofstream(deck) << read_text(example);
  std::ofstream(longer) << replace(read_text(example), "    set: {lumen: 80 mmHg}\n",
                                   "    set: {lumen: 80 mmHg}\n  - {name: unload, increments: 8, set: {lumen: 0 mmHg, stretch: 0 mm}}\n");
  const auto tunica = [](const std::string& args) {
    return std::system((std::string(TUNICA_BINARY) + " " + args + " > /dev/null 2>&1").c_str());
  };
  ASSERT_EQ(tunica("run " + deck + " -q -o " + (dir / "a").string()), 0);
  // The restart takes the longer deck in the first run's folder (its added step not yet reached).
  std::filesystem::copy_file(longer, deck, std::filesystem::copy_options::overwrite_existing);
  ASSERT_EQ(tunica("run " + deck + " -q --restart " + (dir / "a").string()), 0);
  ASSERT_EQ(tunica("run " + deck + " -q -o " + (dir / "b").string()), 0);
  const std::string resumed = read_text((dir / "a" / "history.csv").string());
  EXPECT_EQ(resumed, read_text((dir / "b" / "history.csv").string()));
  const std::string last = resumed.substr(resumed.rfind('\n', resumed.size() - 2) + 1);
  std::printf("examples/rat-aorta-inverse.yaml restarted with an unloading step: last row %s", last.c_str());
  EXPECT_EQ(last.rfind("4,8,4,0,0.763", 0), 0u) << last;
}
