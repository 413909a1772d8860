// Malformed inflation–extension data: one test per class of error, each asserting
// the message and that it names the file, the line and (where there is one) the column.
// The last tests run the real `tunica fit` and expect exit code 2.
#include <gtest/gtest.h>
#include <unistd.h>
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "core/errors.hpp"
#include "fit/inflation_fit.hpp"
#include "../support/cli.hpp"

using namespace tunica;

using tunica::test::Outcome;
using tunica::test::run_cli;

namespace {

// Line 1: specimen, line 2: header, lines 3–7: data (λz = 1.6, 0 → 200 mmHg).
const std::string kSpecimen = "# specimen: {outer_diameter: 1.648 mm, thickness: 0.122 mm, ends: open}\n";
const std::string kHeader = "axial_stretch,pressure_mmHg,outer_diameter_mm,axial_force_N\n";
const std::string kRows =
    "1.6,0,1.40,0.07\n"
    "1.6,50,2.05,0.10\n"
    "1.6,100,2.35,0.13\n"
    "1.6,150,2.50,0.16\n"
    "1.6,200,2.60,0.20\n";

/// Replaces the first `from` in `text` (which must occur).
std::string replace(std::string text, const std::string& from, const std::string& to) {
  const auto pos = text.find(from);
  if (pos == std::string::npos) throw std::runtime_error("not found: " + from);
  return text.replace(pos, from.size(), to);
}

/// Reads `text` as data.csv and returns the InputError message ("" if none).
std::string read_error(const std::string& text, const InflationDataOptions& options = {}) {
  try {
    read_inflation_data_text(text, "data.csv", options);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

/// Expects a message starting with `where` ("data.csv:5:5: key 'x'") and containing `what`.
void expect_message(const std::string& message, const std::string& where, const std::string& what) {
  EXPECT_EQ(message.rfind(where, 0), 0u) << message;
  EXPECT_NE(message.find(what), std::string::npos) << message;
}

}  // namespace

TEST(FitBadData, WellFormedDataAreRead) {
  const InflationData d = read_inflation_data_text(kSpecimen + kHeader + kRows, "data.csv");
  ASSERT_EQ(d.points.size(), 5u);
  EXPECT_EQ(d.points[2].line, 5);
  EXPECT_NEAR(d.points[2].pressure, 100 * 133.322387415e-6, 1e-15);
  EXPECT_NEAR(d.specimen.geometry.R, 0.763, 1e-15);
}

TEST(FitBadData, MissingColumns) {
  expect_message(read_error(kSpecimen + replace(kHeader, "pressure_mmHg", "p_mmHg") + kRows), "data.csv:2: ",
                 "missing column: pressure (e.g. 'pressure_mmHg'); the header has: axial_stretch, p_mmHg,");
  expect_message(read_error(kSpecimen + replace(kHeader, "outer_diameter_mm", "diameter_mm") + kRows),
                 "data.csv:2: ", "missing column: outer diameter or mid-surface radius");
  expect_message(read_error(kSpecimen + replace(kHeader, "axial_force_N", "force_N") + kRows),
                 "data.csv:2: ", "missing column: axial force");
  expect_message(read_error(kSpecimen + replace(kHeader, "axial_stretch", "stretch") + kRows),
                 "data.csv:2: ", "missing column: axial stretch (or give the specimen's `axial_stretch` for all rows)");
}

TEST(FitBadData, ColumnWithoutOrWithWrongUnit) {
  expect_message(
      read_error(kSpecimen + replace(kHeader, "pressure_mmHg", "pressure") + kRows),
      "data.csv:2:15: key 'pressure': ", "the pressure column needs a unit in its header, e.g. 'pressure_mmHg'");
  expect_message(read_error(kSpecimen + replace(kHeader, "pressure_mmHg", "pressure_mmHgx") + kRows),
                 "data.csv:2:15: key 'pressure_mmHgx': ", "unknown unit 'mmHgx'");
  expect_message(read_error(kSpecimen + replace(kHeader, "axial_force_N", "axial_force_mm") + kRows),
                 "data.csv:2:47: key 'axial_force_mm': ", "unit 'mm' is not a force");
}

TEST(FitBadData, SameQuantityTwice) {
  expect_message(read_error(kSpecimen + replace(kHeader, "axial_force_N", "radius_mm") + kRows),
                 "data.csv:2:47: key 'radius_mm': ", "gives the same quantity as column 'outer_diameter_mm'");
}

TEST(FitBadData, MalformedCells) {
  expect_message(read_error(kSpecimen + kHeader + replace(kRows, "1.6,50,", "1.6,5O,")),
                 "data.csv:4:5: key 'pressure_mmHg': ", "'5O' is not a number");
  expect_message(read_error(kSpecimen + kHeader + replace(kRows, "1.6,50,2.05,", "1.6,50,,")),
                 "data.csv:4:8: key 'outer_diameter_mm': ", "empty cell");
  expect_message(read_error(kSpecimen + kHeader + replace(kRows, "1.6,100,2.35,0.13", "1.6,100,2.35")),
                 "data.csv:5: ", "3 fields, but the header (line 2) has 4 columns");
  expect_message(read_error(kSpecimen + kHeader + replace(kRows, "0.16", "inf")),
                 "data.csv:6:14: key 'axial_force_N': ", "'inf' is not a finite number");
}

TEST(FitBadData, NegativeStretches) {
  expect_message(read_error(kSpecimen + kHeader + replace(kRows, "1.6,150", "-1.6,150")),
                 "data.csv:6:1: key 'axial_stretch': ", "axial stretch -1.6 is not positive");
  expect_message(
      read_error(kSpecimen + replace(kHeader, "axial_stretch", "E_z") + replace(kRows, "1.6,150", "-0.6,150")),
      "data.csv:6:1: key 'E_z': ", "axial Green strain -0.6 gives no positive stretch (need E_z > −1/2)");
  expect_message(read_error(kSpecimen + kHeader + replace(kRows, "2.35", "-2.35")),
                 "data.csv:5:9: key 'outer_diameter_mm': ", "outer diameter -2.35 is not positive");
  expect_message(read_error(kSpecimen + kHeader + replace(kRows, "2.35", "0.2")),
                 "data.csv:5:9: key 'outer_diameter_mm': ",
                 "outer diameter 0.2 mm is too small for the wall at axial stretch 1.6");
}

TEST(FitBadData, NonMonotoneHoopStretch) {
  const std::string text = kSpecimen + kHeader + replace(kRows, "2.50", "2.30");
  expect_message(
      read_error(text), "data.csv:6:9: key 'outer_diameter_mm': ",
      "non-monotone hoop stretch at axial stretch 1.6: the outer diameter rises from line 3 to 4 (1.4 → 2.05 "
      "mm) but falls from line 5 to 6 (2.35 → 2.3 mm)");
  InflationDataOptions allow;
  allow.allow_non_monotone = true;
  EXPECT_EQ(read_error(text, allow), "");
  // A new axial-stretch level may start anywhere; noise in the pressure is no error.
  EXPECT_EQ(read_error(kSpecimen + kHeader + kRows + replace(kRows, "1.6", "1.7") + "1.7,190,2.7,0.22\n"), "");
}

TEST(FitBadData, TooFewPointsForTheParameters) {
  const std::string text =
      kSpecimen + kHeader + "1.6,0,1.40,0.07\n1.6,50,2.05,0.10\n1.6,100,2.35,0.13\n1.6,150,2.50,0.16\n";
  const InflationData d = read_inflation_data_text(text, "data.csv");
  try {
    fit_inflation_data(d, FitOptions{});
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    expect_message(
        e.what(), "data.csv:6: ",
        "too few points for model fung2d: 4 point(s) for 4 parameters (ln_c, L11, L21, L22); need at least 5");
  }
  FitOptions neo;
  neo.model = "neo_hookean";
  EXPECT_NO_THROW(fit_inflation_data(d, neo));
}

TEST(FitBadData, SpecimenMissingOrMalformed) {
  expect_message(read_error(kHeader + kRows), "data.csv:1: key 'specimen': ", "no specimen: add a line '# specimen:");
  expect_message(read_error(replace(kSpecimen, "outer_diameter", "diameter") + kHeader + kRows),
                 "data.csv:1:14: key 'specimen.diameter': ", "unknown key 'diameter'");
  expect_message(
      read_error(replace(kSpecimen, "thickness: 0.122 mm", "radius: 0.7 mm, thickness: 0.122 mm") + kHeader + kRows),
      "data.csv:1:", "give exactly one of `outer_diameter`");
  expect_message(read_error(replace(kSpecimen, "0.122 mm", "0.122 kPa") + kHeader + kRows),
                 "data.csv:1:51: key 'specimen.thickness': ", "unit 'kPa' is not a length");
  expect_message(read_error(replace(kSpecimen, "ends: open", "ends: capped") + kHeader + kRows),
                 "data.csv:1:", "'capped' is not one of: open, closed");
  expect_message(read_error(replace(kSpecimen, "ends: open", "ends: open, axial_stretch: 1.6") + kHeader + kRows),
                 "data.csv:1:", "both give the axial stretch");
}

TEST(FitBadData, RowSelection) {
  InflationDataOptions o;
  o.select = {parse_row_selection("step=2")};
  expect_message(read_error(kSpecimen + kHeader + kRows, o),
                 "data.csv:2: key '--select step': ", "no column 'step' to select rows by");
  o.select = {parse_row_selection("axial_stretch=1.7")};
  expect_message(read_error(kSpecimen + kHeader + kRows, o), "data.csv:2: ", "no data rows match --select");
  EXPECT_THROW(parse_row_selection("step"), InputError);
}

namespace {


}  // namespace

TEST(FitBadData, CommandLineExitsWithTwoAndNamesTheFile) {
  const auto dir = std::filesystem::temp_directory_path() / ("tunica-fit-bad-data-" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "data.csv").string();
  std::ofstream(path) << kSpecimen + kHeader + replace(kRows, "1.6,150", "-1.6,150");
  const Outcome o = run_cli("fit " + path + " --model fung2d --no-plot -o " + (dir / "out").string());
  EXPECT_EQ(o.exit_code, 2) << o.output;
  EXPECT_NE(o.output.find("input error: " + path + ":6:1: key 'axial_stretch': axial stretch -1.6 is not positive"),
            std::string::npos)
      << o.output;
  const Outcome m = run_cli("fit " + path + " --model fung4d --no-plot -o " + (dir / "out").string());
  EXPECT_EQ(m.exit_code, 2) << m.output;
  EXPECT_NE(m.output.find("unknown model 'fung4d' (known: fung2d, fung3d, mooney_rivlin, neo_hookean)"),
            std::string::npos)
      << m.output;
}
