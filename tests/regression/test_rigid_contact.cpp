// Axisymmetric membranes against rigid surfaces (deck sections `rigid_surfaces` and
// `contact`, penalty Π = ½ ε ⟨−g_N⟩² A_s per slave node):
// (a) patch test: a flat annulus pressed by a follower pressure p onto a rigid plane
//     (polyline): the contact pressure is p at the interior nodes and the total contact
//     force is p × the annulus' area;
// (b) a neo-Hookean tube at λ_z = 1 inflated into a rigid sleeve r ≤ R_c (cylinder,
//     inside): before contact p = (μH/R)(1 − λ⁻⁴) (theory manual (8.1): S_θ = p R λ_z/H with
//     S_θ = μ(1 − λ⁻⁴ λ_z⁻²)); after contact the contact pressure is p − p_free(R_c/R);
//     with a soft penalty, Newton converges quadratically in the increments whose active
//     set does not change;
// (c) the tube with a penalty far too soft for its contact pressure: the run warns once, at the pair.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>

#include "../support/capture.hpp"
#include "../support/deck_files.hpp"
#include "../support/system_fd.hpp"

using namespace tunica;
using namespace tunica::test;

namespace {

const std::string kPatch = R"(title: annulus pressed onto a rigid plane
units: {length: mm, force: N}
materials:
  soft: {type: neo_hookean, mu: 0.1}
parts:
  sheet:
    element: axisymmetric_membrane
    material: soft
    thickness: 0.1
    mesh: {type: line, from: [1, 0], to: [2, 0], elements: 10}
loads:
  push: {type: pressure, part: sheet}
rigid_surfaces:
  plane: {type: polyline, points: [[3, 0], [1.55, 0], [0.5, 0]]}
contact:
  floor: {slave: sheet, rigid: plane, penalty: 1e4 N/mm^3, offset: 1e-8 mm}
solver: {residual_tolerance: 1e-10}
steps:
  - {name: press, increments: 2, set: {push: 0.01 MPa}}
output:
  vtk: false
  history:
    - {quantity: contact_pressure, contact: floor, name: p_max}
    - {quantity: contact_force, contact: floor}
)";

// μH/R = 0.01 N/mm²; R_c = 1.2 R: p_free(1.2) = 0.01 (1 − 1.2⁻⁴).
const std::string kTube = R"(title: neo-Hookean tube inflated into a rigid sleeve
units: {length: mm, force: N}
materials:
  soft: {type: neo_hookean, mu: 0.1 MPa}
parts:
  tube:
    element: axisymmetric_membrane
    material: soft
    thickness: 0.1 mm
    mesh: {type: line, from: [1, 0], to: [1, 1], elements: 8}
boundary:
  base: {node_set: tube.start, dofs: [z]}
  top: {node_set: tube.end, dofs: [z]}
loads:
  lumen: {type: pressure, part: tube}
rigid_surfaces:
  sleeve: {type: cylinder, radius: 1.2 mm, side: inside}
contact:
  wall: {slave: tube, rigid: sleeve, penalty: PENALTY}
solver: {residual_tolerance: 1e-11}
steps:
  - {name: free, increments: 4, set: {lumen: 0.004}}
  - {name: contact, increments: 10, set: {lumen: 0.009}}
output:
  vtk: false
  history:
    - {quantity: pressure, load: lumen}
    - {quantity: radius, part: tube, name: r}
    - {quantity: contact_pressure, contact: wall, name: pc_max}
    - {quantity: contact_pressure, contact: wall, name: pc_min, reduce: min}
    - {quantity: contact_force, contact: wall}
)";

constexpr double kMuHOverR = 0.01, kR = 1.0, kRc = 1.2;
double p_free(double lambda) { return kMuHOverR * (1.0 - std::pow(lambda, -4)); }

}  // namespace

TEST(RigidContactDeck, PatchTestAnnulusOnRigidPlane) {
  const Model m = read_deck_text(kPatch, "patch.yaml");
  ASSERT_EQ(m.contacts.size(), 1u);
  Capture cap;
  Analysis a(m);
  a.run(cap);
  ASSERT_EQ(cap.rows.size(), 3u);
  const double p = 0.01, eps = 1e4;
  const auto states = a.system().contact_states(a.displacement(), 0, a.loads().step);
  ASSERT_EQ(states.size(), 11u);
  double worst = 0;
  for (std::size_t k = 1; k + 1 < states.size(); ++k) {  // interior nodes
    EXPECT_TRUE(states[k].point.active);
    EXPECT_NEAR(states[k].pressure, p, 1e-5 * p) << "node " << k;  // within 10 p/(ε · 1 mm) relative
    EXPECT_NEAR(states[k].point.normal(1), 1.0, 1e-12);
    worst = std::max(worst, std::abs(states[k].pressure / p - 1));
  }
  const double area = std::numbers::pi * (2.0 * 2.0 - 1.0 * 1.0);
  const double force = cap.rows.back().values[Capture::column(m, "contact_force_N")];
  EXPECT_NEAR(force / (p * area), 1.0, 1e-6);
  // Every node is pushed into the plane by about p/ε (plus the offset).
  for (const auto& s : states) EXPECT_NEAR(s.point.gap, -p / eps, 0.1 * p / eps);
  std::printf("patch test: interior |p_c/p − 1| ≤ %.2e, total force / (p A) − 1 = %.2e, p/ε = %.1e\n", worst,
              force / (p * area) - 1, p / eps);
}

TEST(RigidContactDeck, TubeInflatedIntoRigidSleeveMatchesTheClosedForm) {
  const double eps = 1e3;  // N/mm³: penetration p_c/ε ≈ 5e-6 mm
  const Model m = read_deck_text(replace(kTube, "PENALTY", "1e3"), "tube.yaml");
  Capture cap;
  Analysis a(m);
  a.run(cap);
  EXPECT_EQ(cap.cutbacks, 0);
  const int cp = Capture::column(m, "pressure_N_per_mm2"), cr = Capture::column(m, "r_mm"),
            cmax = Capture::column(m, "pc_max_N_per_mm2"), cmin = Capture::column(m, "pc_min_N_per_mm2"),
            cf = Capture::column(m, "contact_force_N");
  int before = 0, after = 0;
  double worst_free = 0, worst_contact = 0;
  for (const auto& row : cap.rows) {
    if (row.info.step == 0) continue;
    const double p = row.values[cp], r = row.values[cr];
    if (p < p_free(kRc / kR)) {  // free inflation: the closed form p(λ), no contact
      ++before;
      EXPECT_NEAR(p_free(r / kR), p, 1e-9 * p) << "p = " << p;
      EXPECT_EQ(row.values[cmax], 0.0);
      worst_free = std::max(worst_free, std::abs(p_free(r / kR) / p - 1));
    } else if (p > p_free(kRc / kR) * 1.05) {
      ++after;
      const double pc = p - p_free(kRc / kR);
      EXPECT_NEAR(row.values[cmax], pc, 2e-3 * pc) << "p = " << p;
      EXPECT_NEAR(row.values[cmin], row.values[cmax], 1e-9 * pc);
      // The penalty error: r − R_c = p_c/ε (the sleeve is pushed into by the penetration).
      // p_c ε⁻¹ is the penetration per reference area: r − R_c = p_c r/(ε R).
      EXPECT_NEAR(r - kRc, row.values[cmax] * r / (eps * kR), 1e-6 * pc / eps + 1e-13);
      // Exactly (membrane equilibrium at the actual radius): p_c = p − p_free(r/R).
      EXPECT_NEAR(row.values[cmax], p - p_free(r / kR), 1e-8 * pc);
      // The total normal force is p_c × the current lateral area 2π r L.
      EXPECT_NEAR(row.values[cf], row.values[cmax] * 2 * std::numbers::pi * r * 1.0, 1e-8 * row.values[cf]);
      worst_contact = std::max(worst_contact, std::abs(row.values[cmax] / pc - 1));
    }
  }
  EXPECT_GE(before, 4);
  EXPECT_GE(after, 8);
  std::printf("tube: free |p/p_closed − 1| ≤ %.2e (%d rows); contact |p_c/(p − p_free(R_c)) − 1| ≤ %.2e (%d rows)\n",
              worst_free, before, worst_contact, after);
}

TEST(RigidContactDeck, NewtonConvergesQuadraticallyOnceTheActiveSetSettles) {
  // A soft penalty (contact stiffness comparable to the membrane's), so that the contact
  // increments need several iterations and the order can be measured.
  const Model m = read_deck_text(replace(kTube, "PENALTY", "0.05"), "tube-soft.yaml");
  Capture cap;
  Analysis a(m);
  a.run(cap);
  EXPECT_EQ(cap.cutbacks, 0);
  std::map<std::pair<int, int>, std::vector<IterationRecord>> inc;
  for (const auto& it : cap.iterations) inc[{it.info.step, it.info.increment}].push_back(it.rec);
  int measured = 0, settled = 0;
  double qmin = 10, qmax = 0;
  for (const auto& [key, recs] : inc) {
    if (key.first != 2) continue;
    // The active set settled: the same number of active nodes at every iterate.
    bool same = true;
    for (const auto& r : recs) same = same && r.active_contacts == recs.front().active_contacts;
    if (!same || recs.front().active_contacts == 0) continue;
    ++settled;
    EXPECT_EQ(recs.front().active_contacts, 9);
    double floor = recs.front().residual, last_q = 0;
    for (const auto& r : recs) floor = std::min(floor, r.residual);
    for (std::size_t j = 1; j + 1 < recs.size(); ++j) {
      const double r0 = recs[j - 1].relative_residual, r1 = recs[j].relative_residual, r2 = recs[j + 1].relative_residual;
      if (recs[j + 1].residual < 1e3 * floor || r2 < 1e-12 || r1 >= 1.0) continue;
      last_q = std::log(r2 / r1) / std::log(r1 / r0);
    }
    if (last_q == 0) continue;
    ++measured;
    qmin = std::min(qmin, last_q);
    qmax = std::max(qmax, last_q);
    EXPECT_NEAR(last_q, 2.0, 0.3) << "increment " << key.second;
  }
  // The equilibrium after contact is still exact at the actual radius.
  const int cp = Capture::column(m, "pressure_N_per_mm2"), cr = Capture::column(m, "r_mm"),
            cmax = Capture::column(m, "pc_max_N_per_mm2");
  const auto& last = cap.rows.back().values;
  EXPECT_NEAR(last[cmax], last[cp] - p_free(last[cr] / kR), 1e-8 * last[cmax]);
  EXPECT_GT(last[cr], kRc);
  std::printf("soft-penalty tube: %d settled contact increments, order estimate in [%.2f, %.2f] over %d\n", settled,
              qmin, qmax, measured);
  EXPECT_GE(measured, 4);
}

TEST(RigidContactDeck, AssembledTangentWithContactMatchesFiniteDifferences) {
  // The tube pressed into the sleeve and the annulus onto the plane: central differences of the
  // assembled residual (membrane + follower pressure + contact) against K, every free DOF.
  for (const std::string& deck : {replace(kTube, "PENALTY", "1e3"), kPatch}) {
    const Model m = read_deck_text(deck, "fd.yaml");
    const System sys(m);
    LoadState loads;
    loads.boundary.assign(m.boundaries.size(), 0.0);
    loads.pressure.assign(m.loads.size(), 0.007);
    loads.volume.assign(m.loads.size(), 0.0);
    Eigen::VectorXd u = Eigen::VectorXd::Zero(m.num_dofs());
    for (int n = 0; n < m.num_nodes(); ++n) {  // into the tool by a few microns, with some scatter
      const bool tube = m.X[n](0) == 1.0 && m.parts[0].name == "tube";
      u(2 * n) = tube ? 0.2 + 1e-5 * (1 + n % 3) : 1e-3 * std::sin(n);
      u(2 * n + 1) = tube ? 1e-3 * std::cos(n) : -1e-6 * (1 + n % 2);
    }
    sys.apply_boundary(loads, u);
    Eigen::VectorXd R;
    SparseMatrix K;
    int active = 0;
    sys.assemble_full(u, loads, R, K, nullptr, &active);
    EXPECT_EQ(active, m.num_nodes());
    const Eigen::MatrixXd Kd(K);
    const double worst = fd_tangent_error(sys, loads, u, Kd, 1e-7);
    const double size = Kd.cwiseAbs().maxCoeff();
    EXPECT_LT(worst, 1e-6 * size) << m.title;
    std::printf("%s: FD of the assembled residual vs K: %.2e (max |K| %.2e)\n", m.title.c_str(), worst, size);
  }
}

TEST(RigidContactDeck, PenetrationFarBeyondThePenaltysScaleIsWarnedOnceAtThePair) {
  // ε = 0.05 N/mm³ leaves p_c/ε ≈ 0.004/0.05 = 0.08 mm, more than half the 0.125 mm elements.
  const std::string soft = replace(kTube, "PENALTY", "0.05 N/mm^3");
  const std::string deck = write_deck_file("tunica-rigid-contact", "soft-penalty", soft);
  const std::string out = (std::filesystem::temp_directory_path() / "tunica-rigid-contact" / "soft-out").string();
  const Outcome o = run_cli("run " + deck + " -q -o " + out);
  EXPECT_EQ(o.exit_code, 0) << o.output;
  const std::string at = deck + ":" + std::to_string(line_of(soft, "  wall: {slave: tube")) + ":";
  const std::size_t w = o.output.find("tunica: warning: " + at);
  ASSERT_NE(w, std::string::npos) << o.output;
  EXPECT_EQ(o.output.find("tunica: warning: " + at, w + 1), std::string::npos) << "once per pair: " << o.output;
  for (const char* says : {"key 'contact.wall': contact pair 'wall': at step 2 'contact', increment",
                           "mm into the rigid surface 'sleeve'", "of its element length 0.125 mm",
                           "Raise `penalty` (to about", "check the cylinder's `side`"})
    EXPECT_NE(o.output.find(says), std::string::npos) << says << " missing from: " << o.output;
  // The penalty of the tests above leaves 4e-6 mm: no warning.
  const std::string stiff = write_deck_file("tunica-rigid-contact", "stiff-penalty", replace(kTube, "PENALTY", "1e3"));
  const Outcome ok = run_cli("run " + stiff + " -q -o " + out + "-stiff");
  EXPECT_EQ(ok.exit_code, 0) << ok.output;
  EXPECT_EQ(ok.output.find("key 'contact.wall'"), std::string::npos) << ok.output;
}

TEST(RigidContactDeck, ASlaveFilledBeyondItsSleeveUnderVolumeControlIsToldToLowerTheTarget) {
  // The sleeve holds π 1.2² × 1 = 4.52 mm³; filled to 4.9 mm³ the tube must sink about
  // 0.38/(2π 1.2) ≈ 0.05 mm into it whatever the penalty: the volume sets the depth, which the
  // warning names before the penalty.
  std::string filled = replace(kTube, "PENALTY", "10 N/mm^3");
  filled = replace(filled, "  - {name: contact, increments: 10, set: {lumen: 0.009}}",
                   "  - {name: fill, increments: 10, volume_control: {load: lumen, volume: 4.9 mm^3}}");
  const std::string deck = write_deck_file("tunica-rigid-contact", "overfilled", filled);
  const std::string out = (std::filesystem::temp_directory_path() / "tunica-rigid-contact" / "overfilled-out").string();
  const Outcome o = run_cli("run " + deck + " -q -o " + out);
  EXPECT_EQ(o.exit_code, 0) << o.output;
  for (const char* says : {"key 'contact.wall': contact pair 'wall': at step 2 'fill', increment",
                           "mm into the rigid surface 'sleeve'",
                           "step 'fill' prescribes the volume of load 'lumen' on the slave (`volume_control`, target "
                           "4.9 mm³)",
                           "If the target is more than fits inside the rigid surface 'sleeve', the volume and not "
                           "the penalty sets how deep the slave sinks (a larger `penalty` raises the pressure, not "
                           "the depth): lower the step's `volume` target, or control the pressure instead. Otherwise "
                           "raise `penalty` (to about"})
    EXPECT_NE(o.output.find(says), std::string::npos) << says << " missing from: " << o.output;
}
