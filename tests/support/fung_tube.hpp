#pragma once
// The closed 3-D Fung tube of the benchmark (the rat aorta of theory manual §12.1: R = 0.763 mm,
// H = 0.122 mm), length 2πR, ends free to slide radially (held on the planes x = 0 and y = 0
// against rigid motion), circumferential/axial frame, staggered triangles (around = along),
// stretched axially to λz = 1.3 with 40 mmHg in 4 increments, then inflated to 120 mmHg.
// Shared by bench/bench.cpp (which includes it by its relative path) and the tests. Also the
// closed form of the rat aorta's thin tube (theory manual (3.2), (8.1)): namespace fung_tube.
#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <string>

namespace tunica::test {

/// The deck with `around` × `around` split quads: `solver` is inserted as it is before `steps:`
/// (a whole `solver: {…}` line with its newline, or empty); `increments` for the inflation,
/// `prestretch_increments` for the prestretch.
inline std::string fung_tube_deck(int around, const std::string& solver, int increments, int prestretch_increments = 4) {
  const double length = 2 * std::numbers::pi * 0.763;
  return fmt::format(R"(title: bench Fung tube, {0} x {0} split quads
units: {{length: mm, force: N}}
materials:
  aorta: {{type: fung, c: 61.163 kPa, a1: 0.68238, a2: 0.60558, a4: 0.1067}}
parts:
  wall:
    element: membrane
    material: aorta
    thickness: 0.122 mm
    mesh: {{type: tube, radius: 0.763 mm, length: {1} mm, around: {0}, along: {0}, shape: staggered_triangle}}
    frame: {{type: cylindrical, axis: [0, 0, 1]}}
boundary:
  base: {{node_set: wall.bottom, dofs: [z]}}
  stretch: {{node_set: wall.top, dofs: [z]}}
  sym_x: {{node_set: wall.x0, dofs: [x]}}
  sym_y: {{node_set: wall.y0, dofs: [y]}}
loads:
  lumen: {{type: pressure, part: wall}}
{2}steps:
  - {{name: prestretch, increments: {5}, set: {{stretch: {4} mm, lumen: 40 mmHg}}}}
  - {{name: inflation, increments: {3}, set: {{lumen: 120 mmHg}}}}
output: {{vtk: false}}
)",
                     around, length, solver, increments, 0.3 * length, prestretch_increments);
}

}  // namespace tunica::test

// The rat aorta's data (examples/rat-aorta-3d.yaml) and the thin tube's hoop stretch at a given
// hoop stress (theory manual (3.2), (8.1)).
namespace tunica::test::fung_tube {

constexpr double c = 61.163, a1 = 0.68238, a2 = 0.60558, a4 = 0.1067;  // kPa
constexpr double R = 0.763, H = 0.122, lz = 1.6;                          // mm
constexpr double mmHg_kPa = 0.133322387415;

inline double S1(double E1, double E2) {
  return 2 * c * (a1 * E1 + a4 * E2) * std::exp(a1 * E1 * E1 + a2 * E2 * E2 + 2 * a4 * E1 * E2);
}
inline double S2(double E1, double E2) {
  return 2 * c * (a4 * E1 + a2 * E2) * std::exp(a1 * E1 * E1 + a2 * E2 * E2 + 2 * a4 * E1 * E2);
}

/// E_θ with S1(E_θ, E_z) = target (bisection).
inline double solve_E_theta(double target, double Ez) {
  double lo = -0.49, hi = 3.0;
  for (int k = 0; k < 200; ++k) {
    const double mid = 0.5 * (lo + hi);
    (S1(mid, Ez) < target ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace tunica::test::fung_tube
