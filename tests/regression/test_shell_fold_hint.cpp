// A clamped shell tube inflated until its bending layer at the clamp is shorter than the wall is
// thick (solver/shell_fold_hint.hpp): the run stops with the hint that names the clamp and the
// hinge, not `max_iterations`; the hinged tube passes; a state without bending gets no hint.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <fstream>
#include <string>

#include "../support/cli.hpp"
#include "../support/scratch.hpp"
#include "assembly/system.hpp"
#include "io/deck.hpp"
#include "solver/shell_fold_hint.hpp"

using namespace tunica;
using namespace tunica::test;

namespace {

/// R = 2 mm, H = 0.3 mm, L = 8 mm, Fung, both ends held in `dofs`, 100 mmHg in 10 increments.
std::string clamped_tube(const std::string& dofs) {
  return fmt::format(R"(title: clamped shell tube
units: {{length: mm, force: N}}
materials:
  artery: {{type: fung, c: 30 kPa, a1: 1.0, a2: 0.8, a4: 0.1}}
parts:
  tube:
    element: axisymmetric_shell
    material: artery
    thickness: 0.3 mm
    mesh: {{type: line, from: [2 mm, 0 mm], to: [2 mm, 8 mm], elements: 40}}
node_sets:
  ends: {{part: tube, nodes: [0, 40]}}
boundary:
  clamp: {{node_set: ends, dofs: [{}]}}
loads:
  p: {{type: pressure, part: tube}}
steps:
  - {{name: inflate, increments: 10, set: {{p: 100 mmHg}}}}
output:
  vtk: false
)",
                     dofs);
}

std::string write(const std::string& name, const std::string& text) {
  const std::string path = (scratch("shellfold") / (name + ".yaml")).string();
  std::ofstream(path) << text;
  return path;
}

}  // namespace

TEST(ShellFoldHint, AClampedTubeBentThroughItsThicknessNamesTheClampAndTheHinge) {
  const std::string deck = write("clamped", clamped_tube("r, z, slope_r"));
  const Outcome o = run_cli("run " + deck + " -q -o " + (scratch("shellfold") / "clamped-out").string());
  EXPECT_EQ(o.exit_code, 3) << o.output;
  EXPECT_NE(o.output.find("part 'tube' is bent through its thickness near node"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("Boundary 'clamp' holds [r, z, slope_r] at node"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("Hold only r and z there (a hinged end"), std::string::npos) << o.output;
  EXPECT_EQ(o.output.find("raise `max_iterations`"), std::string::npos) << o.output;
  // The hinged tube, the fix the hint names, reaches 100 mmHg.
  const Outcome hinged = run_cli("run " + write("hinged", clamped_tube("r, z")) + " -q -o " +
                                 (scratch("shellfold") / "hinged-out").string());
  EXPECT_EQ(hinged.exit_code, 0) << hinged.output;
}

TEST(ShellFoldHint, AnUnbentShellGetsNoHintAndAFoldedAttemptOne) {
  const Model m = read_deck_text(clamped_tube("r, z, slope_r"), "tube.yaml");
  const System system(m);
  const Eigen::VectorXd u = Eigen::VectorXd::Zero(m.num_dofs());
  EXPECT_EQ(shell_fold_hint(system, u, 0, "no convergence in 12 iterations"), "");
  // A failed attempt that folded: the hint, though the converged state is unbent.
  const std::string h = shell_fold_hint(
      system, u, 0, "axisymmetric shell: no layer position (shell folded through its thickness), in element 0");
  EXPECT_NE(h.find("the failed attempt folded the shell through its thickness (the element named above); at the last "
                   "converged state part 'tube' was bent most near node"),
            std::string::npos)
      << h;
  EXPECT_NE(h.find("where the current thickness is 1 times"), std::string::npos) << h;
}
