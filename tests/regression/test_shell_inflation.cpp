// Axisymmetric shells (element axisymmetric_shell) against the membrane and the closed
// forms where bending is negligible (theory manual §8, §11):
//  - the thin neo-Hookean sphere of examples/balloon-sphere.yaml (H/R = 0.01) as a shell,
//    equator held by symmetry (z, slope_r), pole on the axis (r, slope_z): the pressure
//    matches p = 2μ(H/R)(λ⁻¹ − λ⁻⁷) to O((H/R)²) = 1e-4 at every increment (the
//    through-thickness variation the membrane ignores), Newton without cut-backs;
//  - the rat aorta of examples/rat-aorta-inflation.yaml as a 4-element shell with its ends
//    held in slope_r: hoop equilibrium of the Kirchhoff–Love wall under pressure on its
//    mid-surface, ∫ σ_θ r/(r + η) dη = p r (≈ N_θ − M_θ/r), to round-off at every Gauss
//    point, and the hoop stretch within 1.5 % of the membrane's thin-tube closed form
//    although H/R = 0.16 (the shell differs by about 0.9 %);
//  - the shell artery and balloon of tests/support/shell_decks.hpp run through contact.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "../support/capture.hpp"
#include "../support/shell_decks.hpp"
#include "contributions/kinematics.hpp"
#include "assembly/system.hpp"
#include "elements/shell_output.hpp"

using namespace tunica;
using namespace tunica::test;

namespace {

std::string as_shell_sphere(std::string deck) {
  deck = replace(deck, "element: axisymmetric_membrane", "element: axisymmetric_shell");
  deck = replace(deck, "equator: {node_set: balloon.start, dofs: [z]}",
                 "equator: {node_set: balloon.start, dofs: [z, slope_r]}");
  return replace(deck, "pole:    {node_set: balloon.end, dofs: [r]}", "pole:    {node_set: balloon.end, dofs: [r, slope_z]}");
}

struct ShellRun {
  Model model;
  Capture capture;
};

ShellRun run(const std::string& text, const std::string& file) {
  ShellRun r{read_deck_text(text, file), {}};
  Analysis a(r.model);
  a.run(r.capture);
  return r;
}

}  // namespace

TEST(ShellInflation, ThinSphereMatchesTheMembraneClosedForm) {
  const std::string file = std::string(TUNICA_SOURCE_DIR) + "/examples/balloon-sphere.yaml";
  const ShellRun r = run(as_shell_sphere(read_text(file)), file);
  EXPECT_EQ(r.capture.cutbacks, 0);
  const int p = Capture::column(r.model, "pressure_kPa"), rad = Capture::column(r.model, "equator_radius_mm");
  double err = 0;
  int rows = 0;
  for (const Row& row : r.capture.rows) {
    const double l = row.values[rad];  // R = 1 mm
    const double exact = 2 * 1.0 * 0.01 * (1 / l - std::pow(l, -7)) * 1e3;  // kPa
    if (row.values[p] > 0) err = std::max(err, std::abs(row.values[p] - exact) / exact);
    ++rows;
  }
  EXPECT_EQ(rows, 21);  // the reference state and 20 increments
  EXPECT_LT(err, 1.5e-4);
  std::printf("shell sphere: max relative pressure error against the thin-membrane closed form %.2e\n", err);
}

TEST(ShellInflation, TubeHoopEquilibriumAndTheThinTubeClosedForm) {
  const std::string file = std::string(TUNICA_SOURCE_DIR) + "/examples/rat-aorta-inflation.yaml";
  std::string deck = read_text(file);
  deck = replace(deck, "element: axisymmetric_membrane", "element: axisymmetric_shell");
  deck = replace(deck, "elements: 1}", "elements: 4}");
  deck = replace(deck, "stretch: {node_set: wall.end, dofs: [z]}",
                 "stretch: {node_set: wall.end, dofs: [z]}\n  ends: {node_set: wall_ends, dofs: [slope_r]}");
  deck = replace(deck, "boundary:", "node_sets:\n  wall_ends: {part: wall, nodes: [0, 4]}\nboundary:");
  const Model m = read_deck_text(deck, file);
  Capture capture;
  Analysis a(m);
  a.run(capture);
  EXPECT_EQ(capture.cutbacks, 0);
  const int p = Capture::column(m, "pressure_mmHg"), lt = Capture::column(m, "lambda_theta");
  constexpr double c = 61.163, a1 = 0.68238, a2 = 0.60558, a4 = 0.1067, R = 0.763, H = 0.122, lz = 1.6;
  const auto S1 = [&](double E1, double E2) {
    return 2 * c * (a1 * E1 + a4 * E2) * std::exp(a1 * E1 * E1 + a2 * E2 * E2 + 2 * a4 * E1 * E2);
  };
  double worst_lambda = 0;
  for (const Row& row : capture.rows) {
    if (row.info.step != 2) continue;
    // Thin-tube closed form: S1(E_θ, E_z) = p R λz / H (kPa).
    const double pk = row.values[p] * 0.133322387415;
    double lo = -0.49, hi = 3.0;
    const double Ez = 0.5 * (lz * lz - 1), target = pk * R * lz / H;
    for (int k = 0; k < 200; ++k) (S1(0.5 * (lo + hi), Ez) < target ? lo : hi) = 0.5 * (lo + hi);
    const double l_exact = std::sqrt(1 + (lo + hi));
    worst_lambda = std::max(worst_lambda, std::abs(row.values[lt] - l_exact) / l_exact);
  }
  // Hoop equilibrium at the final state, from the layers of every Gauss point: a radial
  // motion δr moves the layer at η by δr (1 + ∂η/∂r) = δr r/(r + η) (its volume conserved),
  // so the discrete equations hold ∫ σ_θ r/(r + η) dη = p r, dη = w_k/(λ_θ λ_s)(ζ_k).
  const Part& wall = m.parts[0];
  const double pressure = a.loads().pressure[0];
  double worst_eq = 0, largest_moment = 0;
  for (int e = 0; e < wall.blocks[0].size(); ++e) {
    ShellKinematics::State s;
    ShellVector f;
    std::vector<ShellPoint> pts;
    ShellKinematics::gather(m, wall.blocks[0].element(e), a.displacement(), s);
    axisym_shell(s.X, s.x, wall.thickness, *wall.material, f, nullptr,
                 {wall.shell_meridian_points, wall.shell_thickness_points}, &pts);
    for (const ShellPoint& pt : pts) {
      double lhs = 0;
      for (std::size_t k = 0; k < pt.eta.size(); ++k) {
        const Eigen::Index i = static_cast<Eigen::Index>(k);
        lhs += pt.weight_zeta[k] / (pt.stretch(0, i) * pt.stretch(1, i)) * pt.sigma(0, i) * pt.r / (pt.r + pt.eta[k]);
      }
      worst_eq = std::max(worst_eq, std::abs(lhs - pressure * pt.r) / (pressure * pt.r));
      largest_moment = std::max(largest_moment, std::abs(shell_membrane_point(pt, wall.thickness).moment(0)));
    }
  }
  EXPECT_LT(worst_eq, 1e-8);
  EXPECT_GT(largest_moment, 0.0);  // the hoop stress varies through the thickness
  EXPECT_LT(worst_lambda, 1.5e-2);
  std::printf("shell tube: hoop equilibrium %.2e; hoop stretch against the thin-tube closed form %.2e\n", worst_eq,
              worst_lambda);
}

TEST(ShellInflation, ShellBalloonInflatesAShellArteryThroughContact) {
  const ShellRun r = run(kShellArteryBalloon, "shells.yaml");
  EXPECT_EQ(r.capture.cutbacks, 0);
  ASSERT_EQ(r.capture.rows.size(), 11u);  // the reference state and 10 increments
  const auto& last = r.capture.rows.back().values;
  const Model& m = r.model;
  EXPECT_GT(last[Capture::column(m, "pc_MPa")], 0.0);
  EXPECT_GT(last[Capture::column(m, "M_s_max_N")], 0.0);  // the contact bends the artery
  EXPECT_GT(last[Capture::column(m, "balloon_rmax_mm")], 0.9);
}

// A long thin tube (R = 1, h = 0.02, neo-Hookean μ = 1, so E = 3, ν = ½ in the small-strain
// limit) clamped at both ends (r, z and slope_r held) under a small pressure p: the linear
// shell theory of the edge zone (Timoshenko & Woinowsky-Krieger, §114) gives the clamping
// moment per unit length M₀ = 2β²D w_∞ with D = Eh³/(12(1 − ν²)), β⁴ = 3(1 − ν²)/(R²h²),
// w_∞ = pR²(1 − ν²)/(Eh) (axially held), i.e. M₀ = pRh/4 for ν = ½: the history quantity
// reaction_slope_r at an end is 2πR M₀ = πpR²h/2 (whole circumference). Also: slope_r is
// held at 0 at the clamp and the tube's meridian turns in the edge zone (slope_r ≠ 0 there).
TEST(ShellInflation, ClampedTubeEndMomentMatchesTheLinearEdgeZone) {
  const std::string deck = R"(title: clamped shell tube
units: {length: mm, force: N}
materials:
  wall: {type: neo_hookean, mu: 1}
parts:
  tube:
    element: axisymmetric_shell
    material: wall
    thickness: 0.02
    mesh: {type: line, from: [1, 0], to: [1, 2], elements: 100}
node_sets:
  ends: {part: tube, nodes: [0, 100]}
  near_end: {part: tube, nodes: [5]}
boundary:
  clamp: {node_set: ends, dofs: [r, z, slope_r]}
loads:
  p: {type: pressure, part: tube}
steps:
  - {name: load, increments: 1, set: {p: 1e-5}}
output:
  vtk: false
  history:
    - {quantity: reaction_slope_r, node_set: tube.start, name: M_start}
    - {quantity: reaction_slope_r, node_set: ends, name: M_ends}
    - {quantity: slope_r, node_set: tube.start, name: slope_start}
    - {quantity: slope_r, node_set: near_end, name: slope_near}
    - {quantity: radius, part: tube, reduce: max, name: r_max}
)";
  const ShellRun r = run(deck, "clamped-tube.yaml");
  const auto& last = r.capture.rows.back().values;
  const double p = 1e-5, R = 1, h = 0.02, E = 3, nu = 0.5;
  const double closed = std::numbers::pi * p * R * R * h / 2;
  const double M = last[Capture::column(r.model, "M_start_N_mm")];
  const double w_inf = p * R * R * (1 - nu * nu) / (E * h);
  std::printf("clamped tube: reaction_slope_r %.5e N mm, linear edge zone pi p R^2 h / 2 = %.5e (%+.2f %%); "
              "r_max - R = %.4e (w_inf %.4e); slope_r near the end %.3e\n",
              M, closed, 100 * (std::abs(M) / closed - 1), last[Capture::column(r.model, "r_max_mm")] - R, w_inf,
              last[Capture::column(r.model, "slope_near")]);
  EXPECT_NEAR(std::abs(M) / closed, 1.0, 0.05);
  EXPECT_NEAR(last[Capture::column(r.model, "M_ends_N_mm")], 0.0, 1e-9 * closed) << "the two ends' moments cancel";
  EXPECT_EQ(last[Capture::column(r.model, "slope_start")], 0.0);
  EXPECT_GT(std::abs(last[Capture::column(r.model, "slope_near")]), 0.1 * w_inf * std::sqrt(75.0));
  // The overshoot of the edge zone: r_max − R = w_∞ (1 + e^{−π}) at βx = π.
  EXPECT_NEAR((last[Capture::column(r.model, "r_max_mm")] - R) / (w_inf * (1 + std::exp(-std::numbers::pi))), 1.0, 0.05);
}
