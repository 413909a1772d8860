// A 3-D membrane step without pressure (theory manual §7.3, (7.11)): a closed HGO tube of
// 128 × 40 quadrilaterals stretched axially to λz = 1.2 alone, from rest, with the defaults. Its wall
// carries no hoop tension and the tangent is singular along the ovalizing modes; with the plain
// Newton step the run stopped after five cut-backs (relative residual 5e-6 at the iteration
// limit), the regularized one converges in every increment without a cut-back, stays round to
// round-off, and its hoop stretch is the axisymmetric model's (a uniform tube of flat facets
// has no discretization error: each facet's stretches are the tube's).
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "../support/capture.hpp"

using namespace tunica;
using namespace tunica::test;

namespace {

const char* const kMaterial = "{type: hgo, mu: 30 kPa, k1: 100 kPa, k2: 5, beta: 40 deg}";

std::string tube3d() {
  return fmt::format(R"(units: {{length: mm, force: N}}
materials:
  artery: {}
parts:
  wall:
    element: membrane
    material: artery
    thickness: 0.3 mm
    mesh: {{type: tube, radius: 2 mm, length: 10 mm, around: 128, along: 40}}
    frame: {{type: cylindrical, axis: [0, 0, 1], point: [0, 0, 0]}}
boundary:
  sym_x:   {{node_set: wall.x0, dofs: [x]}}
  sym_y:   {{node_set: wall.y0, dofs: [y]}}
  base:    {{node_set: wall.bottom, dofs: [z]}}
  stretch: {{node_set: wall.top, dofs: [z]}}
loads:
  blood: {{type: pressure, part: wall, volume_axis: [0, 0, 1]}}
steps:
  - {{name: prestretch, increments: 4, set: {{stretch: 2 mm}}}}
output:
  vtk: false
  history:
    - {{quantity: radius, part: wall, name: rmin, reduce: min, unit: mm}}
    - {{quantity: radius, part: wall, name: rmax, reduce: max, unit: mm}}
    - {{quantity: lambda_1, part: wall, name: l1}}
    - {{quantity: sigma_1, part: wall, name: s1max, reduce: max, unit: MPa}}
    - {{quantity: sigma_2, part: wall, name: s2, unit: MPa}}
)",
                     kMaterial);
}

std::string tube_axisym() {
  return fmt::format(R"(units: {{length: mm, force: N}}
materials:
  artery: {}
parts:
  wall:
    element: axisymmetric_membrane
    material: artery
    thickness: 0.3 mm
    mesh: {{type: line, from: [2 mm, 0 mm], to: [2 mm, 10 mm], elements: 2}}
boundary:
  base:    {{node_set: wall.start, dofs: [z]}}
  stretch: {{node_set: wall.end, dofs: [z]}}
steps:
  - {{name: prestretch, increments: 4, set: {{stretch: 2 mm}}}}
output:
  vtk: false
  history:
    - {{quantity: lambda_1, part: wall, name: l1}}
    - {{quantity: sigma_2, part: wall, name: s2, unit: MPa}}
)",
                     kMaterial);
}

}  // namespace

TEST(SlackStep, AClosedTubeStretchedAloneConvergesRoundWithTheDefaults) {
  const Model m = read_deck_text(tube3d(), "tube.yaml");
  Capture c;
  Analysis a(m);
  a.run(c);
  EXPECT_EQ(c.cutbacks, 0);
  EXPECT_TRUE(c.retries.empty());
  ASSERT_EQ(c.rows.size(), 5u);  // the reference state and 4 increments
  for (std::size_t k = 1; k < c.rows.size(); ++k) EXPECT_LE(c.rows[k].info.iterations, 4) << "increment " << k;

  const Model ma = read_deck_text(tube_axisym(), "axisym.yaml");
  Capture ca;
  Analysis aa(ma);
  aa.run(ca);
  const auto& last = c.rows.back().values;
  const double lt = ca.rows.back().values[Capture::column(ma, "l1")];
  ASSERT_LT(lt, 0.9);  // the wall contracts: λθ = 0.863
  const double rmin = last[Capture::column(m, "rmin_mm")], rmax = last[Capture::column(m, "rmax_mm")];
  EXPECT_LT(rmax - rmin, 1e-8) << "the cross-section stays round";
  EXPECT_NEAR(last[Capture::column(m, "l1")], lt, 1e-8);
  // The Gauss points lie on the facets' chords, at R √(1 − ⅔ sin²(π/128)) from the axis.
  const double s = std::sin(std::numbers::pi / 128);
  EXPECT_NEAR(rmax / (2 * std::sqrt(1 - 2 * s * s / 3)), lt, 1e-8);
  EXPECT_NEAR(last[Capture::column(m, "s2_MPa")], ca.rows.back().values[Capture::column(ma, "s2_MPa")], 1e-8);
  EXPECT_LT(std::abs(last[Capture::column(m, "s1max_MPa")]), 1e-8) << "no hoop stress";
}
