// Bad input of inverse steps (theory manual §13, io/inverse_step_checks.hpp): what an inverse step
// cannot do is an error at the step's `type` (or the key concerned) naming the file, the line and
// the key, with exit 2.
#include <gtest/gtest.h>

#include "../support/capture.hpp"
#include "../support/cli.hpp"
#include "../support/deck_files.hpp"

using namespace tunica::test;

namespace {

const std::string kExample = std::string(TUNICA_SOURCE_DIR) + "/examples/rat-aorta-inverse.yaml";
const std::string kRat = std::string(TUNICA_SOURCE_DIR) + "/examples/rat-aorta-inflation.yaml";
const std::string kScratch = "tunica-bad-inverse";

}  // namespace

TEST(BadInverse, TheExampleIsValid) {
  // Its inverse step and the forward steps after it (theory manual (13.10)).
  const Outcome o = run_cli("check " + kExample);
  EXPECT_EQ(o.exit_code, 0) << o.output;
}

TEST(BadInverse, AnInverseStepAfterAnotherStep) {
  const std::string text = replace(read_text(kRat), "  - name: inflation\n", "  - name: inflation\n    type: inverse\n");
  expect_check_error(kScratch, "not-first", text, "    type: inverse", "steps[1].type",
                     "an inverse step must be the first step");
}

TEST(BadInverse, ASecondInverseStep) {
  const std::string text = replace(read_text(kExample), "\noutput:",
                                   "  - {name: again, type: inverse, increments: 2, set: {lumen: 130 mmHg}}\n\noutput:");
  expect_check_error(kScratch, "second", text, "  - {name: again", "steps[3].type",
                     "a deck takes one inverse step, and step 'zero_pressure' is one already");
}

TEST(BadInverse, CholmodForItsUnsymmetricTangent) {
  const std::string text = replace(read_text(kExample), "    type: inverse           # the deck's geometry is the imaged configuration",
                                   "    type: inverse\n    solver: {linear_solver: cholmod}");
  expect_check_error(kScratch, "cholmod", text, "    solver: {linear_solver: cholmod}", "steps[0].solver.linear_solver",
                     "the tangent of an inverse step is not symmetric");
}

TEST(BadInverse, VolumeControl) {
  const std::string text = replace(read_text(kExample), "    set: {lumen: 120 mmHg, stretch: -0.6 mm}",
                                   "    set: {stretch: -0.6 mm}\n    volume_control: {load: lumen, volume: 4 mm^3}");
  expect_check_error(kScratch, "volume", text, "    volume_control: {load: lumen, volume: 4 mm^3}",
                     "steps[0].volume_control", "an inverse step takes its loads at their imaged values in `set`");
}

TEST(BadInverse, AShellPart) {
  const std::string text = replace(read_text(kExample), "element: axisymmetric_membrane", "element: axisymmetric_shell");
  expect_check_error(kScratch, "shell", text, "    type: inverse", "steps[0].type", "which have no inverse element");
}
