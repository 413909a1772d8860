// A run that stops without a hint of its own, in a deck that drew warnings before the run
// (app/main.cpp): the stop points back to them. The quarter tube's symmetry sets are swapped
// (x held on the plane y = 0, y on x = 0), which `check` warns about twice.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "../support/cli.hpp"
#include "../support/scratch.hpp"

using namespace tunica::test;

TEST(StopAfterWarnings, AStopWithoutItsOwnHintPointsToTheWarnings) {
  const std::string deck = (scratch("stopwarn") / "swapped.yaml").string();
  std::ofstream(deck) << R"(title: quarter tube with its symmetry sets swapped
units: {length: mm, force: N}
materials:
  media: {type: hgo, mu: 30 kPa, k1: 200 kPa, k2: 10, beta: 35 deg, kappa: 0.1}
parts:
  wall:
    element: membrane
    material: media
    thickness: 0.7 mm
    mesh: {type: tube, radius: 3.5 mm, length: 10 mm, sector: 90 deg, around: 8, along: 8}
    frame: {type: cylindrical, axis: [0, 0, 1]}
boundary:
  sx: {node_set: wall.x0, dofs: [y]}
  sy: {node_set: wall.y0, dofs: [x]}
  base: {node_set: wall.bottom, dofs: [z]}
  stretch: {node_set: wall.top, dofs: [z]}
loads:
  blood: {type: pressure, part: wall}
steps:
  - {name: prestretch, increments: 4, set: {stretch: 1 mm}}
  - {name: inflate, increments: 12, set: {blood: 120 mmHg}}
output:
  vtk: false
)";
  const Outcome o = run_cli("run " + deck + " -q -o " + (scratch("stopwarn") / "out").string());
  EXPECT_EQ(o.exit_code, 3) << o.output;
  EXPECT_NE(o.output.find("tunica: warning:"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("Hint: the deck drew 2 warning(s) before the run (above)"), std::string::npos) << o.output;
}
