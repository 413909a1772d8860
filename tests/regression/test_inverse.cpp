// The inverse step (theory manual §13): the zero-pressure geometry of an imaged, loaded membrane.
//  - Round trips: a forward inflation on a mesh, then the inverse step on the same mesh at the
//    deformed positions and the same pressure, recovers the reference nodes to 1e-8 relative at
//    every mesh size: forward and inverse solve the same discrete equations (axisymmetric sphere,
//    3-D octant of a sphere of quadrilaterals and of triangles).
//  - Closed forms: a neo-Hookean sphere imaged at radius r under p has the reference radius R with
//    p = 2μ(H/R)(λ⁻¹ − λ⁻⁷), λ = r/R, H the reference thickness ((8.3), (13.9)): the error of the
//    inverse's R and its order in the element size; the paper's rat aorta imaged at 120 mmHg gives
//    back its load-free R = 0.763 mm and length.
//  - The reference geometry written as a mesh file is a deck that inflates back to the imaged nodes.
//  - A pressure the imaged shape cannot carry (beyond the sphere's pressure maximum) stops with a
//    message naming the step, and the converged increments are kept.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "../support/capture.hpp"
#include "../support/lattice_msh.hpp"
#include "../support/scratch.hpp"
#include "../support/sphere_octant.hpp"
#include "output/reference_mesh.hpp"

using namespace tunica;
using namespace tunica::test;

namespace {

const std::string kAxisym = std::string(TUNICA_SOURCE_DIR) + "/examples/balloon-sphere.yaml";
const std::string k3d = std::string(TUNICA_SOURCE_DIR) + "/examples/balloon-sphere-3d.yaml";
const char* kTight = "\nsolver: {residual_tolerance: 1e-12}\n";

/// The axisymmetric balloon example with `elements` elements, inflated to p (MPa) in `increments`.
std::string axisym_deck(int elements, double p, int increments) {
  std::string t = replace(read_text(kAxisym), "elements: 100", "elements: " + std::to_string(elements));
  t = replace(t, "increments: 20", "increments: " + std::to_string(increments));
  return replace(t, "set: {inflation: 0.0118 MPa}", "set: {inflation: " + std::to_string(p) + " MPa}") + kTight;
}

/// The 3-D octant example of n × n elements per face (`shape`: "" or ", shape: triangle"), inflated
/// to 0.011 MPa in 10 increments rather than by volume control.
std::string octant_deck(int n, const std::string& shape) {
  std::string t = replace(read_text(k3d), "n: 8}", "n: " + std::to_string(n) + shape + "}");
  t = replace(t, "increments: 40\n    volume_control: {load: inflation, volume: 4.45 mm^3}   # 8.5 × π/6 mm³",
              "increments: 10\n    set: {inflation: 0.011 MPa}");
  return t + kTight;
}

/// `deck` with its (only) step made an inverse one.
std::string inverse_of(const std::string& deck, const std::string& step_name) {
  return replace(deck, "name: " + step_name, "name: zero_pressure\n    type: inverse");
}

/// Positions X + u of every node.
std::vector<Eigen::Vector3d> positions(const Model& m, const Eigen::VectorXd& u) {
  std::vector<Eigen::Vector3d> x = m.X;
  const int d = m.dofs_per_node();
  for (int n = 0; n < m.num_nodes(); ++n)
    for (int c = 0; c < d; ++c) x[n](c) += u(d * n + c);
  return x;
}

struct Inverse {
  std::vector<Eigen::Vector3d> X;  ///< the reference positions found, x̂ + u
  int increments = 0, max_iterations = 0, cutbacks = 0;
};

/// Runs the inverse deck `text` with the imaged positions x̂ in place of its mesh's.
Inverse run_inverse(const std::string& text, const std::string& file, const std::vector<Eigen::Vector3d>& imaged) {
  Model m = read_deck_text(text, file);
  if (!imaged.empty()) m.X = imaged;
  Capture cap;
  Analysis a(m);
  a.run(cap);
  Inverse r;
  r.X = positions(m, a.displacement());
  r.increments = static_cast<int>(cap.rows.size()) - 1;
  r.cutbacks = cap.cutbacks;
  for (const auto& it : cap.iterations) r.max_iterations = std::max(r.max_iterations, it.rec.iteration);
  return r;
}

struct RoundTrip {
  double error = 0;  ///< max |X_found − X| / max |X|
  int forward_iterations = 0;
  Inverse inverse;
};

RoundTrip round_trip(const std::string& forward, const std::string& file, const std::string& step_name) {
  const Model f = read_deck_text(forward, file);
  Capture cap;
  Analysis a(f);
  a.run(cap);
  RoundTrip r;
  for (const auto& it : cap.iterations) r.forward_iterations = std::max(r.forward_iterations, it.rec.iteration);
  r.inverse = run_inverse(inverse_of(forward, step_name), file, positions(f, a.displacement()));
  double scale = 0;
  for (std::size_t n = 0; n < f.X.size(); ++n) {
    r.error = std::max(r.error, (r.inverse.X[n] - f.X[n]).norm());
    scale = std::max(scale, f.X[n].norm());
  }
  r.error /= scale;
  return r;
}

/// The stretch of a neo-Hookean sphere imaged at radius r under p: with R = r/λ,
/// p = 2μ(H/R)(λ⁻¹ − λ⁻⁷) = (2μH/r)(1 − λ⁻⁶), so λ = (1 − p r/(2μH))^(−1/6), for p < 2μH/r.
double exact_stretch(double p, double mu, double H, double r) { return std::pow(1 - p * r / (2 * mu * H), -1.0 / 6.0); }

}  // namespace

TEST(InverseStep, AxisymmetricRoundTripRecoversTheReferenceAtEveryMeshSize) {
  for (int elements : {10, 40, 160}) {
    const RoundTrip r = round_trip(axisym_deck(elements, 0.0118, 10), kAxisym, "inflate");
    std::printf("axisymmetric sphere, %d elements, 0.0118 MPa: round-trip error %.2e, forward iterations ≤ %d, inverse "
                "%d increments, iterations ≤ %d\n",
                elements, r.error, r.forward_iterations, r.inverse.increments, r.inverse.max_iterations);
    EXPECT_LT(r.error, 1e-8) << elements << " elements";
    EXPECT_EQ(r.inverse.cutbacks, 0);
  }
}

TEST(InverseStep, OctantRoundTripRecoversTheReferenceAtEveryMeshSize) {
  for (const std::string shape : {"", ", shape: triangle"})
    for (int n : {4, 8, 16}) {
      const RoundTrip r = round_trip(octant_deck(n, shape), k3d, "inflate");
      std::printf("3-D octant%s, n = %d, 0.011 MPa: round-trip error %.2e, forward iterations ≤ %d, inverse %d "
                  "increments, iterations ≤ %d\n",
                  shape.c_str(), n, r.error, r.forward_iterations, r.inverse.increments, r.inverse.max_iterations);
      EXPECT_LT(r.error, 1e-8) << "n = " << n << shape;
      EXPECT_EQ(r.inverse.cutbacks, 0);
    }
}

TEST(InverseStep, SixNodeTriangleOctantRoundTripRecoversTheReferenceAtEveryMeshSize) {
  // The octahedron face's lattice on the unit sphere as 6-node triangles, mid-edge nodes on the
  // sphere (tests/support/sphere_octant.hpp, as Gmsh writes Mesh.ElementOrder = 2), neo-Hookean,
  // inflated to λ ≈ 1.2, then the inverse step from the positions reached.
  for (int n : {2, 4, 8}) {
    const std::filesystem::path msh = scratch("inverse-tri6") / fmt::format("octant-{}.msh", n);
    sphere_octant_lattice(n, 2, OctantLattice::octahedron, 1.0).write(msh.string());
    const std::string forward = fmt::format(R"(title: tri6 sphere octant
units: {{length: mm, force: N}}
materials:
  rubber: {{type: neo_hookean, mu: 1 MPa}}
parts:
  balloon:
    element: membrane
    material: rubber
    thickness: 0.01 mm
    mesh: {{type: gmsh, file: {}, surface: wall}}
boundary:
  sym_x: {{node_set: x0, dofs: [x]}}
  sym_y: {{node_set: y0, dofs: [y]}}
  sym_z: {{node_set: z0, dofs: [z]}}
loads:
  inflation: {{type: pressure, part: balloon}}
steps:
  - name: inflate
    increments: 8
    set: {{inflation: 0.0115 MPa}}
output:
  vtk: false
)",
                                            msh.string()) +
                              kTight;
    const RoundTrip r = round_trip(forward, (scratch("inverse-tri6") / "octant.yaml").string(), "inflate");
    std::printf("3-D octant of 6-node triangles, n = %d, 0.0115 MPa: round-trip error %.2e, forward iterations ≤ %d, "
                "inverse %d increments, iterations ≤ %d\n",
                n, r.error, r.forward_iterations, r.inverse.increments, r.inverse.max_iterations);
    EXPECT_LT(r.error, 1e-8) << "n = " << n;
    EXPECT_EQ(r.inverse.cutbacks, 0);
  }
}

TEST(InverseStep, SphereImagedUnderPressureAgreesWithTheClosedFormAsTheForwardDoes) {
  // Imaged: the discrete sphere a forward inflation of R = 1 mm to p = 0.0118 MPa gives (μ = 1 MPa,
  // H = 0.01 mm), of equator radius r_h. The inverse step finds R_h (= 1 mm to the solvers' tolerance,
  // the round trip); the closed form (13.9) at the imaged radius gives R(r_h) = r_h/λ(r_h). Their
  // difference is the discretization error of the equations forward and inverse share, O(h²).
  const double p = 0.0118;
  double previous = 0;
  for (int elements : {10, 20, 40, 80}) {
    const std::string forward = axisym_deck(elements, p, 10);
    const Model f = read_deck_text(forward, kAxisym);
    Capture cap;
    Analysis a(f);
    a.run(cap);
    const std::vector<Eigen::Vector3d> imaged = positions(f, a.displacement());
    const Inverse inv = run_inverse(inverse_of(forward, "inflate"), kAxisym, imaged);
    const double r = imaged.front().x(), Rh = inv.X.front().x();  // the equator node (balloon.start)
    const double R = r / exact_stretch(p, 1.0, 0.01, r);
    const double err = std::abs(Rh / R - 1);
    std::printf("axisymmetric sphere, %d elements, imaged at r_h = %.8f mm under 0.0118 MPa: inverse R_h = %.10f mm, "
                "closed form R(r_h) = %.8f mm, relative error %.3e%s; inverse iterations ≤ %d\n",
                elements, r, Rh, R, err, previous > 0 ? fmt::format(", order {:.2f}", std::log2(previous / err)).c_str() : "",
                inv.max_iterations);
    EXPECT_NEAR(Rh, 1.0, 1e-9) << elements;
    EXPECT_LT(err, 2e-3) << elements;
    if (previous > 0) {
      EXPECT_GT(std::log2(previous / err), 1.8) << elements;
    }
    previous = err;
  }
}

TEST(InverseStep, APressureTheImagedShapeCannotCarryStopsNamingTheStep) {
  // The sphere imaged as above at r_h ≈ 1.25 mm carries at most 2μH/r_h ≈ 0.016 MPa, the supremum of
  // (2μH/r)(1 − λ⁻⁶) over λ (13.9): 0.05 MPa in 4 increments converges at 0.0125 MPa, cuts back and
  // stops below 2μH/r_h.
  const std::string forward = axisym_deck(20, 0.0118, 10);
  const Model f = read_deck_text(forward, kAxisym);
  Capture cf;
  Analysis af(f);
  af.run(cf);
  Model m = read_deck_text(inverse_of(axisym_deck(20, 0.05, 4), "inflate"), kAxisym);
  m.X = positions(f, af.displacement());
  Capture cap;
  Analysis a(m);
  try {
    a.run(cap);
    FAIL() << "converged at a pressure no reference radius carries";
  } catch (const SolveError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("step 1 'zero_pressure'"), std::string::npos) << what;
    EXPECT_NE(what.find("converged increments are kept"), std::string::npos) << what;
    std::printf("sphere imaged at r_h = %.4f mm (2μH/r_h = %.5f MPa), 0.05 MPa: last converged %.6f MPa; %s\n",
                m.X.front().x(), 0.02 / m.X.front().x(), a.loads().pressure[0], what.substr(0, 120).c_str());
  }
  EXPECT_GE(cap.rows.size(), 2u);  // the reference state and the increment at 0.0125 MPa
  EXPECT_GE(a.loads().pressure[0], 0.0125);
  EXPECT_LT(a.loads().pressure[0], 2 * 1.0 * 0.01 / m.X.front().x());
}

TEST(InverseStep, RatAortaImagedAt120mmHgGivesBackThePapersReferenceTube) {
  // The paper's rat aorta (theory manual §12.1; examples/rat-aorta-inflation.yaml): prestretched to
  // λz = 1.6, inflated to 120 mmHg. Its imaged tube (radius r over 1.6 mm) and the inverse step from
  // it, at the same pressure and with the prestretch undone (the reference end 0.6 mm below its
  // imaged position), give back R = 0.763 mm and the length 1 mm, at any number of elements along it.
  const std::string file = std::string(TUNICA_SOURCE_DIR) + "/examples/rat-aorta-inflation.yaml";
  for (int elements : {1, 4, 16}) {
    std::string forward = replace(read_text(file), "elements: 1}", "elements: " + std::to_string(elements) + "}");
    forward = replace(forward, "increments: 20\n    set: {lumen: 200 mmHg}", "increments: 12\n    set: {lumen: 120 mmHg}");
    forward = replace(forward, "residual_tolerance: 1e-10", "residual_tolerance: 1e-12");
    const Model f = read_deck_text(forward, file);
    Capture cap;
    Analysis a(f);
    a.run(cap);
    const std::vector<Eigen::Vector3d> imaged = positions(f, a.displacement());
    std::string inverse = replace(forward, "  - name: prestretch\n    increments: 6\n    set: {stretch: 0.6 mm}",
                                  "  - name: zero_pressure\n    type: inverse\n    increments: 12\n    set: {stretch: -0.6 mm, lumen: 120 mmHg}");
    inverse = replace(inverse, "  - name: inflation\n    increments: 12\n    set: {lumen: 120 mmHg}", "");
    const Inverse inv = run_inverse(inverse, file, imaged);
    double radius = 0, length = inv.X.back().y() - inv.X.front().y();
    for (const auto& X : inv.X) radius = std::max(radius, std::abs(X.x() / 0.763 - 1));
    std::printf("rat aorta imaged at 120 mmHg (r = %.6f mm, length %.4f mm), %d element(s): inverse R within %.2e of "
                "0.763 mm, length %.10f mm, %d increments, iterations ≤ %d\n",
                imaged.front().x(), imaged.back().y() - imaged.front().y(), elements, radius, length, inv.increments,
                inv.max_iterations);
    EXPECT_LT(radius, 1e-8) << elements;
    EXPECT_NEAR(length, 1.0, 1e-10) << elements;
  }
}

TEST(InverseStep, ReferenceMeshFileIsADeckThatInflatesBackToTheImagedGeometry) {
  // The octant imaged under 0.011 MPa (the forward inflation of the generated octant); the inverse step's reference geometry
  // written as a Gmsh mesh (output/reference_mesh.hpp), read by a deck of its own and inflated forward
  // to the same pressure, lands on the imaged nodes.
  const std::string imaged_deck = octant_deck(6, "");
  const Model fwd = read_deck_text(imaged_deck, k3d);
  Capture cf0;
  Analysis af0(fwd);
  af0.run(cf0);
  Model m = read_deck_text(inverse_of(imaged_deck, "inflate"), k3d);
  m.X = positions(fwd, af0.displacement());
  Capture cap;
  Analysis a(m);
  a.run(cap);
  EXPECT_EQ(reference_mesh_name(m, 0), "reference_zero_pressure.msh");
  const std::string dir = ::testing::TempDir() + "tunica-inverse-mesh";
  std::filesystem::create_directories(dir);
  const std::string mesh = dir + "/" + reference_mesh_name(m, 0);
  std::ofstream(mesh) << reference_mesh_text(m, a.displacement());
  const std::string forward = replace(imaged_deck, "mesh: {type: octant, radius: 1 mm, n: 6}",
                                      "mesh: {type: gmsh, file: " + mesh + ", surface: balloon}");
  const Model f = read_deck_text(forward, dir + "/forward.yaml");
  ASSERT_EQ(f.num_nodes(), m.num_nodes());
  Capture cf;
  Analysis af(f);
  af.run(cf);
  const std::vector<Eigen::Vector3d> x = positions(f, af.displacement());
  double err = 0;
  for (int n = 0; n < m.num_nodes(); ++n) err = std::max(err, (x[n] - m.X[n]).norm());
  std::printf("octant n = 6: the reference mesh file inflated forward to 0.011 MPa lands within %.2e mm of the imaged "
              "nodes\n", err);
  EXPECT_LT(err, 1e-8);
}

TEST(InverseStep, RatAortaInverseExampleGivesTheLoadFreeTube) {
  // examples/rat-aorta-inverse.yaml: the tube imaged at 120 mmHg and λz = 1.6 (radius to 12 digits).
  const std::string file = std::string(TUNICA_SOURCE_DIR) + "/examples/rat-aorta-inverse.yaml";
  const Model m = read_deck_text(read_text(file), file);
  Capture cap;
  Analysis a(m);
  a.run(cap);
  // The end of its inverse step (the steps after it: InverseThenForward, test_inverse_forward.cpp).
  const Row& last = *std::find_if(cap.rows.begin(), cap.rows.end(),
                                  [](const Row& r) { return r.info.step == 1 && r.info.fraction >= 1.0 - 1e-12; });
  const double R = last.values[Capture::column(m, "radius_mm")];
  const double Z = last.values[Capture::column(m, "end_z_mm")];
  const double lz = last.values[Capture::column(m, "lambda_z")];
  std::printf("examples/rat-aorta-inverse.yaml: R = %.12f mm, reference length %.12f mm, λz = %.10f, %d cut-backs\n", R,
              Z, lz, cap.cutbacks);
  EXPECT_NEAR(R, 0.763, 1e-10);
  EXPECT_NEAR(Z, 1.0, 1e-10);
  EXPECT_NEAR(lz, 1.6, 1e-10);
  EXPECT_EQ(cap.cutbacks, 0);
}
