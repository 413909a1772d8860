#pragma once
// The thin neo-Hookean sphere octant of theory manual (8.3) (R = 1 mm, H = 0.01 mm, μ = 1 MPa; 4-node
// membranes, n × n quads per patch, symmetry planes) inflated by a follower pressure to the
// closed-form value at λ = 1.2. Shared by tests/regression/test_line_search.cpp and
// bench/bench.cpp (which includes it by its relative path); bench/peers/sphere_tunica.sh writes
// the same problem in shell, with history output and VTK files.
#include <fmt/format.h>

#include <cmath>
#include <string>

namespace tunica::test {

/// Theory manual (8.3): p = 2 μ (H/R)(λ⁻¹ − λ⁻⁷), μ = 1 MPa, H/R = 0.01, λ = 1.2 (MPa = N/mm²).
inline double sphere_octant_pressure() {
  const double l = 1.2;
  return 2.0 * 1.0 * 0.01 * (1.0 / l - std::pow(l, -7));
}

/// The deck: `solver` is inserted as it is before `steps:` (a whole `solver: {…}` line with its
/// newline, or empty); one step `inflate` to sphere_octant_pressure() in `increments`; no VTK.
inline std::string sphere_octant_deck(const std::string& title, int n, const std::string& solver, int increments) {
  return fmt::format(R"(title: {0}
units: {{length: mm, force: N}}
materials:
  rubber: {{type: neo_hookean, mu: 1 MPa}}
parts:
  balloon:
    element: membrane
    material: rubber
    thickness: 0.01 mm
    mesh: {{type: octant, radius: 1 mm, n: {1}}}
boundary:
  sym_x: {{node_set: balloon.x0, dofs: [x]}}
  sym_y: {{node_set: balloon.y0, dofs: [y]}}
  sym_z: {{node_set: balloon.z0, dofs: [z]}}
loads:
  inflation: {{type: pressure, part: balloon}}
{2}steps:
  - {{name: inflate, increments: {3}, set: {{inflation: {4:.17g}}}}}
output: {{vtk: false}}
)",
                     title, n, solver, increments, sphere_octant_pressure());
}

}  // namespace tunica::test
