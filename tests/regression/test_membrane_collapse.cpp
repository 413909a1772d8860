// A membrane collapsed to a line or the axis (elements/collapse.hpp): a tube under a pressure from
// outside (`flip: true`) shrinks, its follower pressure vanishing with its radius, and r → 0 was a
// converged state at every pressure (a wall 10⁷ times its reference thickness, the run exiting 0).
// A state with an area stretch below 1e-3 is inadmissible: no converged state reaches it, and the
// run stops naming the collapse.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <stdexcept>
#include <string>

#include "../support/capture.hpp"
#include "io/deck.hpp"
#include "solver/analysis.hpp"

using namespace tunica;
using namespace tunica::test;

TEST(MembraneCollapse, ATubeUnderPressureFromOutsideStopsRatherThanConvergeOnTheAxis) {
  const Model model = read_deck_text(R"(units: {length: mm, force: N}
materials:
  artery: {type: fung, c: 30 kPa, a1: 1.2, a2: 0.9, a4: 0.2}
parts:
  wall:
    element: axisymmetric_membrane
    material: artery
    thickness: 0.2 mm
    mesh: {type: line, from: [1.5 mm, 0 mm], to: [1.5 mm, 5 mm], elements: 100}
boundary:
  base: {node_set: wall.start, dofs: [z]}
  stretch: {node_set: wall.end, dofs: [z]}
loads:
  lumen: {type: pressure, part: wall, flip: true}
steps:
  - {name: prestretch, increments: 2, set: {stretch: 2.5 mm}}
  - {name: squeeze, increments: 4, set: {lumen: 150 mmHg}}
output:
  vtk: false
  history:
    - {quantity: lambda_1, part: wall, name: lambda_theta_min, reduce: min}
    - {quantity: thickness, part: wall, name: h_max, unit: mm, reduce: max}
)",
                                     "squeeze.yaml");
  Analysis a(model);
  Capture capture;
  std::string stop;
  try {
    a.run(capture);
  } catch (const std::exception& e) {
    stop = e.what();
  }
  ASSERT_FALSE(capture.rows.empty());
  const int lam = Capture::column(model, "lambda_theta_min"), h = Capture::column(model, "h_max_mm");
  for (const Row& r : capture.rows) {
    EXPECT_GT(r.values[lam], 1e-3) << "step " << r.info.step << " increment " << r.info.increment;
    EXPECT_LT(r.values[h], 1000 * 0.2) << "mm, step " << r.info.step << " increment " << r.info.increment;
  }
  EXPECT_FALSE(capture.rows.back().info.step == 2 && capture.rows.back().info.fraction == 1.0)
      << "the squeeze to 150 mmHg completed: a membrane carries no such pressure from outside";
  EXPECT_NE(stop.find("collapsed"), std::string::npos) << stop;
}
