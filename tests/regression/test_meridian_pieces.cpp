// An axisymmetric meridian made of pieces (`mesh:` a list of `line` and `arc` maps joined end to
// start, io/deck_meridian_parts.hpp) is one membrane: the node where two pieces meet is shared.
// - A capsule (arc, line, arc) under pressure: far from the caps its cylinder is the closed-ended
//   thin tube of the closed form, σθ h = p r and σz h = p r / 2 (the axial force p π r² reaches
//   the cylinder through the joints), with the neo-Hookean membrane stresses
//   σα = μ (λα² − 1/(λθ λz)²), h = H/(λθ λz) (theory manual §2).
// - A sphere of two arcs equals the sphere of one arc, membrane and shell.
// - Pieces that do not meet, run the wrong way, or (shell) meet at a corner are errors at the
//   piece's key.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "../support/capture.hpp"
#include "../support/cli.hpp"
#include "../support/deck_files.hpp"

using namespace tunica;
using namespace tunica::test;

namespace {

const std::string kScratch = "tunica-meridian-pieces";

const std::string kCapsule = R"(units: {length: mm, force: N}
materials:
  rubber: {type: neo_hookean, mu: 1 MPa}
parts:
  capsule:
    element: axisymmetric_membrane
    material: rubber
    thickness: 0.05 mm
    mesh:
      - {type: arc, center: [0 mm, 0 mm], radius: 1 mm, start_angle: -90 deg, end_angle: 0 deg, elements: 10}
      - {type: line, from: [1 mm, 0 mm], to: [1 mm, 10 mm], elements: 40}
      - {type: arc, center: [0 mm, 10 mm], radius: 1 mm, start_angle: 0 deg, end_angle: 90 deg, elements: 10}
node_sets:
  mid: {part: capsule, nodes: [30]}
  below: {part: capsule, nodes: [29]}
  above: {part: capsule, nodes: [31]}
boundary:
  south: {node_set: capsule.start, dofs: [r, z]}
  north: {node_set: capsule.end, dofs: [r]}
loads:
  p: {type: pressure, part: capsule}
steps:
  - {name: inflate, increments: 5, set: {p: 0.03 MPa}}
output:
  vtk: false
  history:
    - {quantity: position_r, node_set: mid, name: r_mid}
    - {quantity: position_z, node_set: below, name: z_below}
    - {quantity: position_z, node_set: above, name: z_above}
)";

/// A sphere of radius 1 mm, pole to pole: one arc of 20 elements, or two of 10 (`element` given),
/// or (`points`) the nodes of the one arc written out.
std::string sphere(const std::string& element, bool two_arcs, bool points = false) {
  std::string written;
  for (int i = 0; i <= 20; ++i) {
    const double phi = -std::numbers::pi / 2 + std::numbers::pi * i / 20;
    const double r = i == 0 || i == 20 ? 0.0 : std::cos(phi);
    written += fmt::format("{}[{:.17g} mm, {:.17g} mm]", i ? ", " : "", r, std::sin(phi));
  }
  const std::string mesh =
      points   ? " {type: points, points: [" + written + "]}"
      : two_arcs ? "\n      - {type: arc, center: [0 mm, 0 mm], radius: 1 mm, start_angle: -90 deg, end_angle: 0 deg, "
                 "elements: 10}\n      - {type: arc, center: [0 mm, 0 mm], radius: 1 mm, start_angle: 0 deg, "
                 "end_angle: 90 deg, elements: 10}"
               : " {type: arc, center: [0 mm, 0 mm], radius: 1 mm, start_angle: -90 deg, end_angle: 90 deg, "
                 "elements: 20}";
  const std::string poles = element == "axisymmetric_shell" ? "dofs: [r, slope_z]" : "dofs: [r]";
  return fmt::format(R"(units: {{length: mm, force: N}}
materials:
  rubber: {{type: neo_hookean, mu: 1 MPa}}
parts:
  ball:
    element: {}
    material: rubber
    thickness: 0.05 mm
    mesh:{}
boundary:
  south: {{node_set: ball.start, dofs: [r, z]}}
  north: {{node_set: ball.end, {}}}
loads:
  p: {{type: pressure, part: ball}}
steps:
  - {{name: inflate, increments: 4, set: {{p: 0.04 MPa}}}}
output:
  vtk: false
)",
                     element, mesh, poles);
}

Eigen::VectorXd final_displacement(const std::string& deck) {
  const Model m = read_deck_text(deck, "sphere.yaml");
  Capture c;
  Analysis a(m);
  a.run(c);
  return a.displacement();
}

}  // namespace

TEST(MeridianPieces, ACapsuleCylinderIsTheClosedEndedTubeOfTheClosedForm) {
  const Model m = read_deck_text(kCapsule, "capsule.yaml");
  ASSERT_EQ(m.num_nodes(), 61);  // 10 + 40 + 10 elements, the two joints shared
  Capture c;
  Analysis a(m);
  a.run(c);
  const auto& last = c.rows.back().values;
  const double r = last[Capture::column(m, "r_mid_mm")];
  const double lz = (last[Capture::column(m, "z_above_mm")] - last[Capture::column(m, "z_below_mm")]) / 0.5;
  // The closed form: f(λθ, λz) = 0 by Newton from the FE values' neighbourhood.
  const double mu = 1, H = 0.05, R = 1, p = 0.03;
  double t = 1.2, z = 1.05;
  for (int it = 0; it < 50; ++it) {
    const auto f = [&](double a, double b) {
      const double J = 1 / (a * a * b * b), h = H / (a * b);
      return Eigen::Vector2d(mu * (a * a - J) * h - p * a * R, mu * (b * b - J) * h - p * a * R / 2);
    };
    const Eigen::Vector2d f0 = f(t, z);
    const double e = 1e-7;
    Eigen::Matrix2d K;
    K.col(0) = (f(t + e, z) - f(t - e, z)) / (2 * e);
    K.col(1) = (f(t, z + e) - f(t, z - e)) / (2 * e);
    const Eigen::Vector2d d = K.partialPivLu().solve(-f0);
    t += d(0);
    z += d(1);
    if (d.norm() < 1e-14) break;
  }
  ASSERT_NEAR(t, 1.25234, 1e-4);  // the closed form itself, for the record
  EXPECT_NEAR(r / R, t, 1e-4 * t) << "hoop stretch at mid-length";
  EXPECT_NEAR(lz, z, 1e-4 * z) << "axial stretch at mid-length";
}

TEST(MeridianPieces, ASphereOfTwoArcsIsTheSphereOfOneArc) {
  for (const std::string element : {"axisymmetric_membrane", "axisymmetric_shell"}) {
    const Eigen::VectorXd one = final_displacement(sphere(element, false));
    const Eigen::VectorXd two = final_displacement(sphere(element, true));
    ASSERT_EQ(one.size(), two.size()) << element;
    ASSERT_GT(one.cwiseAbs().maxCoeff(), 0.1) << element;
    EXPECT_LT((one - two).cwiseAbs().maxCoeff(), 1e-10 * one.cwiseAbs().maxCoeff()) << element;
  }
}

TEST(MeridianPieces, ASphereThroughWrittenPointsIsTheSphereOfTheArc) {
  const Eigen::VectorXd arc = final_displacement(sphere("axisymmetric_membrane", false));
  const Eigen::VectorXd points = final_displacement(sphere("axisymmetric_membrane", false, true));
  ASSERT_EQ(arc.size(), points.size());
  EXPECT_LT((arc - points).cwiseAbs().maxCoeff(), 1e-10 * arc.cwiseAbs().maxCoeff());
}

TEST(MeridianPieces, WrittenPointsOffTheHalfPlaneOrRepeatedAreRefusedAtThePoint) {
  std::string base = replace(kCapsule, "      - {type: line, from: [1 mm, 0 mm], to: [1 mm, 10 mm], elements: 40}",
                                   "      - {type: points, points: [[1 mm, 0 mm], [1.1 mm, 5 mm], [1 mm, 10 mm]]}");
  // 10 + 2 + 10 elements: nodes 0 … 22.
  base = replace(replace(replace(base, "nodes: [30]", "nodes: [11]"), "nodes: [29]", "nodes: [10]"), "nodes: [31]",
                 "nodes: [12]");
  const Outcome ok = run_cli("check " + write_deck_file(kScratch, "points", base));
  EXPECT_EQ(ok.exit_code, 0) << ok.output;
  expect_check_error(kScratch, "points-negative", replace(base, "[1.1 mm, 5 mm]", "[-1.1 mm, 5 mm]"), "[-1.1 mm, 5 mm]",
                     "parts.capsule.mesh[1].points[1][0]",
                     "r = -1.1 mm is negative: a meridian stays at r ≥ 0 (points are [r, z], the radius first)");
  expect_check_error(kScratch, "points-repeated", replace(base, "[1.1 mm, 5 mm]", "[1 mm, 0 mm]"),
                     "type: points", "parts.capsule.mesh[1].points[1]", "point 1 is point 0 again");
  expect_check_error(kScratch, "points-one", replace(base, "[[1 mm, 0 mm], [1.1 mm, 5 mm], [1 mm, 10 mm]]", "[[1 mm, 0 mm]]"),
                     "type: points", "parts.capsule.mesh[1].points", "expected a list of at least 2 points [r, z]");
}

TEST(MeridianPieces, ThePiecesCountAsOnePartInCheck) {
  const Outcome o = run_cli("check " + write_deck_file(kScratch, "capsule", kCapsule));
  EXPECT_EQ(o.exit_code, 0) << o.output;
  EXPECT_NE(o.output.find("61 node(s), 60 element(s)"), std::string::npos) << o.output;
  EXPECT_EQ(o.output.find("not joined"), std::string::npos) << o.output;
}

TEST(MeridianPieces, APieceThatDoesNotStartWhereTheLastEndedNamesTheGapAndTheStart) {
  expect_check_error(kScratch, "gap", replace(kCapsule, "from: [1 mm, 0 mm]", "from: [1.1 mm, 0 mm]"),
                     "from: [1.1 mm, 0 mm]", "parts.capsule.mesh[1].from",
                     "this piece starts at [1.1, 0] mm but the piece before it (mesh[0]) ends at [1, 0] mm, 0.1 mm "
                     "apart: the pieces of a meridian join end to start, in node order (start it at [1, 0] mm)");
}

TEST(MeridianPieces, APieceThatRunsTheOtherWayIsToldToSwapItsEnds) {
  expect_check_error(kScratch, "reversed",
                     replace(kCapsule, "from: [1 mm, 0 mm], to: [1 mm, 10 mm]", "from: [1 mm, 10 mm], to: [1 mm, 0 mm]"),
                     "from: [1 mm, 10 mm]", "parts.capsule.mesh[1].from",
                     "this piece ends there, so it runs the other way: swap `from` and `to`");
}

TEST(MeridianPieces, AFirstPieceOrAListThatRunsTheOtherWayIsNamed) {
  // mesh[0] written from the equator down to the pole: the line starts where mesh[0] starts.
  expect_check_error(kScratch, "first-reversed",
                     replace(kCapsule, "start_angle: -90 deg, end_angle: 0 deg", "start_angle: 0 deg, end_angle: -90 deg"),
                     "from: [1 mm, 0 mm]", "parts.capsule.mesh[1].from",
                     "it starts where mesh[0] starts, so mesh[0] runs the other way: in mesh[0], swap `from` and `to`");
  // Every piece written backwards and listed in the meridian's order: the line ends where mesh[0]
  // starts; both ways out are named.
  const std::string backwards =
      replace(replace(replace(kCapsule, "start_angle: -90 deg, end_angle: 0 deg", "start_angle: 0 deg, end_angle: -90 deg"),
                      "from: [1 mm, 0 mm], to: [1 mm, 10 mm]", "from: [1 mm, 10 mm], to: [1 mm, 0 mm]"),
              "start_angle: 0 deg, end_angle: 90 deg", "start_angle: 90 deg, end_angle: 0 deg");
  expect_check_error(kScratch, "all-reversed", backwards, "from: [1 mm, 10 mm]", "parts.capsule.mesh[1].from",
                     "it ends where mesh[0] starts, so the list runs from the meridian's far end: list the pieces in "
                     "the meridian's order, this one before mesh[0] (and if each piece also runs the other way, keep "
                     "the list and in every piece swap `from` and `to`");
}

TEST(MeridianPieces, PiecesListedOutOfOrderNameThePieceThatStartsThere) {
  // arc, arc, line: the upper arc (mesh[1]) does not start where the lower one ends; the line does.
  const std::string line = "      - {type: line, from: [1 mm, 0 mm], to: [1 mm, 10 mm], elements: 40}\n";
  const std::string upper =
      "      - {type: arc, center: [0 mm, 10 mm], radius: 1 mm, start_angle: 0 deg, end_angle: 90 deg, elements: 10}\n";
  ASSERT_NE(kCapsule.find(line + upper), std::string::npos);
  expect_check_error(kScratch, "out-of-order", replace(kCapsule, line + upper, upper + line), "start_angle: 0 deg",
                     "parts.capsule.mesh[1].start_angle",
                     "; mesh[2] starts there: list the pieces in the meridian's order, mesh[2] before this one");
}

TEST(MeridianPieces, AnEmptyListOrAnItemThatIsNotAMapIsRefused) {
  const std::string pieces = kCapsule.substr(kCapsule.find("      - {type: arc"),
                                             kCapsule.find("node_sets:") - kCapsule.find("      - {type: arc"));
  expect_check_error(kScratch, "empty", replace(replace(kCapsule, pieces, ""), "    mesh:\n", "    mesh: []\n"),
                     "mesh: []", "parts.capsule.mesh", "an empty list: expected a map with `type: line`");
  expect_check_error(kScratch, "scalar-item", replace(kCapsule, "      - {type: line", "      - 3\n      - {type: line"),
                     "      - 3", "parts.capsule.mesh[1]", "expected a map with `type: line`, `type: arc` or `type: points`");
}

TEST(MeridianPieces, AShellsPiecesThatMeetAtACornerAreRefused) {
  const std::string deck = R"(units: {length: mm, force: N}
materials:
  rubber: {type: neo_hookean, mu: 1 MPa}
parts:
  cone:
    element: axisymmetric_shell
    material: rubber
    thickness: 0.05 mm
    mesh:
      - {type: line, from: [1 mm, 0 mm], to: [1 mm, 2 mm], elements: 4}
      - {type: line, from: [1 mm, 2 mm], to: [0.5 mm, 3 mm], elements: 4}
boundary:
  a: {node_set: cone.start, dofs: [r, z]}
steps:
  - {name: s, increments: 1, set: {}}
)";
  expect_check_error(kScratch, "corner", deck, "      - {type: line, from: [1 mm, 2 mm]", "parts.cone.mesh[1]",
                     "the meridian turns by 26.6 deg at node 4, where mesh[0] and mesh[1] join");
  // The same corner is a membrane's to carry.
  const Outcome o = run_cli("check " + write_deck_file(kScratch, "corner-membrane",
                                                       replace(deck, "axisymmetric_shell", "axisymmetric_membrane")));
  EXPECT_EQ(o.exit_code, 0) << o.output;
}

TEST(MeridianPieces, AMeridianThatCrossesFoldsBackOrClosesIsRefusedAtThePiece) {
  // The line runs back down over itself.
  expect_check_error(kScratch, "folded",
                     replace(kCapsule, "      - {type: arc, center: [0 mm, 10 mm], radius: 1 mm, start_angle: 0 deg, "
                                       "end_angle: 90 deg, elements: 10}",
                             "      - {type: line, from: [1 mm, 10 mm], to: [1 mm, 5 mm], elements: 10}"),
                     "to: [1 mm, 5 mm]", "parts.capsule.mesh[2]",
                     "the meridian turns back on itself at node 50, [1, 10] mm: element 50 runs back along element 49");
  // The upper cap swung below the equator crosses the cylinder.
  expect_check_error(kScratch, "crossing",
                     replace(kCapsule, "      - {type: arc, center: [0 mm, 10 mm], radius: 1 mm, start_angle: 0 deg, "
                                       "end_angle: 90 deg, elements: 10}",
                             "      - {type: line, from: [1 mm, 10 mm], to: [2 mm, 11 mm], elements: 2}\n"
                             "      - {type: line, from: [2 mm, 11 mm], to: [0.5 mm, 5 mm], elements: 4}"),
                     "to: [0.5 mm, 5 mm]", "parts.capsule.mesh[3]", "the meridian crosses itself at [1, ");
  // A full circle closes on its first node, not joined there.
  const std::string ring = replace(kCapsule, kCapsule.substr(kCapsule.find("    mesh:\n"), kCapsule.find("node_sets:") - kCapsule.find("    mesh:\n")),
                                   "    mesh: {type: arc, center: [2 mm, 0 mm], radius: 1 mm, start_angle: -180 deg, end_angle: 180 deg, elements: 60}\n");
  expect_check_error(kScratch, "ring", ring, "start_angle: -180 deg", "parts.capsule.mesh",
                     "the meridian's last node lies on its first, at [1, 0] mm, where the ring is not joined");
}
