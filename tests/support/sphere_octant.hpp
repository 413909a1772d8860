#pragma once
// The thin neo-Hookean sphere octant of theory manual (8.3) (R = 1 mm, H = 0.01 mm, μ = 1 MPa,
// symmetry planes) inflated by a follower pressure to the closed-form value at λ = 1.2. Its meshes:
//  - the deck's `octant` generator: 4-node membranes, n × n quads per cube-projection patch (3n²);
//  - Gmsh 2.2 files of 3-node or 6-node triangles (lattice_msh.hpp), mid-edge nodes on the exact
//    sphere, on one of two lattices: `cube`, the generator's cube-projection patches with each quad
//    split into two triangles (6n², the same corners as the quads), or `octahedron`, the face
//    x + y + z = R of the octahedron projected on the sphere (n²; the lattice of
//    tests/regression/test_tri6_convergence.cpp).
// Shared by tests/regression/test_line_search.cpp, test_stress_free_start.cpp,
// test_tri6_convergence.cpp and bench/bench.cpp (which includes it by its relative path);
// bench/peers/sphere_tunica.sh writes the quad problem in shell, with history output and VTK files.
#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "lattice_msh.hpp"

namespace tunica::test {

/// Theory manual (8.3): p = 2 μ (H/R)(λ⁻¹ − λ⁻⁷), μ = 1 MPa, H/R = 0.01, λ = 1.2 (MPa = N/mm²).
inline double sphere_octant_pressure() {
  const double l = 1.2;
  return 2.0 * 1.0 * 0.01 * (1.0 / l - std::pow(l, -7));
}

/// The raw error of the sphere's pressure against the closed form, the measure of bench/peers/ for
/// every code and mesh: p / p_closed(λ) − 1 with λ the mean radius of all nodes (a 6-node
/// triangle's mid-edge nodes included) at the positions `x(n)`, n < `nodes`, over R = 1 mm.
template <class Position>
double sphere_octant_p_error(int nodes, const Position& x, double p = sphere_octant_pressure()) {
  double r = 0;
  for (int n = 0; n < nodes; ++n) r += x(n).norm();
  const double l = r / nodes;
  return p / (2.0 * 1.0 * 0.01 * (1.0 / l - std::pow(l, -7))) - 1.0;
}

/// The lattices of a triangle octant written as a Gmsh file (see the top of this file).
enum class OctantLattice { cube, octahedron };

inline OctantLattice octant_lattice(const std::string& name) {
  if (name == "cube") return OctantLattice::cube;
  if (name == "octahedron") return OctantLattice::octahedron;
  throw std::invalid_argument("octant lattice must be cube or octahedron, not " + name);
}

/// Triangles of the octant x, y, z ≥ 0 of the sphere of radius R (order 1 or 2) as a writer, with
/// the node sets of the `octant` generator: x0, y0, z0 (the symmetry planes), pole (the node on +z).
///  - cube: n × n cells per cube face x = R, y = R, z = R, the lattice point l ∈ [0, 2n]³ at the
///    equal-angle cube coordinates u(a) = tan((π/4) a/(2n)) projected radially, so that the corners
///    (even l) are the generator's nodes bit for bit; each cell split along a–c or b–d alternately,
///    as the generator's `shape: triangle`: 6n² triangles.
///  - octahedron: lattice point (I, J) of 2n at (2n − I − J) e_x + I e_y + J e_z, projected: n²
///    triangles.
inline MshWriter sphere_octant_lattice(int n, int order, OctantLattice lattice, double R = 1.0) {
  if (n < 1 || (order != 1 && order != 2)) throw std::invalid_argument("sphere_octant_lattice: n >= 1, order 1 or 2");
  MshWriter w;
  const int m = 2 * n;
  if (lattice == OctantLattice::octahedron) {
    const auto at = [m, R](const LatticePoint& l) {
      const Eigen::Vector3d p(m - l[0] - l[1], l[0], l[1]);
      return Eigen::Vector3d(R * p / p.norm());
    };
    lattice_triangles(w, n, n, order, true, at);
    w.sets["x0"] = w.nodes_where([m](const LatticePoint& l) { return l[0] + l[1] == m; });
    w.sets["y0"] = w.nodes_where([](const LatticePoint& l) { return l[0] == 0; });
    w.sets["z0"] = w.nodes_where([](const LatticePoint& l) { return l[1] == 0; });
    w.sets["pole"] = w.nodes_where([m](const LatticePoint& l) { return l[1] == m; });
    return w;
  }
  std::vector<double> u(m + 1);
  for (int a = 0; a <= m; ++a) u[a] = std::tan((std::numbers::pi / 4) * a / m);
  u[0] = 0.0;
  u[m] = 1.0;
  const auto at = [&u, R](const LatticePoint& l) {
    const Eigen::Vector3d c(u[l[0]], u[l[1]], u[l[2]]);
    Eigen::Vector3d x = c * (R / c.norm());
    for (int d = 0; d < 3; ++d)
      if (c(d) == 0.0) x(d) = 0.0;  // exactly on the symmetry plane
    return x;
  };
  for (int axis = 0; axis < 3; ++axis) {
    const int e1 = (axis + 1) % 3, e2 = (axis + 2) % 3;
    for (int b = 0; b < n; ++b)
      for (int a = 0; a < n; ++a) {
        const auto P = [&](int p, int q) {
          LatticePoint l{};
          l[axis] = m;
          l[e1] = 2 * p;
          l[e2] = 2 * q;
          return l;
        };
        const LatticePoint A = P(a, b), B = P(a + 1, b), C = P(a + 1, b + 1), D = P(a, b + 1);
        if ((a + b) % 2 == 0) {
          w.triangle({A, B, C}, order, at);
          w.triangle({A, C, D}, order, at);
        } else {
          w.triangle({A, B, D}, order, at);
          w.triangle({B, C, D}, order, at);
        }
      }
  }
  w.sets["x0"] = w.nodes_where([](const LatticePoint& l) { return l[0] == 0; });
  w.sets["y0"] = w.nodes_where([](const LatticePoint& l) { return l[1] == 0; });
  w.sets["z0"] = w.nodes_where([](const LatticePoint& l) { return l[2] == 0; });
  w.sets["pole"] = w.nodes_where([](const LatticePoint& l) { return l[0] == 0 && l[1] == 0; });
  return w;
}

/// A part's mesh in the sphere deck: its `mesh:` flow map and the prefix of its node sets
/// ("balloon." for the generator's, "" for a Gmsh file's physical names).
struct OctantMesh {
  std::string mesh;
  std::string sets;
};

/// The `octant` generator: 3n² quads (`triangles`: each split in two, 6n²).
inline OctantMesh octant_generator_mesh(int n, bool triangles = false) {
  return {fmt::format("{{type: octant, radius: 1 mm, n: {}{}}}", n, triangles ? ", shape: triangle" : ""), "balloon."};
}

/// Writes sphere_octant_lattice(n, order, lattice) to `path`; the deck names it by `file` (the path
/// as the deck should read it: relative to the deck's folder, or absolute).
inline OctantMesh octant_msh_mesh(const std::string& path, const std::string& file, int n, int order,
                                  OctantLattice lattice) {
  sphere_octant_lattice(n, order, lattice).write(path);
  return {fmt::format("{{type: gmsh, file: '{}', surface: wall}}", file), ""};
}

/// The deck: `solver` is inserted as it is before `steps:` (a whole `solver: {…}` line with its
/// newline, or empty); one step `inflate` to sphere_octant_pressure() in `increments`; `output`
/// is the output map (default: no VTK).
inline std::string sphere_octant_deck(const std::string& title, const OctantMesh& mesh, const std::string& solver,
                                      int increments, const std::string& output = "{vtk: false}") {
  return fmt::format(R"(title: {0}
units: {{length: mm, force: N}}
materials:
  rubber: {{type: neo_hookean, mu: 1 MPa}}
parts:
  balloon:
    element: membrane
    material: rubber
    thickness: 0.01 mm
    mesh: {1}
boundary:
  sym_x: {{node_set: {5}x0, dofs: [x]}}
  sym_y: {{node_set: {5}y0, dofs: [y]}}
  sym_z: {{node_set: {5}z0, dofs: [z]}}
loads:
  inflation: {{type: pressure, part: balloon}}
{2}steps:
  - {{name: inflate, increments: {3}, set: {{inflation: {4:.17g}}}}}
output: {6}
)",
                     title, mesh.mesh, solver, increments, sphere_octant_pressure(), mesh.sets, output);
}

/// The deck with the generator's 3n² quads.
inline std::string sphere_octant_deck(const std::string& title, int n, const std::string& solver, int increments) {
  return sphere_octant_deck(title, octant_generator_mesh(n), solver, increments);
}

}  // namespace tunica::test
