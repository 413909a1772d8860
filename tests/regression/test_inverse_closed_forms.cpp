// The inverse step against closed forms in 3-D and axisymmetric (issue #19; theory manual §13):
//  - a neo-Hookean sphere octant imaged from a forward run: the inverse's reference radius against
//    (13.9) at the imaged radius, the faceting error falling at order 2;
//  - the paper's rat aorta (Fung) as a 3-D quarter tube imaged at 120 mmHg and λ_z = 1.6 gives back
//    the reference tube R = 0.763 mm over 1 mm, the error of its facets falling at order 2;
//  - an HGO artery imaged as a thin tube under pressure (13.11), ends held axially, so λ_z = 1 and
//    the tube's hoop equilibrium
// p r = σ_θ h gives p = S_θ(λ_θ) H λ_θ / r (r = λ_θ R, h = H/λ_θ, σ_θ = λ_θ² S_θ), one equation for
// the reference radius R = r/λ_θ of the imaged radius r. The axisymmetric straight meridian carries
// the thin-tube state exactly (no discretization error); the 3-D quarter tube's facets err by
// O(h²), and the order is measured.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "../support/capture.hpp"

using namespace tunica;
using namespace tunica::test;

namespace {

// The media of the campaign's HGO decks: μ, k1 in MPa; β in radians.
constexpr double kMu = 0.03, kK1 = 0.2, kK2 = 8, kBeta = 40 * std::numbers::pi / 180, kKappa = 0.1;
constexpr double kH = 0.2, kR = 1.5, kP = 0.016;  // mm, mm (imaged radius), MPa
const char* kMedia = "{type: hgo, mu: 30 kPa, k1: 200 kPa, k2: 8, beta: 40 deg, kappa: 0.1}";

/// S_θ = (1/λ_θ) dŴ/dλ_θ at λ_z = 1 (theory manual (3.5); two families alike, C₁₂ = 0).
double hoop_pk2(double l) {
  const double I1 = l * l + 1 + 1 / (l * l), dI1 = 2 * l - 2 / (l * l * l);
  const double c2 = std::cos(kBeta) * std::cos(kBeta), s2 = std::sin(kBeta) * std::sin(kBeta);
  const double I4 = l * l * c2 + s2, dI4 = 2 * l * c2;
  const double e = kKappa * I1 + (1 - 3 * kKappa) * I4 - 1, de = kKappa * dI1 + (1 - 3 * kKappa) * dI4;
  double dW = 0.5 * kMu * dI1;
  if (e > 0) dW += 2 * kK1 * e * std::exp(kK2 * e * e) * de;
  return dW / l;
}

/// The reference radius of a tube imaged at radius r under p, λ_z = 1: p = S_θ(λ) H λ / r.
double reference_radius(double r, double p) {
  double lo = 1, hi = 3;
  for (int k = 0; k < 200; ++k) {
    const double mid = 0.5 * (lo + hi);
    (hoop_pk2(mid) * kH * mid / r < p ? lo : hi) = mid;
  }
  return r / (0.5 * (lo + hi));
}

/// The zero-pressure reference's largest radius and Newton's largest iteration count.
struct Found {
  double R_min = 1e300, R_max = 0;
  int iterations = 0, cutbacks = 0;
};

Found run_inverse(const std::string& deck, bool axisymmetric) {
  const Model m = read_deck_text(deck + "solver: {residual_tolerance: 1e-12}\n", "hgo-tube.yaml");
  Capture cap;
  Analysis a(m);
  a.run(cap);
  Found f;
  const Eigen::VectorXd& u = a.displacement();
  const int d = m.dofs_per_node();
  for (int n = 0; n < m.num_nodes(); ++n) {
    Eigen::Vector3d X = m.X[n];
    for (int c = 0; c < d; ++c) X(c) += u(d * n + c);
    const double R = axisymmetric ? X(0) : std::hypot(X(0), X(1));
    f.R_min = std::min(f.R_min, R);
    f.R_max = std::max(f.R_max, R);
  }
  for (const auto& it : cap.iterations) f.iterations = std::max(f.iterations, it.rec.iteration);
  f.cutbacks = cap.cutbacks;
  return f;
}

}  // namespace

TEST(InverseHgoTube, AxisymmetricMeridianGivesTheClosedFormReferenceRadius) {
  const std::string deck = fmt::format(R"(title: HGO tube imaged at 16 kPa, axisymmetric
units: {{length: mm, force: N}}
materials:
  media: {}
parts:
  wall:
    element: axisymmetric_membrane
    material: media
    thickness: {} mm
    mesh: {{type: line, from: [{} mm, 0 mm], to: [{} mm, 2 mm], elements: 8}}
boundary:
  base: {{node_set: wall.start, dofs: [z]}}
  end: {{node_set: wall.end, dofs: [z]}}
loads:
  lumen: {{type: pressure, part: wall}}
steps:
  - {{name: zero_pressure, type: inverse, increments: 4, set: {{lumen: 16 kPa}}}}
output: {{vtk: false}}
)",
                                       kMedia, kH, kR, kR);
  const Found f = run_inverse(deck, true);
  const double R = reference_radius(kR, kP);
  std::printf("HGO tube imaged at r = %.2f mm under 16 kPa, axisymmetric: inverse R = %.12f…%.12f mm, closed form "
              "%.12f mm (lambda_theta = %.6f), iterations <= %d\n",
              kR, f.R_min, f.R_max, R, kR / R, f.iterations);
  EXPECT_NEAR(f.R_min, R, 1e-10 * R);
  EXPECT_NEAR(f.R_max, R, 1e-10 * R);
  EXPECT_GT(kR / R, 1.05);  // the fibres are recruited: a real stretch, not the small-strain range
  EXPECT_EQ(f.cutbacks, 0);
}

TEST(InverseHgoTube, QuarterTubeOfQuadrilateralsConvergesToTheClosedFormAtSecondOrder) {
  const double R = reference_radius(kR, kP);
  double previous = 0;
  for (int around : {4, 8, 16, 32}) {
    const std::string deck = fmt::format(R"(title: HGO quarter tube imaged at 16 kPa
units: {{length: mm, force: N}}
materials:
  media: {}
parts:
  wall:
    element: membrane
    material: media
    thickness: {} mm
    mesh: {{type: tube, radius: {} mm, length: 1 mm, sector: 90 deg, around: {}, along: 2, shape: quad}}
    frame: {{type: cylindrical, axis: [0, 0, 1]}}
boundary:
  sym_x: {{node_set: wall.x0, dofs: [x]}}
  sym_y: {{node_set: wall.y0, dofs: [y]}}
  base: {{node_set: wall.bottom, dofs: [z]}}
  end: {{node_set: wall.top, dofs: [z]}}
loads:
  lumen: {{type: pressure, part: wall}}
steps:
  - {{name: zero_pressure, type: inverse, increments: 4, set: {{lumen: 16 kPa}}}}
output: {{vtk: false}}
)",
                                         kMedia, kH, kR, around);
    const Found f = run_inverse(deck, false);
    // The facets' corners lie on the circle of radius R_h; the closed form is the smooth tube's.
    const double err = std::abs(f.R_max / R - 1);
    std::printf("HGO quarter tube, %d quads around, imaged at r = %.2f mm under 16 kPa: inverse R = %.10f mm "
                "(spread %.1e), closed form %.10f mm, relative error %.3e%s; iterations <= %d\n",
                around, kR, f.R_max, f.R_max - f.R_min, R, err,
                previous > 0 ? fmt::format(", order {:.2f}", std::log2(previous / err)).c_str() : "", f.iterations);
    EXPECT_LT(f.R_max - f.R_min, 1e-8 * R) << around;  // every node on one circle: the symmetric solution
    EXPECT_LT(err, 0.05) << around;
    if (previous > 0) {
      EXPECT_GT(std::log2(previous / err), 1.8) << around;
    }
    EXPECT_EQ(f.cutbacks, 0) << around;
    previous = err;
  }
}

TEST(InverseRatAorta3d, QuarterTubeImagedAt120mmHgGivesBackThePapersReferenceAtSecondOrder) {
  // Imaged: the closed form's tube at 120 mmHg, λ_z = 1.6 (theory manual §12.1, (8.1)–(8.2)): radius
  // 1.18791190481 mm over 1.6 mm; the prestretch undone by the top's prescribed −0.6 mm.
  double previous = 0;
  for (int around : {4, 8, 16, 32}) {
    const std::string deck = fmt::format(R"(title: rat aorta, 3-D quarter tube imaged at 120 mmHg
units: {{length: mm, force: N}}
materials:
  aorta: {{type: fung, c: 61.163 kPa, a1: 0.68238, a2: 0.60558, a4: 0.1067}}
parts:
  wall:
    element: membrane
    material: aorta
    thickness: 0.122 mm
    mesh: {{type: tube, radius: 1.18791190481 mm, length: 1.6 mm, sector: 90 deg, around: {}, along: 2, shape: quad}}
    frame: {{type: cylindrical, axis: [0, 0, 1]}}
boundary:
  sym_x: {{node_set: wall.x0, dofs: [x]}}
  sym_y: {{node_set: wall.y0, dofs: [y]}}
  base: {{node_set: wall.bottom, dofs: [z]}}
  stretch: {{node_set: wall.top, dofs: [z]}}
loads:
  lumen: {{type: pressure, part: wall}}
steps:
  - {{name: zero_pressure, type: inverse, increments: 12, set: {{lumen: 120 mmHg, stretch: -0.6 mm}}}}
output: {{vtk: false}}
)",
                                         around);
    const Found f = run_inverse(deck, false);
    const double err = std::abs(f.R_max / 0.763 - 1);
    std::printf("rat aorta, 3-D quarter tube of %d quads around, imaged at 120 mmHg: inverse R = %.10f mm (spread "
                "%.1e), paper 0.763 mm, relative error %.3e%s; iterations <= %d\n",
                around, f.R_max, f.R_max - f.R_min, err,
                previous > 0 ? fmt::format(", order {:.2f}", std::log2(previous / err)).c_str() : "", f.iterations);
    EXPECT_LT(f.R_max - f.R_min, 1e-7 * 0.763) << around;  // one circle: the round reference
    EXPECT_LT(err, 0.005) << around;
    if (previous > 0) {
      EXPECT_GT(std::log2(previous / err), 1.8) << around;
    }
    EXPECT_EQ(f.cutbacks, 0) << around;
    previous = err;
  }
}

TEST(InverseSphere3d, OctantImagedFromAForwardRunAgreesWithTheClosedFormAtSecondOrder) {
  // μ = 1 MPa, H = 0.01 mm, R = 1 mm, 0.0118 MPa; the imaged radius r_h is the pole's height, and
  // (13.9) gives the reference radius R(r_h) that a smooth sphere imaged there would have.
  const double p = 0.0118, mu = 1, H = 0.01;
  double previous = 0;
  for (int n : {4, 8, 16}) {
    const std::string forward = fmt::format(R"(title: neo-Hookean sphere octant
units: {{length: mm, force: N}}
materials:
  rubber: {{type: neo_hookean, mu: 1 MPa}}
parts:
  balloon:
    element: membrane
    material: rubber
    thickness: 0.01 mm
    mesh: {{type: octant, radius: 1 mm, n: {}}}
boundary:
  sym_x: {{node_set: balloon.x0, dofs: [x]}}
  sym_y: {{node_set: balloon.y0, dofs: [y]}}
  sym_z: {{node_set: balloon.z0, dofs: [z]}}
loads:
  inflation: {{type: pressure, part: balloon}}
solver: {{residual_tolerance: 1e-12}}
steps:
  - {{name: inflate, increments: 10, set: {{inflation: 0.0118 MPa}}}}
output: {{vtk: false}}
)",
                                            n);
    const Model f = read_deck_text(forward, "octant.yaml");
    Capture cf;
    Analysis af(f);
    af.run(cf);
    int pole = 0;
    for (int k = 0; k < f.num_nodes(); ++k)
      if (f.X[k](2) > f.X[pole](2)) pole = k;
    std::vector<Eigen::Vector3d> imaged = f.X;
    for (int k = 0; k < f.num_nodes(); ++k) imaged[k] += af.displacement().segment<3>(3 * k);
    std::string inverse = forward;
    inverse.replace(inverse.find("name: inflate"), 13, "name: zero_pressure, type: inverse");
    Model m = read_deck_text(inverse, "octant.yaml");
    m.X = imaged;
    Capture cap;
    Analysis a(m);
    a.run(cap);
    const double r = imaged[pole](2), Rh = (imaged[pole] + a.displacement().segment<3>(3 * pole))(2);
    const double R = r * std::pow(1 - p * r / (2 * mu * H), 1.0 / 6.0);  // (13.9): R = r/λ
    const double err = std::abs(Rh / R - 1);
    int iterations = 0;
    for (const auto& it : cap.iterations) iterations = std::max(iterations, it.rec.iteration);
    std::printf("3-D sphere octant, n = %d, imaged at the pole's r_h = %.8f mm under 0.0118 MPa: inverse R_h = "
                "%.10f mm, closed form R(r_h) = %.8f mm, relative error %.3e%s; inverse iterations <= %d\n",
                n, r, Rh, R, err, previous > 0 ? fmt::format(", order {:.2f}", std::log2(previous / err)).c_str() : "",
                iterations);
    EXPECT_NEAR(Rh, 1.0, 1e-9) << n;  // the forward run's reference
    EXPECT_LT(err, 0.02) << n;
    if (previous > 0) {
      EXPECT_GT(std::log2(previous / err), 1.7) << n;
    }
    previous = err;
  }
}
