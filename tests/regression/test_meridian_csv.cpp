// A meridian read from a CSV file (`mesh: {type: points, file: ...}`, mesh/meridian_csv.hpp): the
// zero-pressure geometry an axisymmetric inverse step writes (`reference_<step>.csv`), read back by
// a forward deck, stretched and inflated as imaged, gives back the imaged tube; a file that is
// not such a CSV is an error naming the file and its line.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <filesystem>
#include <fstream>

#include "../support/capture.hpp"
#include "../support/cli.hpp"
#include "../support/deck_files.hpp"
#include "../support/scratch.hpp"

using namespace tunica::test;

namespace {

const std::string kScratch = "tunica-meridian-csv";

/// The rat aorta of examples/rat-aorta-inverse.yaml (Fung, H = 0.122 mm): `mesh` its meridian,
/// `steps` its steps.
std::string aorta(const std::string& mesh, const std::string& steps) {
  return fmt::format(R"(units: {{length: mm, force: N}}
materials:
  aorta: {{type: fung, c: 61.163 kPa, a1: 0.68238, a2: 0.60558, a4: 0.1067}}
parts:
  wall:
    element: axisymmetric_membrane
    material: aorta
    thickness: 0.122 mm
    mesh: {}
boundary:
  base:    {{node_set: wall.start, dofs: [z]}}
  stretch: {{node_set: wall.end, dofs: [z]}}
loads:
  lumen: {{type: pressure, part: wall}}
solver: {{residual_tolerance: 1e-12}}
steps:
{}
output:
  vtk: false
  history:
    - {{quantity: position_r, node_set: wall.start, name: r, unit: mm}}
)",
                     mesh, steps);
}

/// A deck for the bad-file checks: the meridian from `mesh`.
std::string sphere(const std::string& mesh, const std::string& step) {
  return aorta(mesh, "  - " + step);
}

double last_value(const std::string& history_csv) {
  const std::string text = read_text(history_csv);
  const std::string last = text.substr(text.rfind('\n', text.size() - 2) + 1);
  return std::stod(last.substr(last.rfind(',') + 1));
}

}  // namespace

TEST(MeridianCsv, TheZeroPressureGeometryReadBackInflatesToTheImagedSphere) {
  const std::string dir = scratch("meridian-csv", "round-trip").string();
  // Imaged at 120 mmHg and λz = 1.6: radius 1.18791190481 mm over 1.6 mm (theory manual §13.1).
  const std::string imaged = write_deck_file(
      kScratch, "imaged",
      aorta("{type: line, from: [1.18791190481 mm, 0 mm], to: [1.18791190481 mm, 1.6 mm], elements: 4}",
            "  - {name: zero, type: inverse, increments: 12, set: {lumen: 120 mmHg, stretch: -0.6 mm}}"));
  const Outcome inv = run_cli("run " + imaged + " -q -o " + dir + "/inverse");
  ASSERT_EQ(inv.exit_code, 0) << inv.output;
  const std::string csv = dir + "/inverse/reference_zero.csv";
  ASSERT_EQ(read_text(csv).rfind("node,R_mm,Z_mm\n", 0), 0u);
  ASSERT_NEAR(last_value(dir + "/inverse/history.csv"), 0.763, 1e-9);  // the reference radius
  const std::string forward = write_deck_file(
      kScratch, "forward",
      aorta("{type: points, file: " + csv + "}",
            "  - {name: prestretch, increments: 6, set: {stretch: 0.6 mm}}\n"
            "  - {name: inflation, increments: 12, set: {lumen: 120 mmHg}}"));
  const Outcome fwd = run_cli("run " + forward + " -q -o " + dir + "/forward");
  ASSERT_EQ(fwd.exit_code, 0) << fwd.output;
  EXPECT_NEAR(last_value(dir + "/forward/history.csv"), 1.18791190481, 1e-9) << "the imaged radius back";
}

TEST(MeridianCsv, AFileThatIsNotAMeridianCsvNamesItsLine) {
  const std::string dir = scratch("meridian-csv", "bad").string();
  const auto check = [&](const std::string& name, const std::string& text, const std::string& range, int line,
                         const std::string& what) {
    const std::string csv = dir + "/" + name + ".csv";
    std::ofstream(csv) << text;
    const std::string deck = write_deck_file(
        kScratch, name, sphere("{type: points, file: " + csv + range + "}", "{name: s, increments: 1, set: {lumen: 1 kPa}}"));
    const Outcome o = run_cli("check " + deck);
    EXPECT_EQ(o.exit_code, 2) << o.output;
    EXPECT_NE(o.output.find(fmt::format("{}:{}:1: {}", csv, line, what)), std::string::npos) << o.output;
    EXPECT_NE(o.output.find("(the meridian of " + deck), std::string::npos) << o.output;
  };
  check("header", "n,r,z\n1,0,0\n2,1,1\n", "", 1, "the header is 'n,r,z': a meridian CSV starts with node,R_<unit>,Z_<unit>");
  check("unit", "node,R_kPa,Z_kPa\n1,0,0\n2,1,1\n", "", 1, "the header's unit 'kPa' is not a length unit");
  check("fields", "node,R_mm,Z_mm\n1,0,-1\n2,1\n", "", 3, "expected 3 fields (node, R, Z), found 2");
  check("nan", "node,R_mm,Z_mm\n1,0,-1\n2,nan,0\n", "", 3, "field 2 ('nan') is not a finite number");
  check("order", "node,R_mm,Z_mm\n1,0,-1\n3,1,0\n", "", 3, "node 3 follows node 1");
  check("negative", "node,R_mm,Z_mm\n1,0,-1\n2,-1,0\n", "", 3, "R = -1 is negative");
  check("range", "node,R_mm,Z_mm\n1,0,-1\n2,1,0\n3,0,1\n", ", nodes: [2, 5]", 4,
        "the file ends at node 3, before node 5 of `nodes: [2, 5]`");
  check("empty", "", "", 1, "the file is empty");
}
