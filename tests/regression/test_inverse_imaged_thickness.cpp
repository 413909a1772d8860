// An inverse step with the wall thickness measured in the imaged state (theory manual (13.12)–
// (13.14); a part's `thickness_at: imaged`): each Gauss point's reference thickness is
// H = h λ₁λ₂, found with X, and the steps after the inverse step use it.
//  - Round trips: a forward inflation from (X, H) gives the imaged nodes and the imaged thickness
//    h = λ₃H at each Gauss point; the inverse step from them gives back X and H to 1e-8 relative
//    (axisymmetric sphere; 3-D octant of quadrilaterals, triangles and 6-node triangles).
//  - The paper's rat aorta imaged at 120 mmHg, its thickness given as the closed form's imaged
//    h = H/(λθ λz): the inverse step gives back R = 0.763 mm and H = 0.122 mm, and the steps after
//    it follow those of examples/rat-aorta-inverse.yaml (reference thickness given).
//  - An inverse step, then a forward step: the state of the forward run from the true reference.
//  - `thickness_at: imaged` in a deck without an inverse step is refused, naming the key.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "../support/capture.hpp"
#include "../support/scratch.hpp"
#include "../support/sphere_octant.hpp"
#include "core/errors.hpp"
#include "output/vtk_writer.hpp"

using namespace tunica;
using namespace tunica::test;

namespace {

const std::string kAxisym = std::string(TUNICA_SOURCE_DIR) + "/examples/balloon-sphere.yaml";
const std::string k3d = std::string(TUNICA_SOURCE_DIR) + "/examples/balloon-sphere-3d.yaml";
const std::string kRatInverse = std::string(TUNICA_SOURCE_DIR) + "/examples/rat-aorta-inverse.yaml";
const char* kTight = "\nsolver: {residual_tolerance: 1e-12}\n";

std::string axisym_deck(int elements, double p, int increments) {
  std::string t = replace(read_text(kAxisym), "elements: 100", "elements: " + std::to_string(elements));
  t = replace(t, "increments: 20", "increments: " + std::to_string(increments));
  return replace(t, "set: {inflation: 0.0118 MPa}", fmt::format("set: {{inflation: {} MPa}}", p)) + kTight;
}

std::string octant_deck(int n, const std::string& shape) {
  std::string t = replace(read_text(k3d), "n: 8}", "n: " + std::to_string(n) + shape + "}");
  t = replace(t, "increments: 40\n    volume_control: {load: inflation, volume: 4.45 mm^3}   # 8.5 × π/6 mm³",
              "increments: 10\n    set: {inflation: 0.011 MPa}");
  return t + kTight;
}

std::vector<Eigen::Vector3d> positions(const Model& m, const Eigen::VectorXd& u) {
  std::vector<Eigen::Vector3d> x = m.X;
  const int d = m.dofs_per_node();
  for (int n = 0; n < m.num_nodes(); ++n)
    for (int c = 0; c < d; ++c) x[n](c) += u(d * n + c);
  return x;
}

double relative_distance(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b) {
  double err = 0, scale = 0;
  for (std::size_t n = 0; n < a.size(); ++n) {
    err = std::max(err, (a[n] - b[n]).norm());
    scale = std::max(scale, b[n].norm());
  }
  return err / scale;
}

/// A forward run of `deck`: the positions reached and the thickness λ₃H of each Gauss point of part 0.
struct Forward {
  Model model;
  std::vector<Eigen::Vector3d> x;
  std::vector<double> h;
};
Forward forward(const std::string& deck, const std::string& file) {
  Forward f{read_deck_text(deck, file), {}, {}};
  Capture cap;
  Analysis a(f.model);
  a.run(cap);
  f.x = positions(f.model, a.displacement());
  for (const MembranePoint& p : a.system().points(a.displacement(), 0, a.loads().step)) f.h.push_back(p.thickness);
  return f;
}

struct ImagedInverse {
  double position_error = 0;   ///< max |X_found − X| / max |X|
  double thickness_error = 0;  ///< max |H_q/H − 1| over the Gauss points
  int max_iterations = 0, cutbacks = 0;
};

/// The inverse step of `deck` (its only step made an inverse one) on the imaged state of `f`, the
/// thickness of part 0 given per Gauss point as f's λ₃H (or, if `uniform` > 0, as that value).
ImagedInverse imaged_round_trip(const Forward& f, const std::string& deck, const std::string& file, double H,
                                double uniform = 0) {
  Model m = read_deck_text(replace(deck, "name: inflate", "name: zero_pressure\n    type: inverse"), file);
  m.X = f.x;
  m.parts[0].imaged_thickness = true;
  if (uniform > 0) m.parts[0].thickness = uniform;
  else m.parts[0].imaged_point_thickness = f.h;
  Capture cap;
  Analysis a(m);
  a.run(cap);
  ImagedInverse r;
  r.position_error = relative_distance(positions(m, a.displacement()), f.model.X);
  for (const MembranePoint& p : a.system().points(a.displacement(), 0, 0))
    r.thickness_error = std::max(r.thickness_error, std::abs(p.reference_thickness / H - 1));
  r.cutbacks = cap.cutbacks;
  for (const auto& it : cap.iterations) r.max_iterations = std::max(r.max_iterations, it.rec.iteration);
  return r;
}

}  // namespace

TEST(InverseImagedThickness, AxisymmetricSphereRecoversTheReferenceAndItsThickness) {
  // Forward from R = 1 mm, H = 0.01 mm to 0.0118 MPa; imaged: the nodes reached and h = λ₃H of each
  // Gauss point (13.12). The inverse gives back R and H.
  for (int elements : {10, 40, 80, 160}) {
    const std::string deck = axisym_deck(elements, 0.0118, 10);
    const Forward f = forward(deck, kAxisym);
    const auto [lo, hi] = std::minmax_element(f.h.begin(), f.h.end());
    const ImagedInverse r = imaged_round_trip(f, deck, kAxisym, 0.01);
    // The sphere's uniform h = H/λ² with λ = r/R at the equator: the discrete sphere's Gauss points
    // differ from it by the discretization's O(h²), and so does the reference found from it.
    const double lambda = f.x.front().x() / f.model.X.front().x();
    const ImagedInverse u = imaged_round_trip(f, deck, kAxisym, 0.01, 0.01 / (lambda * lambda));
    std::printf("axisymmetric sphere, %d elements, 0.0118 MPa, imaged thickness %.8f–%.8f mm: X within %.2e, H within "
                "%.2e (iterations ≤ %d); uniform h = H/λ² = %.8f mm: X within %.2e, H within %.2e\n",
                elements, *lo, *hi, r.position_error, r.thickness_error, r.max_iterations, 0.01 / (lambda * lambda),
                u.position_error, u.thickness_error);
    // The residual tolerance (1e-12 relative) of both runs bounds the round trip; at 160 elements
    // the conditioning of the meridian's tangent makes that a few 1e-8 in X.
    const double tolerance = elements < 160 ? 1e-8 : 5e-8;
    EXPECT_LT(r.position_error, tolerance) << elements;
    EXPECT_LT(r.thickness_error, tolerance) << elements;
    EXPECT_EQ(r.cutbacks, 0);
  }
}

TEST(InverseImagedThickness, OctantRoundTripRecoversTheReferenceAndItsThickness) {
  for (const std::string shape : {"", ", shape: triangle"})
    for (int n : {4, 8}) {
      const std::string deck = octant_deck(n, shape);
      const Forward f = forward(deck, k3d);
      const ImagedInverse r = imaged_round_trip(f, deck, k3d, 0.01);
      std::printf("3-D octant%s, n = %d, 0.011 MPa, imaged thickness per Gauss point: X within %.2e, H within %.2e, "
                  "iterations ≤ %d\n",
                  shape.c_str(), n, r.position_error, r.thickness_error, r.max_iterations);
      EXPECT_LT(r.position_error, 1e-8) << "n = " << n << shape;
      EXPECT_LT(r.thickness_error, 1e-8) << "n = " << n << shape;
      EXPECT_EQ(r.cutbacks, 0);
    }
}

TEST(InverseImagedThickness, SixNodeTriangleOctantRoundTripRecoversTheReferenceAndItsThickness) {
  // The octahedron face's lattice on the unit sphere as 6-node triangles (as in test_inverse.cpp).
  for (int n : {2, 4}) {
    const std::filesystem::path msh = scratch("inverse-imaged-tri6") / fmt::format("octant-{}.msh", n);
    sphere_octant_lattice(n, 2, OctantLattice::octahedron, 1.0).write(msh.string());
    const std::string deck = fmt::format(R"(title: tri6 sphere octant
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
    const std::string file = (scratch("inverse-imaged-tri6") / "octant.yaml").string();
    const Forward f = forward(deck, file);
    const ImagedInverse r = imaged_round_trip(f, deck, file, 0.01);
    std::printf("3-D octant of 6-node triangles, n = %d, 0.0115 MPa, imaged thickness per Gauss point: X within %.2e, "
                "H within %.2e, iterations ≤ %d\n",
                n, r.position_error, r.thickness_error, r.max_iterations);
    EXPECT_LT(r.position_error, 1e-8) << "n = " << n;
    EXPECT_LT(r.thickness_error, 1e-8) << "n = " << n;
    EXPECT_EQ(r.cutbacks, 0);
  }
}

TEST(InverseImagedThickness, InverseThenForwardEqualsTheForwardRunFromTheReference) {
  // R0 = 1 mm, H = 0.01 mm forward to p1 = 0.0118 MPa gives x1 and h1 = λ₃H; the deck on x1 with the
  // thickness h1, an inverse step at p1 and a forward step to p2 = 0.008 MPa ends where the forward
  // run from R0 straight to p2 does (13.10), (13.14), and its Gauss points have H = 0.01 mm.
  const Forward f1 = forward(axisym_deck(40, 0.0118, 10), kAxisym);
  const Forward f2 = forward(axisym_deck(40, 0.008, 10), kAxisym);
  std::string deck = replace(axisym_deck(40, 0.0118, 10), "name: inflate", "name: zero_pressure\n    type: inverse");
  deck = replace(deck, "\noutput:", "\n  - name: deflate\n    increments: 5\n    set: {inflation: 0.008 MPa}\noutput:");
  Model m = read_deck_text(deck, kAxisym);
  m.X = f1.x;
  m.parts[0].imaged_thickness = true;
  m.parts[0].imaged_point_thickness = f1.h;
  Capture cap;
  Analysis a(m);
  a.run(cap);
  const double err = relative_distance(positions(a.model(), a.displacement()), f2.x);
  double H = 0;
  for (const MembranePoint& p : a.system().points(a.displacement(), 0, a.loads().step))
    H = std::max(H, std::abs(p.reference_thickness / 0.01 - 1));
  ASSERT_EQ(a.model().parts[0].point_thickness.size(), f1.h.size());
  std::printf("axisymmetric sphere, inverse at 0.0118 MPa from the imaged thickness, then forward to 0.008 MPa: within "
              "%.2e of the forward run from the reference; H within %.2e of 0.01 mm\n",
              err, H);
  EXPECT_LT(err, 1e-10);
  EXPECT_LT(H, 1e-8);
}

TEST(InverseImagedThickness, RatAortaFromItsImagedThicknessGivesThePapersTubeAndLoadsItAsTheExampleDoes) {
  // The paper's tube (R = 0.763 mm, H = 0.122 mm) imaged at 120 mmHg and λz = 1.6 has r = 1.18791190481
  // mm, so h = H/(λθ λz) with λθ = r/R (13.12). examples/rat-aorta-inverse.yaml with that h as
  // `thickness` and `thickness_at: imaged` gives back R and H, and its forward steps to 160 and
  // 80 mmHg follow the example's (reference thickness given) row by row.
  const double r = 1.18791190481, R = 0.763, H = 0.122, h = H / ((r / R) * 1.6);
  const std::string text = read_text(kRatInverse);
  std::string imaged = replace(text, "    thickness: 0.122 mm     # reference thickness H",
                               fmt::format("    thickness: {:.17g} mm\n    thickness_at: imaged", h));
  imaged = replace(imaged, "    - {quantity: thickness, part: wall, name: imaged_thickness, unit: mm}",
                   "    - {quantity: thickness, part: wall, name: imaged_thickness, unit: mm}\n"
                   "    - {quantity: reference_thickness, part: wall, name: H, unit: mm}");
  const Model given = read_deck_text(text, kRatInverse), m = read_deck_text(imaged, kRatInverse);
  ASSERT_TRUE(m.parts[0].imaged_thickness);
  Capture c0, c1;
  Analysis a0(given), a1(m);
  a0.run(c0);
  a1.run(c1);
  const Row& last = *std::find_if(c1.rows.begin(), c1.rows.end(),
                                  [](const Row& row) { return row.info.step == 1 && row.info.fraction >= 1.0 - 1e-12; });
  const double Rf = last.values[Capture::column(m, "radius_mm")], Hf = last.values[Capture::column(m, "H_mm")];
  const double hf = last.values[Capture::column(m, "imaged_thickness_mm")];
  ASSERT_EQ(c0.rows.size(), c1.rows.size());
  double worst = 0;
  const int columns = static_cast<int>(c0.rows.front().values.size());
  // The inverse step's intermediate increments differ (the imaged thickness is h at every pressure
  // of the ramp, so the references of the partial pressures differ); its end and the forward steps do not.
  int compared = 0;
  for (std::size_t i = 0; i < c0.rows.size(); ++i) {
    const IncrementInfo& at = c0.rows[i].info;
    if (at.step < 1 || (at.step == 1 && at.fraction < 1.0 - 1e-12)) continue;
    ++compared;
    for (int k = 0; k < columns; ++k)
      worst = std::max(worst, std::abs(c1.rows[i].values[k] - c0.rows[i].values[k]) /
                                  std::max(1.0, std::abs(c0.rows[i].values[k])));
  }
  EXPECT_EQ(compared, 13);  // the inverse step's end, 4 + 8 forward increments
  std::printf("rat aorta imaged at 120 mmHg, imaged thickness h = %.12f mm: R = %.12f mm, H = %.12f mm, imaged "
              "thickness output %.12f mm; the example's history from the inverse step's end on within %.2e (%d rows)\n",
              h, Rf, Hf, hf, worst, compared);
  EXPECT_NEAR(Rf / R, 1.0, 1e-8);
  EXPECT_NEAR(Hf / H, 1.0, 1e-8);
  EXPECT_NEAR(hf / h, 1.0, 1e-12);
  EXPECT_LT(worst, 1e-8);
  // After the inverse step the reference thickness is H at every Gauss point.
  for (double Hq : a1.model().parts[0].point_thickness) EXPECT_NEAR(Hq / H, 1.0, 1e-8);
  // The frames carry it as a cell field where a part has an imaged thickness, and only there.
  const std::string vtu = meridian_vtu(a1, VtkFormat::ascii);
  const std::size_t at = vtu.find("Name=\"reference_thickness_mm\"");
  ASSERT_NE(at, std::string::npos);
  EXPECT_NEAR(std::stod(vtu.substr(vtu.find('>', at) + 1)) / H, 1.0, 1e-8);
  EXPECT_EQ(meridian_vtu(a0, VtkFormat::ascii).find("reference_thickness"), std::string::npos);
  EXPECT_NE(surface_vtu(a1, 4, VtkFormat::ascii).find("reference_thickness_mm"), std::string::npos);
}

TEST(InverseImagedThickness, ImagedThicknessWithoutAnInverseStepIsRefused) {
  const std::string deck =
      replace(axisym_deck(10, 0.0118, 10), "thickness: 0.01 mm", "thickness: 0.007 mm\n    thickness_at: imaged");
  ASSERT_NE(deck.find("thickness_at: imaged"), std::string::npos);
  try {
    read_deck_text(deck, kAxisym);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("thickness_at"), std::string::npos) << what;
    EXPECT_NE(what.find("no inverse step"), std::string::npos) << what;
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

}  // namespace

TEST(InverseImagedThickness, ARestartPastTheInverseStepHasTheSameReferenceThicknessBitForBit) {
  // The reference thickness (13.14) is recomputed from the checkpoint's reference shift.
  const Forward f1 = forward(axisym_deck(40, 0.0118, 10), kAxisym);
  std::string deck = replace(axisym_deck(40, 0.0118, 10), "name: inflate", "name: zero_pressure\n    type: inverse");
  deck = replace(deck, "\noutput:", "\n  - name: deflate\n    increments: 6\n    set: {inflation: 0.008 MPa}\noutput:");
  Model m = read_deck_text(deck, kAxisym);
  m.X = f1.x;
  m.parts[0].imaged_thickness = true;
  m.parts[0].imaged_point_thickness = f1.h;
  KeepCheckpoint keep(2, 3);
  Analysis whole(m);
  whole.run(keep);
  ASSERT_EQ(keep.kept.reference_shift.size(), m.num_dofs());
  Capture cap;
  Analysis resumed(m);
  resumed.run(cap, &keep.kept);
  EXPECT_EQ(resumed.model().parts[0].point_thickness, whole.model().parts[0].point_thickness);
  EXPECT_EQ(resumed.displacement(), whole.displacement());
  EXPECT_FALSE(resumed.model().parts[0].point_thickness.empty());
}

TEST(InverseImagedThickness, APartOfTrianglesAndQuadrilateralsTakesItsReferenceThicknessPointByPoint) {
  // One surface of a triangle (1 Gauss point) and a quadrilateral (4), as a Gmsh surface with
  // partial recombination gives: H per Gauss point (13.14) in System::points order, block by block.
  const std::filesystem::path dir = scratch("imaged-thickness-mixed");
  std::ofstream(dir / "mixed.msh")
      << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n2\n1 10 \"edge\"\n2 1 \"wall\"\n$EndPhysicalNames\n"
         "$Nodes\n6\n1 0 0 0\n2 1 0 0\n3 1 1 0.2\n4 0 1 0\n5 2 0 0.1\n6 2 1 0\n$EndNodes\n$Elements\n3\n"
         "1 1 2 10 1 1 4\n2 2 2 1 1 1 2 3\n3 3 2 1 1 2 5 6 3\n$EndElements\n";
  const std::string deck = R"(title: mixed surface
units: {length: mm, force: N}
materials:
  rubber: {type: neo_hookean, mu: 1 MPa}
parts:
  wall:
    element: membrane
    material: rubber
    thickness: 0.1 mm
    mesh: {type: gmsh, file: mixed.msh, surface: wall}
boundary:
  fixed: {node_set: edge, dofs: [x, y, z]}
steps:
  - {name: s, increments: 1, set: {}}
)";
  Model m = read_deck_text(deck, (dir / "mixed.yaml").string());
  ASSERT_EQ(m.parts[0].blocks.size(), 2u);
  std::vector<double> H;
  for (int k = 0; k < 5; ++k) H.push_back(0.1 + 0.01 * k);
  m.parts[0].point_thickness = H;
  const System system(m);
  const auto points = system.points(Eigen::VectorXd::Zero(m.num_dofs()), 0);
  ASSERT_EQ(points.size(), 5u);
  for (std::size_t k = 0; k < points.size(); ++k) EXPECT_DOUBLE_EQ(points[k].reference_thickness, H[k]) << k;
}
