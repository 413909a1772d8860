// The 6-node quadratic triangle membrane (tri6, Gmsh type 9) against closed forms, with
// its convergence order in the element size measured, beside the 3-node triangle on the
// same node lattice (theory manual §5, §8):
//  - a neo-Hookean spherical balloon (an octant with symmetry planes) inflated by pressure
//    to below its maximum, p = 2μ(H/R)(λ⁻¹ − λ⁻⁷) (theory manual (8.3)): the error of the
//    enclosed volume and of the pole's radius against the sphere of stretch λ(p);
//  - the rat-aorta Fung tube (examples/rat-aorta-3d.yaml) prestretched and inflated, against
//    the thin-tube closed form (8.1): the error of λθ, Sθ, Sz and h against the circle.
// The meshes are written as Gmsh 2.2 files (tests/support/lattice_msh.hpp): an octahedron face's
// lattice projected on the sphere (sphere_octant.hpp), a quarter cylinder's (θ, z) lattice; quadratic elements take their mid-edge
// nodes on the exact surface (as Gmsh does with Mesh.ElementOrder = 2), linear ones the
// corners of the same lattice. Flat facets err by O(h²) in the geometry; curved 6-node
// elements by O(h³) or better.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <numbers>
#include <vector>

#include <fmt/format.h>

#include "../support/capture.hpp"
#include "../support/scratch.hpp"
#include "../support/fung_tube.hpp"
#include "../support/lattice_msh.hpp"
#include "../support/sphere_octant.hpp"

using namespace tunica;
using namespace tunica::test;
namespace fs = std::filesystem;

namespace {

// ---- sphere ----------------------------------------------------------------------------------

constexpr double kMu = 1.0, kR = 1.0, kH = 0.01;  // MPa, mm, mm

double sphere_pressure(double l) { return 2 * kMu * (kH / kR) * (1 / l - std::pow(l, -7)); }  // (8.3)

/// The octant x, y, z ≥ 0: the octahedron face's lattice projected on the sphere
/// (sphere_octant.hpp, n² triangles; node sets x0, y0, z0, pole).
fs::path octant_msh(int n, int order) {
  const fs::path path = scratch("tri6-convergence") / fmt::format("octant-{}-{}.msh", n, order);
  sphere_octant_lattice(n, order, OctantLattice::octahedron, kR).write(path.string());
  return path;
}

struct SphereError {
  double volume = 0, pole = 0;  ///< relative errors of V and of the pole's height at the last increment
  int max_iterations = 0;
  int unknowns = 0;
};

SphereError sphere(int n, int order) {
  // λ = 1.25 (below the maximum at 7^(1/6) ≈ 1.383): p(λ) from the closed form.
  const double lambda = 1.25, p = sphere_pressure(lambda);
  const std::string deck = fmt::format(R"(title: tri6 sphere
units: {{length: mm, force: N}}
materials:
  rubber: {{type: neo_hookean, mu: {} MPa}}
parts:
  balloon:
    element: membrane
    material: rubber
    thickness: {} mm
    mesh: {{type: gmsh, file: {}, surface: wall}}
boundary:
  sym_x: {{node_set: x0, dofs: [x]}}
  sym_y: {{node_set: y0, dofs: [y]}}
  sym_z: {{node_set: z0, dofs: [z]}}
loads:
  inflation: {{type: pressure, part: balloon}}
solver: {{residual_tolerance: 1e-11}}
steps:
  - name: inflate
    increments: 8
    set: {{inflation: {:.17g} MPa}}
output:
  vtk: false
  history:
    - {{quantity: volume, load: inflation, unit: mm^3}}
    - {{quantity: position_z, node_set: pole, name: pole_z, unit: mm}}
)",
                                       kMu, kH, octant_msh(n, order).string(), p);
  const Model m = read_deck_text(deck, (scratch("tri6-convergence") / "sphere.yaml").string());
  Capture cap;
  Analysis a(m);
  a.run(cap);
  EXPECT_EQ(cap.cutbacks, 0);
  SphereError e;
  const Row& last = cap.rows.back();
  const double V = last.values[Capture::column(m, "volume_mm3")], z = last.values[Capture::column(m, "pole_z_mm")];
  const double V_exact = std::pow(lambda * kR, 3) * std::numbers::pi / 6;
  e.volume = std::abs(V / V_exact - 1);
  e.pole = std::abs(z / (lambda * kR) - 1);
  for (const auto& it : cap.iterations) e.max_iterations = std::max(e.max_iterations, it.rec.iteration);
  e.unknowns = a.system().num_free();
  return e;
}

}  // namespace

TEST(Tri6Convergence, SphereVolumeAndPoleConvergeFasterThanFlatTriangles) {
  const std::vector<int> ns = {2, 4, 8, 16};
  std::vector<SphereError> e6, e3;
  for (int n : ns) {
    e6.push_back(sphere(n, 2));
    e3.push_back(sphere(2 * n, 1));  // the same nodes: the tri3 mesh of the tri6 mesh's lattice
  }
  std::printf("sphere octant, λ = 1.25: relative errors (volume, pole) by elements per edge\n");
  for (std::size_t k = 0; k < ns.size(); ++k)
    std::printf("  n = %d: tri6 %.3e %.3e (≤ %d iterations, %d unknowns) | tri3 (n = %d) %.3e %.3e\n", ns[k], e6[k].volume,
                e6[k].pole, e6[k].max_iterations, e6[k].unknowns, 2 * ns[k], e3[k].volume, e3[k].pole);
  for (std::size_t k = 1; k < ns.size(); ++k) {
    const double r6v = std::log2(e6[k - 1].volume / e6[k].volume), r6p = std::log2(e6[k - 1].pole / e6[k].pole);
    const double r3v = std::log2(e3[k - 1].volume / e3[k].volume);
    std::printf("  rates %d → %d: tri6 volume %.2f, pole %.2f; tri3 volume %.2f\n", ns[k - 1], ns[k], r6v, r6p, r3v);
    EXPECT_GT(r6v, 2.8);
    EXPECT_GT(r6p, 2.8);
    EXPECT_NEAR(r3v, 2.0, 0.3);
  }
  // On the same nodes, the curved elements are far closer than the flat facets.
  EXPECT_LT(e6.back().volume, 0.1 * e3.back().volume);
  for (const auto& e : e6) EXPECT_LE(e.max_iterations, 8);
}

namespace {

// ---- tube --------------------------------------------------------------------------------------

namespace ft = fung_tube;
constexpr double kLength = 1.0;  // mm

/// A quarter of the tube, θ ∈ [0, π/2] (`around` cells), z ∈ [0, L] (`along` cells), each cell two
/// triangles; lattice point (I, J) at θ = I π/(4 around), z = J L/(2 along), on the cylinder.
fs::path tube_msh(int around, int along, int order) {
  MshWriter w;
  const auto at = [=](const LatticePoint& l) {
    const double t = l[0] * std::numbers::pi / (4 * around);
    return Eigen::Vector3d(ft::R * std::cos(t), ft::R * std::sin(t), l[1] * kLength / (2 * along));
  };
  lattice_triangles(w, around, along, order, false, at);
  w.sets["x0"] = w.nodes_where([=](const LatticePoint& l) { return l[0] == 2 * around; });
  w.sets["y0"] = w.nodes_where([](const LatticePoint& l) { return l[0] == 0; });
  w.sets["bottom"] = w.nodes_where([](const LatticePoint& l) { return l[1] == 0; });
  w.sets["top"] = w.nodes_where([=](const LatticePoint& l) { return l[1] == 2 * along; });
  const fs::path path = scratch("tri6-convergence") / fmt::format("tube-{}-{}-{}.msh", around, along, order);
  w.write(path.string());
  return path;
}

struct TubeError {
  double hoop = 0;  ///< largest relative error of λθ, Sθ, Sz, h against the circle's closed form, over the inflation
  int increments = 0, max_iterations = 0, unknowns = 0;
};

TubeError tube(int around, int order) {
  const std::string kDeck = std::string(TUNICA_SOURCE_DIR) + "/examples/rat-aorta-3d.yaml";
  std::string text = read_text(kDeck);
  text = replace(text, "mesh: {type: tube, radius: 0.763 mm, length: 1 mm, sector: 90 deg, around: 8, along: 2}",
                 "mesh: {type: gmsh, file: " + tube_msh(around, 2, order).string() + ", surface: wall}");
  for (const std::string set : {"x0", "y0", "bottom", "top"}) {
    text = replace(text, "node_set: wall." + set + ",", "node_set: " + set + ",");
  }
  text = replace(text, "node_set: wall.top, name:", "node_set: top, name:");
  const Model m = read_deck_text(text, kDeck);
  Capture cap;
  Analysis a(m);
  a.run(cap);
  EXPECT_EQ(cap.cutbacks, 0);
  const int p = Capture::column(m, "pressure_mmHg"), lt = Capture::column(m, "lambda_theta"),
            st = Capture::column(m, "S_theta_kPa"), sz = Capture::column(m, "S_z_kPa"), h = Capture::column(m, "thickness_mm");
  TubeError e;
  const double Ez = 0.5 * (ft::lz * ft::lz - 1);
  for (const Row& row : cap.rows) {
    if (row.info.step != 2) continue;
    const double pk = row.values[p] * ft::mmHg_kPa;
    const double St = pk * ft::R * ft::lz / ft::H;  // theory manual (8.1): Sθ = p R λz / H
    const double Et = ft::solve_E_theta(St, Ez);
    const double lt_exact = std::sqrt(2 * Et + 1), Sz = ft::S2(Et, Ez), h_exact = ft::H / (lt_exact * ft::lz);
    for (double err : {std::abs(row.values[lt] / lt_exact - 1), std::abs(row.values[st] / St - 1),
                       std::abs(row.values[sz] / Sz - 1), std::abs(row.values[h] / h_exact - 1)})
      e.hoop = std::max(e.hoop, err);
    ++e.increments;
  }
  for (const auto& it : cap.iterations) e.max_iterations = std::max(e.max_iterations, it.rec.iteration);
  e.unknowns = a.system().num_free();
  return e;
}

}  // namespace

TEST(Tri6Convergence, FungTubeConvergesFasterThanFlatTriangles) {
  const std::vector<int> arounds = {2, 4, 8};
  std::vector<TubeError> e6, e3;
  for (int n : arounds) {
    e6.push_back(tube(n, 2));
    e3.push_back(tube(2 * n, 1));
  }
  std::printf("Fung tube quarter: largest relative error of λθ, Sθ, Sz, h over the inflation, by cells around\n");
  for (std::size_t k = 0; k < arounds.size(); ++k)
    std::printf("  %d around: tri6 %.3e (≤ %d iterations, %d unknowns) | tri3 (%d around) %.3e (%d unknowns)\n", arounds[k], e6[k].hoop,
                e6[k].max_iterations, e6[k].unknowns, 2 * arounds[k], e3[k].hoop, e3[k].unknowns);
  for (std::size_t k = 1; k < arounds.size(); ++k) {
    const double r6 = std::log2(e6[k - 1].hoop / e6[k].hoop), r3 = std::log2(e3[k - 1].hoop / e3[k].hoop);
    std::printf("  rates %d → %d around: tri6 %.2f, tri3 %.2f\n", arounds[k - 1], arounds[k], r6, r3);
    EXPECT_GT(r6, 2.8);
  }
  EXPECT_LT(e6.back().hoop, 0.1 * e3.back().hoop);
  for (const auto& e : e6) EXPECT_EQ(e.increments, 19);
}
