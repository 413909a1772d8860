// Warnings for pressure loads that read as valid but are likely not meant
// (assembly/pressure_load_checks.hpp): a surface whose normals point into the volume it encloses,
// and an open surface whose reported volume misses the caps that would close it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "../support/capture.hpp"
#include "../support/cli.hpp"
#include "../support/deck_files.hpp"
#include "../support/sphere_octant.hpp"
#include "assembly/pressure_load_checks.hpp"
#include "assembly/volume_control_checks.hpp"
#include "solver/failure_hints.hpp"

using namespace tunica;
using namespace tunica::test;

namespace {

/// The 3-D rat aorta (a quarter tube, R 0.763 mm, length 1 mm) with its lumen volume in history.
std::string quarter_tube(const std::string& load) {
  std::string d = read_text(std::string(TUNICA_SOURCE_DIR) + "/examples/rat-aorta-3d.yaml");
  d = replace(d, "    - {quantity: pressure, load: lumen, unit: mmHg}\n",
              "    - {quantity: pressure, load: lumen, unit: mmHg}\n    - {quantity: volume, load: lumen, unit: mm^3}\n");
  return replace(d, "lumen: {type: pressure, part: wall}", load);
}

std::vector<std::string> warnings_of(const std::string& deck) {
  const Model m = read_deck_text(deck, "warn.yaml");
  return pressure_load_warnings(System(m));
}

constexpr double kPi = 3.14159265358979323846;

}  // namespace

TEST(PressureLoadChecks, AnOpenTubeMeasuredAboutAPointMissesItsEndCap) {
  const Model m = read_deck_text(quarter_tube("lumen: {type: pressure, part: wall}"), "open.yaml");
  int open = 0;
  // The quarter tube's end z = 1 mm is not closed by a plane through the origin; its cap, the
  // quarter disc, is a cone of volume ⅓ · 1 mm · π R²/4 about p₀ (the chords' disc, 8 elements).
  const double chord_area = 0.5 * 0.763 * 0.763 * std::sin(kPi / 16) * 8;
  EXPECT_NEAR(std::abs(missing_cap_volume(m, 0, Eigen::Vector3d::Zero(), &open)), chord_area / 3, 1e-12);
  EXPECT_EQ(open, 8);
  const auto w = pressure_load_warnings(System(m));
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("load 'lumen'"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("8 open edge(s)"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("`volume_axis`"), std::string::npos) << w[0];
}

TEST(PressureLoadChecks, SymmetryPlanesAndAVolumeAxisCloseTheSurface) {
  EXPECT_TRUE(warnings_of(quarter_tube("lumen: {type: pressure, part: wall, volume_axis: [0, 0, 1]}")).empty());
  // The sphere octant: its three open arcs lie in the symmetry planes through p₀.
  const Model octant = read_deck_text(sphere_octant_deck("octant", 8, "", 1), "octant.yaml");
  int open = -1;
  EXPECT_EQ(missing_cap_volume(octant, 0, Eigen::Vector3d::Zero(), &open), 0.0);
  EXPECT_EQ(open, 0);
  // Without a volume reported or controlled the open tube is not worth a warning.
  EXPECT_TRUE(warnings_of(read_text(std::string(TUNICA_SOURCE_DIR) + "/examples/rat-aorta-3d.yaml")).empty());
}

TEST(PressureLoadChecks, AnInwardPressureNamesTheFixForItsFlip) {
  // The generated quarter tube's normals point outward: with `flip: true` the pressure pushes
  // inward, and the fix is to remove the flip, not to set it.
  auto w = warnings_of(quarter_tube("lumen: {type: pressure, part: wall, flip: true, volume_axis: [0, 0, 1]}"));
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("pushes its surface (part 'wall') inward"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("because the load has `flip: true`. A pressure inside a vessel or balloon pushes outward: "
                      "remove `flip: true` from the load (or set `flip: false`)"),
            std::string::npos)
      << w[0];
  EXPECT_EQ(w[0].find("set `flip: true`"), std::string::npos) << w[0];
  EXPECT_TRUE(warnings_of(quarter_tube("lumen: {type: pressure, part: wall, volume_axis: [0, 0, 1]}")).empty());
  // Normals that point inward (the quarter tube with its elements' node order reversed): set the flip.
  Model m = read_deck_text(quarter_tube("lumen: {type: pressure, part: wall, volume_axis: [0, 0, 1]}"), "in.yaml");
  for (ElementBlock& b : m.parts[0].blocks)
    for (int e = 0; e < b.size(); ++e) std::reverse(b.nodes.begin() + 4 * e, b.nodes.begin() + 4 * e + 4);
  w = pressure_load_warnings(System(m));
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("so the normals point into the volume the surface encloses. A pressure inside a vessel or "
                      "balloon pushes outward: set `flip: true` on the load (or reverse the elements' node order in "
                      "the mesh)"),
            std::string::npos)
      << w[0];
  // An axisymmetric tube meshed downwards: the meridian is run the other way.
  std::string down = read_text(std::string(TUNICA_SOURCE_DIR) + "/examples/rat-aorta-inflation.yaml");
  down = replace(down, "from: [0.763 mm, 0 mm], to: [0.763 mm, 1 mm]", "from: [0.763 mm, 1 mm], to: [0.763 mm, 0 mm]");
  w = warnings_of(down);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("set `flip: true` on the load (or run the meridian the other way: swap the mesh's `from` and "
                      "`to`, or `start_angle` and `end_angle`)"),
            std::string::npos)
      << w[0];
}

TEST(PressureLoadChecks, TunicaCheckPrintsTheWarningAndStillAcceptsTheDeck) {
  const std::string deck = write_deck_file("tunica-load-checks", "inward",
      quarter_tube("lumen: {type: pressure, part: wall, flip: true, volume_axis: [0, 0, 1]}"));
  const Outcome o = run_cli("check " + deck);
  EXPECT_EQ(o.exit_code, 0) << o.output;
  // At the load's line in the deck, with its key.
  EXPECT_NE(o.output.find("inward.yaml:" + std::to_string(line_of(read_text(deck), "  lumen: {type: pressure")) +
                          ":10: key 'loads.lumen': load 'lumen' pushes its surface"),
            std::string::npos)
      << o.output;
}

TEST(PressureLoadChecks, AHoleInAWallIsAnUnheldChainOfOpenEdges) {
  // A 4 × 4 grid of quadrilaterals in the plane z = 0 whose outer edge is held; without its
  // element (1, 1) it has a hole, the one chain of open edges that nothing holds.
  const auto plate = [](bool hole) {
    Model m;
    m.geometry = Geometry::three_d;
    for (int j = 0; j <= 4; ++j)
      for (int i = 0; i <= 4; ++i) m.X.emplace_back(i, j, 0.0);
    Part p;
    p.name = "wall";
    ElementBlock b;
    b.kind = ElementKind::quad4;
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 4; ++i)
        if (!(hole && i == 1 && j == 1))
          for (int n : {5 * j + i, 5 * j + i + 1, 5 * (j + 1) + i + 1, 5 * (j + 1) + i}) b.nodes.push_back(n);
    p.blocks.push_back(b);
    m.parts.push_back(p);
    NodeSet edge{"wall.edge", {}, "this test"};
    for (int n = 0; n < 25; ++n)
      if (n % 5 == 0 || n % 5 == 4 || n < 5 || n >= 20) edge.nodes.push_back(n);
    m.node_sets.push_back(edge);
    Boundary held;
    held.name = "clamp";
    held.node_set = 0;
    held.dofs = {0, 1, 2};
    m.boundaries.push_back(held);
    return m;
  };
  EXPECT_TRUE(unheld_open_edges(plate(false), 0).empty());
  const auto holes = unheld_open_edges(plate(true), 0);
  ASSERT_EQ(holes.size(), 1u);
  EXPECT_EQ(holes[0].edges, 4);
  EXPECT_NEAR((holes[0].centre - Eigen::Vector3d(1.5, 1.5, 0)).norm(), 0.0, 1e-12);
  // Nothing held at all: the outer edge is a free edge too.
  Model free = plate(true);
  free.boundaries.clear();
  EXPECT_EQ(unheld_open_edges(free, 0).size(), 2u);
}

TEST(VolumeControlWarnings, ATargetBelowTheStressFreeVolumeIsWarnedAtItsKey) {
  // Issue #17 C3: the balloon octant (stress-free volume π/6 mm³) asked to deflate to 0.4 mm³.
  const std::string path = std::string(TUNICA_SOURCE_DIR) + "/examples/balloon-sphere-3d.yaml";
  const std::string text = read_text(path);
  const std::string below = replace(text, "volume: 4.45 mm^3}", "volume: 0.4 mm^3}");
  const std::vector<std::string> w = volume_control_warnings(System(read_deck_text(below, path)));
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("key 'steps[0].volume_control.volume'"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("to 0.4 mm³, below its stress-free volume, 0.521"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("compresses it"), std::string::npos) << w[0];
  EXPECT_TRUE(volume_control_warnings(System(read_deck_text(text, path))).empty());
}

TEST(CompressionHint, ACompressedMembraneNamesWhereHowStronglyAndTheWrinklingLimitation) {
  // Issue #17 B3: a failure with no other evidence whose last converged state is compressed. The
  // 3-D rat aorta's quarter tube shortened by 5 % under 1 kPa is compressed axially everywhere.
  const std::string path = std::string(TUNICA_SOURCE_DIR) + "/examples/rat-aorta-3d.yaml";
  const std::string deck = R"(units: {length: mm, force: N}
materials:
  rubber: {type: neo_hookean, mu: 1 MPa}
parts:
  wall:
    element: membrane
    material: rubber
    thickness: 0.05 mm
    mesh: {type: tube, radius: 1 mm, length: 2 mm, sector: 90 deg, around: 8, along: 4, shape: triangle}
boundary:
  sym_x: {node_set: wall.x0, dofs: [x]}
  sym_y: {node_set: wall.y0, dofs: [y]}
  base: {node_set: wall.bottom, dofs: [z]}
  stretch: {node_set: wall.top, dofs: [z]}
loads:
  lumen: {type: pressure, part: wall}
steps:
  - {name: load, increments: 4, set: {stretch: -0.1 mm, lumen: 1 kPa}}
output:
  vtk: false
)";
  const Model m = read_deck_text(deck, path);
  Analysis a(m);
  Capture c;
  a.run(c);
  StepTrace trace;
  trace.restart_at(a.loads());
  const std::string h = compression_hint(a.system(), a.displacement(), m.steps[0], 0, trace);
  EXPECT_NE(h.find("part 'wall' is in compression over "), std::string::npos) << h;
  EXPECT_NE(h.find("% of the largest tension"), std::string::npos) << h;
  EXPECT_NE(h.find("most at the point ("), std::string::npos) << h;
  EXPECT_NE(h.find("Tunica does not model wrinkling (user guide §5, compression)"), std::string::npos) << h;
  // In tension (stretched instead): no hint.
  const Model t = read_deck_text(replace(deck, "stretch: -0.1 mm", "stretch: 0.4 mm"), path);
  Analysis b(t);
  Capture d;
  b.run(d);
  EXPECT_EQ(compression_hint(b.system(), b.displacement(), t.steps[0], 0, trace), "");
}
