// Volume control from the stress-free state (theory manual §7.2, (7.10); user guide §3.1): the
// HGO tube of the user guide, ends held axially, inflated under volume control from rest to
// 276 mm³ in one increment. At rest the pressure is 0 and the unstressed wall barely resists
// uneven normal motion; the plain bordered correction (7.5) threw it out (residual 1e-15 to
// NaN), the stiffened one converges quadratically. The state is exact: the pressure found is the
// one whose pressure-controlled run reaches the same volume, and the thin-tube closed form
// (8.1) at the stretch the volume gives (λ_θ² = V/V₀, λ_z = 1) within the faceting error.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>

#include "../support/capture.hpp"

using namespace tunica;
using namespace tunica::test;

namespace {

std::string tube(const std::string& shape, const std::string& step, const std::string& material = "hgo") {
  const std::string media = material == "hgo" ? "{type: hgo, mu: 40 kPa, k1: 60 kPa, k2: 8, beta: 40 deg, kappa: 0.1}"
                                              : "{type: neo_hookean, mu: 40 kPa}";
  return fmt::format(R"(title: tube, volume control from rest
units: {{length: mm, force: N}}
materials:
  media: {}
parts:
  wall:
    element: membrane
    material: media
    thickness: 0.7 mm
    mesh: {{type: tube, radius: 3 mm, length: 6 mm, around: 40, along: 4, shape: {}}}
    frame: {{type: cylindrical, axis: [0, 0, 1]}}
boundary:
  ends: {{node_set: wall.bottom, dofs: [z]}}
  top: {{node_set: wall.top, dofs: [z]}}
  nox: {{node_set: wall.x0, dofs: [x]}}
  noy: {{node_set: wall.y0, dofs: [y]}}
loads:
  bp: {{type: pressure, part: wall, volume_axis: [0, 0, 1]}}
steps:
  - {}
output:
  vtk: false
  history:
    - {{quantity: pressure, load: bp, unit: kPa}}
    - {{quantity: volume, load: bp, unit: mm^3}}
)",
                     media, shape, step);
}

struct Run {
  double pressure = 0, volume = 0;  // kPa, mm³ at the end
  double V0 = 0;                    // mm³ at rest
  int cutbacks = 0, retries = 0, iterations = 0;
  double order = 0;  // the largest q_k = log(r_{k+1}/r_k)/log(r_k/r_{k−1}) of the last attempt
};

Run run(const std::string& deck) {
  const Model m = read_deck_text(deck, "tube.yaml");
  Capture c;
  Analysis a(m);
  a.run(c);
  const int p = Capture::column(m, "pressure_kPa"), v = Capture::column(m, "volume_mm3");
  Run r;
  r.V0 = c.rows.front().values[v];
  r.pressure = c.rows.back().values[p];
  r.volume = c.rows.back().values[v];
  r.cutbacks = c.cutbacks;
  r.retries = static_cast<int>(c.retries.size());
  r.iterations = c.rows.back().info.iterations;
  std::vector<double> rel;
  for (const auto& it : c.iterations)
    if (it.info.attempt == c.iterations.back().info.attempt && it.rec.iteration > 0) rel.push_back(it.rec.relative_residual);
  for (std::size_t k = 2; k < rel.size(); ++k)
    r.order = std::max(r.order, std::log(rel[k] / rel[k - 1]) / std::log(rel[k - 1] / rel[k - 2]));
  return r;
}

/// Theory manual (8.1) at λ_z = 1: p = S_θ H/R, S_θ = (1/λ_θ) dŴ/dλ_θ of (3.5) (C₁₂ = 0), in kPa.
double closed_form_kpa(double lt, bool hgo) {
  const double mu = 0.04, k1 = 0.06, k2 = 8, beta = 40 * M_PI / 180, kappa = 0.1, H = 0.7, R = 3;
  const auto W = [&](double l) {
    const double I1 = l * l + 1 + 1 / (l * l);
    double w = mu / 2 * (I1 - 3);
    const double I4 = l * l * std::cos(beta) * std::cos(beta) + std::sin(beta) * std::sin(beta);
    const double Is = kappa * I1 + (1 - 3 * kappa) * I4;
    if (hgo && Is > 1) w += 2 * k1 / (2 * k2) * (std::exp(k2 * (Is - 1) * (Is - 1)) - 1);
    return w;
  };
  const double h = 1e-6;
  return (W(lt + h) - W(lt - h)) / (2 * h) / lt * H / R * 1e3;
}

void expect_exact_from_rest(const std::string& shape, const std::string& material) {
  SCOPED_TRACE(shape + ", " + material);
  Run vc;
  ASSERT_NO_THROW(vc = run(tube(shape, "{name: inflate, increments: 1, volume_control: {load: bp, volume: 276 mm^3}}",
                                material)));
  EXPECT_EQ(vc.cutbacks, 0);
  EXPECT_EQ(vc.retries, 0);
  EXPECT_LE(vc.iterations, 7);
  EXPECT_GE(vc.order, 1.8);  // quadratic at the end
  EXPECT_NEAR(vc.volume, 276, 1e-8 * 276);
  // The pressure found, applied under pressure control from rest, gives the same volume.
  const Run pc = run(tube(shape, fmt::format("{{name: inflate, increments: 1, set: {{bp: {:.12g} kPa}}}}", vc.pressure),
                          material));
  EXPECT_NEAR(pc.volume, 276, 1e-7 * 276);
  const double exact = closed_form_kpa(std::sqrt(276 / vc.V0), material == "hgo");
  std::printf("%s %s from rest: p = %.6f kPa (closed form %.6f), %d iterations, order %.2f; pressure control to it: V = %.9f mm^3\n",
              shape.c_str(), material.c_str(), vc.pressure, exact, vc.iterations, vc.order, pc.volume);
  EXPECT_NEAR(vc.pressure, exact, 5e-3 * exact);
}

}  // namespace

TEST(VolumeControlFromRest, TriangleTubeConvergesToTheExactState) { expect_exact_from_rest("triangle", "hgo"); }
TEST(VolumeControlFromRest, QuadTubeConvergesToTheExactState) { expect_exact_from_rest("quad", "hgo"); }
TEST(VolumeControlFromRest, StaggeredNeoHookeanTubeConvergesToTheExactState) {
  expect_exact_from_rest("staggered_triangle", "neo_hookean");
}

TEST(VolumeControlFromRest, ThePlainStartIsWhatFailed) {
  // stress_free_start: exact keeps the plain bordered correction at rest, which throws the wall out.
  EXPECT_THROW(run(tube("triangle", "{name: inflate, increments: 1, solver: {stress_free_start: exact}, "
                                    "volume_control: {load: bp, volume: 276 mm^3}}")),
               SolveError);
}

namespace {

/// A Mooney–Rivlin sac, the whole meridian from pole to pole (R 4 mm, H 0.05 mm, b1/b2 =
/// 150/30 kPa), inflated under volume control from rest to λ = 2.5 in 10 increments: past the
/// pressure maximum near λ = 1.4. Near the poles the fine meridian is nearly flat across the
/// axis, and the unstressed membrane resists the relative normal motion of its nodes there with
/// nothing: the plain first correction kinks it (a Gauss radius crosses the axis, or Newton
/// wanders) at every increment size. The axisymmetric K₀ (7.7) of the Laplace tension (7.8)
/// stiffens exactly those modes.
std::string sac(int elements, const std::string& start) {
  return fmt::format(R"(title: Mooney-Rivlin sac, whole meridian, volume control from rest
units: {{length: mm, force: N}}
materials:
  wall: {{type: mooney_rivlin, b1: 150 kPa, b2: 30 kPa}}
parts:
  sac:
    element: axisymmetric_membrane
    material: wall
    thickness: 0.05 mm
    mesh: {{type: arc, center: [0 mm, 0 mm], radius: 4 mm, start_angle: -90 deg, end_angle: 90 deg, elements: {}}}
boundary:
  south: {{node_set: sac.start, dofs: [r, z]}}
  north: {{node_set: sac.end, dofs: [r]}}
loads:
  bp: {{type: pressure, part: sac}}
steps:
  - {{name: inflate, increments: 10, solver: {{stress_free_start: {}}}, volume_control: {{load: bp, volume: 4188.790205 mm^3}}}}
output:
  vtk: false
  history:
    - {{quantity: pressure, load: bp, unit: kPa}}
    - {{quantity: volume, load: bp, unit: mm^3}}
)",
                     elements, start);
}

}  // namespace

TEST(VolumeControlFromRest, AFineMooneyRivlinSacPastItsPressureMaximumConvergesWithTheDefaults) {
  for (int elements : {250, 1000}) {
    SCOPED_TRACE(elements);
    const Model m = read_deck_text(sac(elements, "stiffened"), "sac.yaml");
    Capture c;
    Analysis a(m);
    ASSERT_NO_THROW(a.run(c));
    EXPECT_EQ(c.cutbacks, 0);
    EXPECT_EQ(c.retries.size(), 0u);
    int most = 0;
    for (const auto& row : c.rows) most = std::max(most, row.info.iterations);
    EXPECT_LE(most, 6);
    // (8.3) at λ = (V/V₀)^⅓ = 2.5, within the faceting error of the meridian.
    const double l = 2.5, exact = 4 * (0.05 / 4) * (1 / l - std::pow(l, -7)) * (150 + 30 * l * l);
    const double p = c.rows.back().values[Capture::column(m, "pressure_kPa")];
    std::printf("MR sac, %d elements, from rest: p = %.6f kPa at lambda 2.5 (closed form %.6f), at most %d iterations\n",
                elements, p, exact, most);
    EXPECT_NEAR(p, exact, 1e-3 * exact);
  }
}

TEST(VolumeControlFromRest, TheFineSacFailsWithThePlainStartAndTheStopSaysToLeaveItOut) {
  const Model m = read_deck_text(sac(1000, "exact"), "sac.yaml");
  Capture c;
  Analysis a(m);
  try {
    a.run(c);
    ADD_FAILURE() << "the plain start converged";
  } catch (const SolveError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("no increment converged from the stress-free reference state"), std::string::npos) << what;
    EXPECT_NE(what.find("`stress_free_start: exact`"), std::string::npos) << what;
    EXPECT_NE(what.find("leave it out"), std::string::npos) << what;
  }
}

namespace {

/// A flat neo-Hookean disc (radius 10 mm, H 0.5 mm, μ 50 kPa, rim held, the bulge test), its
/// pressure from below (`flip`), inflated under volume control from its flat rest state (V₀ = 0)
/// to 1500 mm³ in `increments`: `control` is the step's load.
std::string disc(const std::string& control, int increments) {
  return fmt::format(R"(title: bulge test from a flat disc
units: {{length: mm, force: N}}
materials:
  tissue: {{type: neo_hookean, mu: 50 kPa}}
parts:
  disc:
    element: axisymmetric_membrane
    material: tissue
    thickness: 0.5 mm
    mesh: {{type: line, from: [0 mm, 0 mm], to: [10 mm, 0 mm], elements: 40}}
boundary:
  centre: {{node_set: disc.start, dofs: [r]}}
  rim: {{node_set: disc.end, dofs: [r, z]}}
loads:
  bp: {{type: pressure, part: disc, flip: true}}
steps:
  - {{name: bulge, increments: {}, {}}}
output:
  vtk: false
  history:
    - {{quantity: pressure, load: bp, unit: kPa}}
    - {{quantity: volume, load: bp, unit: mm^3}}
)",
                     increments, control);
}

}  // namespace

TEST(VolumeControlFromRest, AFlatDiscBulgesFromZeroVolume) {
  // At rest the sheet has no curvature, no pressure and no normal stiffness: the bordered matrix
  // of K alone is singular, and the start seeds p̂ with μ₀H/ℓ (solver/volume_start.hpp).
  ::Run vc;
  ASSERT_NO_THROW(vc = run(disc("volume_control: {load: bp, volume: 1500 mm^3}", 20)));
  EXPECT_NEAR(vc.V0, 0, 1e-12);
  EXPECT_EQ(vc.cutbacks, 0);
  EXPECT_NEAR(vc.volume, 1500, 1e-8 * 1500);
  EXPECT_GT(vc.pressure, 0);
  // The pressure found, applied under pressure control, bulges the disc to the same volume.
  const ::Run pc = run(disc(fmt::format("set: {{bp: {:.12g} kPa}}", vc.pressure), 20));
  EXPECT_NEAR(pc.volume, 1500, 1e-6 * 1500);
  std::printf("flat disc from rest: p = %.6f kPa at 1500 mm^3; pressure control to it: V = %.9f mm^3\n", vc.pressure,
              pc.volume);
}
