// Bad input: every class of error in a deck gets a clear message naming the
// file, the line and the key, a non-zero exit (2) and no crash. Each test runs
// the real `tunica check` (or `tunica run`) on a broken copy of the example deck.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <fmt/format.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "../support/capture.hpp"
#include "../support/cli.hpp"
#include "../support/deck_files.hpp"

using namespace tunica::test;
namespace fs = std::filesystem;

namespace {

const std::string kExample = std::string(TUNICA_SOURCE_DIR) + "/examples/rat-aorta-inflation.yaml";

const std::string kScratch = "tunica-bad-input";

std::string write_deck(const std::string& name, const std::string& text) {
  return write_deck_file(kScratch, name, text);
}

/// Replaces `from` by `to` in the example, checks the deck and expects exit 2 and a
/// message "<file>:<line>:...key '<key>': ...<what>...".
void expect_error(const std::string& name, const std::string& from, const std::string& to, const std::string& key,
                  const std::string& what, const std::string& line_text = "") {
  const Outcome o = expect_check_error(kScratch, name, replace(read_text(kExample), from, to),
                                       line_text.empty() ? to : line_text, key, what);
  EXPECT_EQ(o.output.find("terminate called"), std::string::npos) << o.output;
}

}  // namespace

TEST(BadInput, TheExampleItselfIsValid) {
  const Outcome o = run_cli("check " + kExample);
  EXPECT_EQ(o.exit_code, 0) << o.output;
  EXPECT_NE(o.output.find("valid deck"), std::string::npos);
}

TEST(BadInput, TheCheckCountsSolidMaterialsToo) {
  // Two membrane materials and the plaque's solid one.
  const Outcome o = run_cli("check " + std::string(TUNICA_SOURCE_DIR) + "/examples/balloon-angioplasty.yaml");
  EXPECT_EQ(o.exit_code, 0) << o.output;
  EXPECT_NE(o.output.find("valid deck: 3 material(s)"), std::string::npos) << o.output;
}

TEST(BadInput, YamlSyntaxError) {
  // yaml-cpp reports where it noticed the unclosed list: the next line; the message adds where it
  // was opened.
  expect_error("syntax", "a2: 0.60558", "a2: [0.60558", "", "YAML syntax error", "    a4: 0.1067");
  const std::string text = replace(read_text(kExample), "a2: 0.60558", "a2: [0.60558");
  const Outcome o = expect_check_error(kScratch, "syntax-where", text, "    a4: 0.1067", "",
                                       "is not closed: add the `]` there");
  EXPECT_NE(o.output.find("the `[` opened on line " + std::to_string(line_of(text, "a2: [0.60558")) + ", column 9"),
            std::string::npos)
      << o.output;
}

TEST(BadInput, UnknownKey) {
  expect_error("unknown-key", "    a4: 0.1067", "    a4: 0.1067\n    a9: 1.0", "materials.aorta.a9",
               "unknown key 'a9' (allowed here: type, c, a1, a2, a3, a4, a5, a6, a7)", "a9: 1.0");
}

TEST(BadInput, UnknownTopLevelSection) {
  expect_error("unknown-section", "loads:", "load:", "load", "unknown key 'load'");
}

TEST(BadInput, MissingKey) {
  // The error points at the map that lacks the key.
  expect_error("missing-key", "    a1: 0.68238\n", "", "materials.aorta.a1", "missing required key 'a1'",
               "    type: fung");
}

TEST(BadInput, MissingSection) {
  const std::string text = read_text(kExample);
  const std::string cut = text.substr(0, text.find("steps:")) + text.substr(text.find("output:"));
  const Outcome o = run_cli("check " + write_deck("missing-steps", cut));
  EXPECT_EQ(o.exit_code, 2);
  EXPECT_NE(o.output.find("key 'steps': missing required key 'steps'"), std::string::npos) << o.output;
}

TEST(BadInput, AnAngleInAUnitOfAnotherDimensionSaysAnAngle) {
  const std::string hgo = "type: hgo, mu: 30 kPa, k1: 100 kPa, k2: 5, beta: 40 mm, kappa: 0.1}";
  const std::string text = read_text(kExample);
  const std::string deck = text.substr(0, text.find("  aorta:")) + "  aorta: {" + hgo + "\n" + text.substr(text.find("\nparts:"));
  expect_check_error(kScratch, "angle-in-mm", deck, "beta: 40 mm", "materials.aorta.beta",
                     "unit 'mm' is not an angle (in '40 mm'; expected an angle, e.g. `40 deg`)");
}

TEST(BadInput, WrongTypeNumber) {
  expect_error("wrong-type", "a2: 0.60558", "a2: stiff", "materials.aorta.a2", "expected a number, got 'stiff'");
}

TEST(BadInput, WrongTypeListForScalar) {
  expect_error("wrong-type-list", "thickness: 0.122 mm", "thickness: [0.122 mm]", "parts.wall.thickness",
               "expected a single value");
}

TEST(BadInput, WrongTypeInteger) {
  expect_error("wrong-type-int", "increments: 20", "increments: 2.5", "steps[1].increments",
               "expected an integer, got '2.5'");
}

TEST(BadInput, ZeroThickness) {
  expect_error("zero-thickness", "thickness: 0.122 mm", "thickness: 0 mm", "parts.wall.thickness",
               "value 0 mm is out of range (must be > 0 mm)");
}

TEST(BadInput, NegativeThickness) {
  expect_error("negative-thickness", "thickness: 0.122 mm", "thickness: -0.122 mm", "parts.wall.thickness",
               "value -0.122 mm is out of range (must be > 0 mm)");
}

TEST(BadInput, FungQuadraticFormNotPositiveDefinite) {
  // The message stands at a4, shows the failed condition with the constants as written and
  // their lines, the bound on a4, and the factor 2 of sources that write a4 E1E2.
  const std::string deck = replace(read_text(kExample), "a4: 0.1067 ", "a4: 0.9 ");
  expect_error("fung-not-convex", "a4: 0.1067 ", "a4: 0.9 ", "materials.aorta.a4",
               "the Fung quadratic form is not positive definite (the two-dimensional approach, a3 = a5 = a6 = 0, "
               "needs a1 > 0, a2 > 0 and a1·a2 − a4² > 0), so W would not be convex: a1·a2 − a4² = 0.68238 × 0.60558 "
               "− (0.9)² = -0.3968 ≤ 0",
               "    a4: 0.9");
  expect_error("fung-not-convex-values", "a4: 0.1067 ", "a4: 0.9 ", "materials.aorta.a4",
               fmt_lines("(a1 = 0.68238 (line {}), a2 = 0.60558 (line {}), a4 = 0.9 (line {})): |a4| must be < "
                         "√(a1·a2) = 0.6428. If your source writes Q with a4 E1E2 rather than 2 a4 E1E2, give half its "
                         "value: a4: 0.45",
                         deck, {"a1: 0.68238", "a2: 0.60558", "a4: 0.9"}),
               "    a4: 0.9");
  // a1 itself not positive: at a1.
  expect_error("fung-a1", "a1: 0.68238", "a1: -0.5", "materials.aorta.a1", "a1 = -0.5 ≤ 0 (a1 = -0.5 (line 12)");
  // The full matrix: its determinant, and the a3 that would do.
  expect_error("fung-3d", "    a4: 0.1067", "    a4: 0.1067\n    a3: 0.1\n    a5: 0.5\n    a6: 0.4", "materials.aorta.a3",
               "its determinant is -0.1846 ≤ 0 (a1 = 0.68238 (line 12), a2 = 0.60558 (line 13), a3 = 0.1 (line 15), a4 "
               "= 0.1067 (line 14), a5 = 0.5 (line 16), a6 = 0.4 (line 17)): with these a1, a2, a4, a5, a6, a3 must be "
               "> 0.5594",
               "    a3: 0.1");
}

TEST(BadInput, NegativeFungConstant) {
  expect_error("fung-negative-c", "c: 61.163 kPa", "c: -61.163 kPa", "materials.aorta.c", "value -61.163 kPa (= -0.061163 N/mm²) is out of range (must be > 0 N/mm²)");
}

TEST(BadInput, UndefinedMaterial) {
  expect_error("undefined-material", "material: aorta", "material: aorta2", "parts.wall.material",
               "undefined material 'aorta2'");
}

TEST(BadInput, UndefinedNodeSet) {
  expect_error("undefined-set", "node_set: wall.start", "node_set: wall.begin", "boundary.base.node_set",
               "undefined node set 'wall.begin' (the node sets are: wall.start, wall.end, wall.all)");
}

TEST(BadInput, AnEmptyDofListIsAnErrorAtItsLine) {
  // `dofs: []` would hold nothing, and a step setting the boundary would do nothing.
  expect_error("empty-dofs", "stretch: {node_set: wall.end, dofs: [z]}", "stretch: {node_set: wall.end, dofs: []}",
               "boundary.stretch.dofs",
               "the list of DOFs is empty, so the boundary would hold nothing: name the DOFs it holds (axisymmetric "
               "DOFs are r and z, and slope_r and slope_z on shells), e.g. `dofs: [z]`");
}

TEST(BadInput, ADofListedTwiceIsAnErrorAtItsItem) {
  // `[z, z]` was read as `[z]`; most likely another DOF was meant.
  expect_error("dof-twice", "stretch: {node_set: wall.end, dofs: [z]}", "stretch: {node_set: wall.end, dofs: [z, z]}",
               "boundary.stretch.dofs[1]",
               "DOF 'z' is listed twice in `dofs`: list each DOF once (or write the one meant; not listed: r)");
}

TEST(BadInput, ATubeWithoutX0SaysWhyAndProposesNoOtherSet) {
  // The 3-D quarter tube with its sector written 1.5708 (rad, not exactly π/2): its last column
  // is its x0 by construction, so the deck is valid. With 85 deg there is no column at 90°:
  // the error says why, and does not propose `wall.y0` (another set, not a typo).
  const std::string quarter = read_text(std::string(TUNICA_SOURCE_DIR) + "/examples/rat-aorta-3d.yaml");
  const Outcome ok = run_cli("check " + write_deck("sector-1.5708", replace(quarter, "sector: 90 deg", "sector: 1.5708")));
  EXPECT_EQ(ok.exit_code, 0) << ok.output;
  const Outcome o = expect_check_error(
      kScratch, "sector-85", replace(quarter, "sector: 90 deg", "sector: 85 deg"), "sym_x:", "boundary.sym_x.node_set",
      "undefined node set 'wall.x0': its part's mesh has none, since `x0` holds the nodes at θ = 90° and 270°, on the "
      "plane x = 0, and this tube's sector, 85 deg, ends before 90° (a quarter tube is `sector: 90 deg`) (the node "
      "sets are: ");
  EXPECT_EQ(o.output.find("did you mean"), std::string::npos) << o.output;
}

TEST(BadInput, UndefinedLoadInHistory) {
  expect_error("undefined-load", "load: lumen", "load: lumen2", "output.history[0].load", "undefined load 'lumen2'");
}

TEST(BadInput, StepSetsSomethingUndefined) {
  expect_error("undefined-target", "set: {lumen: 200 mmHg}", "set: {lumenn: 200 mmHg}", "steps[1].set.lumenn",
               "'lumenn' is neither a boundary nor a load");
}

TEST(BadInput, UnknownUnit) {
  expect_error("unknown-unit", "c: 61.163 kPa", "c: 61.163 kPaa", "materials.aorta.c", "unknown unit 'kPaa'");
}

TEST(BadInput, UnitOfTheWrongDimension) {
  expect_error("wrong-dimension", "thickness: 0.122 mm", "thickness: 0.122 kPa", "parts.wall.thickness",
               "unit 'kPa' is not a length");
}

TEST(BadInput, UnknownUnitSystem) {
  expect_error("unknown-system", "units: {length: mm, force: N}", "units: {length: mm, force: Nw}", "units.force",
               "unknown unit 'Nw'");
}

TEST(BadInput, UnknownMaterialType) {
  expect_error("unknown-material-type", "type: fung ", "type: fungus ", "materials.aorta.type",
               "unknown material type 'fungus' (known: fung, hgo, mooney_rivlin, neo_hookean, ogden, neo_hookean_solid)");
}

TEST(BadInput, UnreadableFile) {
  const Outcome o = run_cli("check /nonexistent/deck.yaml");
  EXPECT_EQ(o.exit_code, 2);
  EXPECT_NE(o.output.find("/nonexistent/deck.yaml: cannot read the deck: no such file"), std::string::npos)
      << o.output;
  const fs::path dir = fs::temp_directory_path() / "tunica-bad-input" / "a-directory.yaml";
  fs::create_directories(dir);
  const Outcome d = run_cli("check " + dir.string());
  EXPECT_EQ(d.exit_code, 2) << d.output;
  EXPECT_NE(d.output.find(dir.string() + ": cannot read the deck: it is a directory"), std::string::npos) << d.output;
}

TEST(BadInput, RunWithABadDeckWritesNothingAndKeepsEarlierResults) {
  const fs::path out = fs::temp_directory_path() / "tunica-bad-input" / "kept";
  fs::create_directories(out);
  std::ofstream(out / "history.csv") << "earlier results\n";
  const std::string path = write_deck("run-bad", replace(read_text(kExample), "a2: 0.60558", "a2: x"));
  const Outcome o = run_cli("run " + path + " -o " + out.string());
  EXPECT_EQ(o.exit_code, 2);
  EXPECT_EQ(read_text((out / "history.csv").string()), "earlier results\n");
}

TEST(BadInput, AHistoryColumnNameThatWouldCorruptTheCsvIsRefused) {
  // A comma in `name` split the column in history.csv's header (one name, two columns), so every
  // reader misaligned the rows; a double quote or a line break breaks the row. Refused at the
  // name with the characters allowed and the name with them replaced.
  const std::string from = "name: lambda_theta}";
  expect_error("name-comma", from, "name: \"lambda,theta\"}", "output.history[1].name",
               "'lambda,theta' holds a comma, which would corrupt the header of history.csv (a comma splits the "
               "column; a quote or a line break breaks the row): a column name may hold any printable character but "
               "a comma and a double quote, e.g. `lambda_theta`");
  expect_error("name-quote", from, "name: 'lambda\"theta'}", "output.history[1].name", "'lambda\"theta' holds a double quote");
  expect_error("name-newline", from, "name: \"lambda\\ntheta\"}", "output.history[1].name",
               "'lambda\\ntheta' holds a line break");
  expect_error("name-empty", from, "name: \"\"}", "output.history[1].name", "the column name is empty");
  // Any other printable text is a column of its own: spaces, quotes of another kind, UTF-8. The
  // header and every row of history.csv have as many fields as columns.
  const std::string deck = write_deck("name-printable", replace(read_text(kExample), from, "name: \"λ_θ (it's; 1/2)\"}"));
  const fs::path out = fs::temp_directory_path() / "tunica-bad-input" / "name-printable";
  const Outcome o = run_cli("run " + deck + " -q -o " + out.string());
  ASSERT_EQ(o.exit_code, 0) << o.output;
  std::ifstream csv(out / "history.csv");
  std::string header, row;
  std::getline(csv, header);
  EXPECT_NE(header.find(",λ_θ (it's; 1/2),"), std::string::npos) << header;
  const auto fields = [](const std::string& line) { return std::count(line.begin(), line.end(), ',') + 1; };
  int rows = 0;
  while (std::getline(csv, row)) {
    EXPECT_EQ(fields(row), fields(header)) << row;
    ++rows;
  }
  EXPECT_GT(rows, 1);
}

TEST(BadInput, DeckThatIsNotAMap) {
  const Outcome o = run_cli("check " + write_deck("not-a-map", "- just\n- a list\n"));
  EXPECT_EQ(o.exit_code, 2);
  EXPECT_NE(o.output.find(":1:1: a deck is a YAML map"), std::string::npos) << o.output;
}

TEST(BadInput, DuplicateKey) {
  expect_error("duplicate-key", "    a2: 0.60558\n", "    a2: 0.60558\n    a2: 0.7\n", "materials.aorta.a2",
               "duplicate key 'a2' (first given on line 13)", "    a2: 0.7");
}

TEST(BadInput, DuplicateNamedEntry) {
  expect_error("duplicate-material", "parts:\n", "  aorta: {type: neo_hookean, mu: 1}\n\nparts:\n", "materials.aorta",
               "duplicate key 'aorta' (first given on line 9)", "  aorta: {type: neo_hookean");
}

TEST(BadInput, EmptyOutputDirectory) {
  const Outcome o = run_cli("run " + kExample + " -q -o ''");
  EXPECT_EQ(o.exit_code, 2) << o.output;
  EXPECT_NE(o.output.find("the output directory (-o) is empty"), std::string::npos) << o.output;
}

TEST(BadInput, HistoryColumnThatIsAlwaysWritten) {
  // step, increment and time open every history.csv: a request for `time` would repeat its header.
  expect_error("history-time", "    - {quantity: pressure, load: lumen, unit: mmHg}\n",
               "    - {quantity: time}\n    - {quantity: pressure, load: lumen, unit: mmHg}\n", "output.history[0]",
               "always the first three columns", "    - {quantity: time}");
}

TEST(BadInput, APressureWithoutAUnitIsValidButSaid) {
  // 150 meant as mmHg is 150 N/mm²: the deck is valid, the warning names the line, the key, the
  // value in kPa and mmHg, and the fix.
  const std::string deck = write_deck("pressure-no-unit", replace(read_text(kExample), "set: {lumen: 200 mmHg}", "set: {lumen: 150}"));
  const Outcome o = run_cli("check " + deck);
  EXPECT_EQ(o.exit_code, 0) << o.output;
  EXPECT_NE(o.output.find("pressure-no-unit.yaml:38:18: key 'steps[1].set.lumen': 150 has no unit"), std::string::npos)
      << o.output;
  EXPECT_NE(o.output.find("1.125e+06 mmHg"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("`150 mmHg`"), std::string::npos) << o.output;
  EXPECT_EQ(run_cli("check " + kExample).output.find("warning"), std::string::npos);
}

TEST(BadInput, AModulusWithoutAUnitIsValidButSaid) {
  // `c: 61.163` meant as kPa is 61.163 N/mm², a thousand times too stiff: valid, but said at its
  // line and key, with the value in kPa and the fix.
  const std::string deck = write_deck("modulus-no-unit", replace(read_text(kExample), "c: 61.163 kPa", "c: 61.163"));
  const Outcome o = run_cli("check " + deck);
  EXPECT_EQ(o.exit_code, 0) << o.output;
  EXPECT_NE(o.output.find("modulus-no-unit.yaml:11:8: key 'materials.aorta.c': 61.163 has no unit"), std::string::npos)
      << o.output;
  EXPECT_NE(o.output.find("= 6.116e+04 kPa"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("`61.163 kPa`"), std::string::npos) << o.output;
}

TEST(BadInput, ABarePressureInAnSIDeckIsProposedWithItsValueAsRead) {
  // In metres and newtons a bare pressure is in Pa: `c: 61163` is 61.163 kPa and `lumen: 26664.5`
  // 200 mmHg, both right. The unit proposed keeps the value (`61.163 kPa`, not `61163 kPa`); the
  // number with the unit perhaps meant is offered only as that.
  std::string text = replace(read_text(kExample), "units: {length: mm, force: N}", "units: {length: m, force: N}");
  text = replace(text, "c: 61.163 kPa", "c: 61163");
  text = replace(text, "set: {lumen: 200 mmHg}", "set: {lumen: 26664.5}");
  const Outcome o = run_cli("check " + write_deck("si-bare-pressure", text));
  EXPECT_EQ(o.exit_code, 0) << o.output;
  for (const char* says :
       {"key 'materials.aorta.c': 61163 has no unit and is taken in the deck's pressure unit, N/m² (= 61.16 kPa); "
        "write the unit to be sure, e.g. `61.163 kPa` (this value), or `61163 kPa` if kPa is meant",
        "key 'steps[1].set.lumen': 26664.5 has no unit and is taken in the deck's pressure unit, N/m² (= 26.66 kPa = "
        "200 mmHg); write the unit to be sure, e.g. `26.6645 kPa` (this value), or `26664.5 mmHg` if mmHg is meant"})
    EXPECT_NE(o.output.find(says), std::string::npos) << says << " missing from: " << o.output;
  // N/m² is Pa: no pascal reading is offered there; in mm and N a bare 6000 may be meant in Pa.
  EXPECT_EQ(o.output.find("if pascals are meant"), std::string::npos) << o.output;
  const Outcome mm = run_cli(
      "check " + write_deck("mm-bare-pascals", replace(read_text(kExample), "set: {lumen: 200 mmHg}", "set: {lumen: 6000}")));
  EXPECT_NE(mm.output.find("or `6000 mmHg` if mmHg is meant, or `6000 Pa` if pascals are meant"), std::string::npos)
      << mm.output;
}

TEST(BadInput, AnAngleWithoutAUnitIsValidButSaid) {
  // `beta: 0.7` is 0.7 rad = 40.1°: in range, so valid, but said at its line and key with how
  // it was read and the fix; so are a meridian arc's and a tube's angles. 0 is the same in
  // every unit and is not said.
  const std::string hgo = "    type: hgo\n    mu: 30 kPa\n    k1: 100 kPa\n    k2: 5\n    beta: 0.7\n    kappa: 0.1";
  const std::string text = read_text(kExample);
  const std::string deck = text.substr(0, text.find("    type: fung")) + hgo + "\n" + text.substr(text.find("\nparts:"));
  Outcome o = run_cli("check " + write_deck("angle-no-unit", deck));
  EXPECT_EQ(o.exit_code, 0) << o.output;
  EXPECT_NE(o.output.find("tunica: warning: " + fs::path(write_deck("angle-no-unit", deck)).string() + ":" +
                          std::to_string(line_of(deck, "beta: 0.7")) +
                          ":11: key 'materials.aorta.beta': 0.7 has no unit and is read in radians (0.7 rad = 40.11 "
                          "deg); write the unit to be sure, e.g. `0.7 rad`, or `0.7 deg` if degrees are meant"),
            std::string::npos)
      << o.output;
  o = run_cli("check " + write_deck("angle-zero", replace(deck, "beta: 0.7", "beta: 0")));
  EXPECT_EQ(o.exit_code, 0) << o.output;
  EXPECT_EQ(o.output.find("warning"), std::string::npos) << o.output;
  const std::string sphere = read_text(std::string(TUNICA_SOURCE_DIR) + "/examples/balloon-sphere.yaml");
  o = run_cli("check " + write_deck("arc-no-unit", replace(sphere, "end_angle: 90 deg", "end_angle: 1.5")));
  EXPECT_EQ(o.exit_code, 0) << o.output;
  EXPECT_NE(o.output.find("key 'parts.balloon.mesh.end_angle': 1.5 has no unit and is read in radians (1.5 rad = 85.94 deg)"),
            std::string::npos)
      << o.output;
  const std::string quarter = read_text(std::string(TUNICA_SOURCE_DIR) + "/examples/rat-aorta-3d.yaml");
  o = run_cli("check " + write_deck("sector-no-unit", replace(quarter, "sector: 90 deg", "sector: 1.5707963267948966")));
  EXPECT_EQ(o.exit_code, 0) << o.output;
  EXPECT_NE(o.output.find("key 'parts.wall.mesh.sector': 1.5707963267948966 has no unit and is read in radians"), std::string::npos)
      << o.output;
}

TEST(BadInput, AnArcAngleInRadiansToAFewDigitsEndsOnTheAxis) {
  // `end_angle: 1.5708` is π/2 to 5 digits, 4·10⁻⁶ rad past the pole: its node, 4·10⁻⁶ mm beyond the
  // axis, is put on it (less than a thousandth of an element), and the angle is said as read in
  // radians. `1.571` puts it 2·10⁻⁴ mm beyond (13 thousandths of an element): refused, with the
  // angle that ends on the axis as the fix, not `1.571 deg`.
  const std::string sphere = read_text(std::string(TUNICA_SOURCE_DIR) + "/examples/balloon-sphere.yaml");
  const std::string arc = "end_angle: 90 deg";
  const std::string text = replace(sphere, arc, "end_angle: 1.5708");
  Outcome o = run_cli("check " + write_deck("arc-radians-pole", text));
  EXPECT_EQ(o.exit_code, 0) << o.output;
  EXPECT_NE(o.output.find("key 'parts.balloon.mesh.end_angle': 1.5708 has no unit and is read in radians (1.5708 rad = "
                          "90 deg); write the unit to be sure"),
            std::string::npos)
      << o.output;
  const tunica::Model m = tunica::read_deck_text(text, "arc-radians-pole.yaml");
  EXPECT_EQ(m.X[m.parts[0].nodes.back()](0), 0.0);
  o = expect_check_error(kScratch, "arc-radians-short", replace(sphere, arc, "end_angle: 1.571"), "end_angle: 1.571",
                         "parts.balloon.mesh.end_angle",
                         "1.571 has no unit and is read in radians (1.571 rad = 90.01 deg), which puts node 100 at a "
                         "negative radius r = -0.000203673 mm: a plain number is radians; to end on the axis write "
                         "`90 deg` (or the angle in radians to more digits, `1.570796327`)");
  EXPECT_EQ(o.output.find("1.571 deg"), std::string::npos) << o.output;
}

TEST(BadInput, ABareArcAngleThatBreaksTheMeridianIsNamedWithDegrees) {
  // `end_angle: 90` is 90 rad: the arc turned 14 times and ended in "node 2 has a negative
  // radius" at the mesh, naming no key. The error stands at the angle, says how it was read and
  // proposes degrees; without a bare angle the mesh is blamed as before, without the radians hint.
  const std::string sphere = read_text(std::string(TUNICA_SOURCE_DIR) + "/examples/balloon-sphere.yaml");
  const std::string arc = "start_angle: 0 deg, end_angle: 90 deg";
  Outcome o = expect_check_error(kScratch, "arc-90", replace(sphere, arc, "start_angle: 0 deg, end_angle: 90"),
                                 "end_angle: 90,", "parts.balloon.mesh.end_angle",
                                 "90 has no unit and is read in radians (90 rad = 5157 deg), which makes the arc span "
                                 "5156.62 deg, more than a full turn: a plain number is radians; for degrees write `90 deg`");
  // Within a turn, 3 rad (172°) reaches r < 0; both bare, the first is blamed and the other named.
  o = expect_check_error(kScratch, "arc-3", replace(sphere, arc, "start_angle: -1, end_angle: 3"), "start_angle: -1",
                         "parts.balloon.mesh.start_angle",
                         "-1 has no unit and is read in radians (-1 rad = -57.3 deg), which puts node 65 at a negative "
                         "radius r = -0.0291995 mm: a plain number is radians; for degrees write `-1 deg` (and `3 deg` "
                         "for `end_angle`, also without a unit)");
  expect_check_error(kScratch, "arc-deg", replace(sphere, arc, "start_angle: 0 deg, end_angle: 120 deg"), "mesh: {type: arc",
                     "parts.balloon.mesh",
                     "the meridian has node 76 at a negative radius r = -0.0209424 mm: an axisymmetric meridian stays "
                     "at r ≥ 0 (check `center`, `radius` and the angles, or `from` and `to`)");
}

TEST(BadInput, NoExampleDeckWarns) {
  // The examples write a unit on every pressure and angle; none of them is warned about.
  for (const auto& entry : fs::directory_iterator(std::string(TUNICA_SOURCE_DIR) + "/examples")) {
    if (entry.path().extension() != ".yaml") continue;
    const Outcome o = run_cli("check --allow-scripts " + entry.path().string());
    EXPECT_EQ(o.exit_code, 0) << entry.path() << ": " << o.output;
    EXPECT_EQ(o.output.find("warning"), std::string::npos) << entry.path() << ": " << o.output;
  }
}

TEST(BadInput, APressureGivenToABoundaryNamesTheLoads) {
  // `stretch` is a displacement boundary: a pressure there means the load was meant.
  expect_error("pressure-to-boundary", "set: {stretch: 0.6 mm}", "set: {stretch: 150 mmHg}", "steps[0].set.stretch",
               "'stretch' is a boundary, whose value is a prescribed position change (in mm), but '150 mmHg' is a "
               "pressure: a pressure is set on a load (the loads are: lumen)");
}

TEST(BadInput, ARigidMotionNoBoundaryConditionHoldsIsWarnedAbout) {
  // The 3-D quarter tube with its symmetry planes held is held (a first-order rotation its stress
  // stops is not named); without them it may translate in x and y and turn about z; a full tube
  // held in z at its ends and in x on the plane x = 0 may still translate in y (the two lines of
  // that plane stop the rotation); an axisymmetric tube without a held z slides along the axis.
  const std::string quarter = std::string(TUNICA_SOURCE_DIR) + "/examples/rat-aorta-3d.yaml";
  EXPECT_EQ(run_cli("check " + quarter).output.find("warning"), std::string::npos);
  const std::string free3d = write_deck(
      "rigid-3d", replace(replace(read_text(quarter), "  sym_x:   {node_set: wall.x0, dofs: [x]}      # symmetry plane x = 0\n", ""),
                          "  sym_y:   {node_set: wall.y0, dofs: [y]}      # symmetry plane y = 0\n", ""));
  Outcome o = run_cli("check " + free3d);
  EXPECT_EQ(o.exit_code, 0) << o.output;
  EXPECT_NE(o.output.find("rigid-3d.yaml:23:3: key 'boundary': part 'wall': the boundary conditions leave it free to "
                          "move rigidly (translation along x, translation along y, rotation about z)"),
            std::string::npos)
      << o.output;
  // What to hold comes from the part's own node sets: its symmetry planes, by their names.
  EXPECT_NE(o.output.find("hold enough DOFs to stop them, e.g. x of `wall.x0` (on x = 0) and y of `wall.y0` (on y = 0): "
                          "held so, the body can still inflate freely"),
            std::string::npos)
      << o.output;
  EXPECT_EQ(o.output.find("<part>"), std::string::npos) << o.output;
  const std::string full = write_deck(
      "rigid-full", replace(replace(replace(read_text(quarter), "sector: 90 deg, ", ""),
                                    "  sym_x:   {node_set: wall.x0, dofs: [x]}      # symmetry plane x = 0\n", ""),
                            "  sym_y:   {node_set: wall.y0, dofs: [y]}      # symmetry plane y = 0\n",
                            "  hold_x:  {node_set: wall.x0, dofs: [x]}\n"));
  o = run_cli("check " + full);
  EXPECT_NE(o.output.find("free to move rigidly (translation along y), so"),
            std::string::npos)
      << o.output;
  EXPECT_NE(o.output.find("e.g. y of `wall.y0` (on y = 0)"), std::string::npos) << o.output;
  const std::string axisym = write_deck(
      "rigid-axisym", replace(replace(read_text(kExample), "  base:    {node_set: wall.start, dofs: [z]}   # axial position held at z = 0\n", ""),
                              "  stretch: {node_set: wall.end, dofs: [z]}     # axial displacement of the other end\n",
                              "  stretch: {node_set: wall.end, dofs: [r]}\n"));
  o = run_cli("check " + axisym);
  EXPECT_NE(o.output.find("part 'wall': no boundary condition holds z, so it is free to slide along the axis (a "
                          "singular tangent): hold z of at least one node, e.g. of `wall.start`"),
            std::string::npos)
      << o.output;
}

TEST(BadInput, ABodyFreeToMoveWithoutABoundarySectionIsSaidAtItsFirstStep) {
  // The axisymmetric example without its `boundary` (and the prestretch that sets one): nothing
  // holds z. Said at the first step, where the tangent is singular, not at the deck's 1:1.
  std::string text = read_text(kExample);
  text = text.substr(0, text.find("boundary:\n")) + text.substr(text.find("loads:\n"));
  text = replace(text, "  - name: prestretch\n    increments: 6\n    set: {stretch: 0.6 mm}", "");
  text = replace(text, "    - {quantity: reaction_z, node_set: wall.end, name: axial_force, unit: N}\n", "");
  const std::string deck = write_deck("no-boundary", text);
  const Outcome o = run_cli("check " + deck);
  EXPECT_EQ(o.exit_code, 0) << o.output;
  EXPECT_NE(o.output.find("no-boundary.yaml:" + std::to_string(line_of(text, "  - name: inflation")) +
                          ":5: key 'steps[0]': part 'wall': no boundary condition holds z, so it is free to slide along "
                          "the axis (a singular tangent): hold z of at least one node, e.g. of `wall.start` (the deck "
                          "has no boundary conditions yet: add them in a `boundary` section)"),
            std::string::npos)
      << o.output;
}

TEST(BadInput, TheRigidMotionFixComesFromThePartsOwnSets) {
  // A sphere has no `x0` or `y0`: held at its south pole only, it may turn about three lines. Its
  // north pole held in x and y stops the turns about x and y (both poles stay on the z axis as it
  // inflates), and nothing but a node off the axis stops the turn about z: named by its index in
  // the part, with the node set that names it. The proposal was "x0/y0 of `<part>`".
  const std::string sphere =
      "units: {length: mm, force: N}\nmaterials:\n  latex: {type: neo_hookean, mu: 0.2 MPa}\n"
      "parts:\n  balloon: {element: membrane, material: latex, thickness: 0.1 mm, mesh: {type: sphere, radius: 5 mm, n: 6}}\n"
      "boundary:\n  south: {node_set: balloon.south, dofs: [x, y, z]}\n"
      "loads:\n  p: {type: pressure, part: balloon}\nsteps:\n  - {name: inflate, increments: 1, set: {p: 5 kPa}}\n";
  const Outcome o = run_cli("check " + write_deck("rigid-sphere", sphere));
  EXPECT_EQ(o.exit_code, 0) << o.output;
  EXPECT_NE(o.output.find("hold enough DOFs to stop them, e.g. x and y of `balloon.north` (on x = 0 and y = 0) and y of "
                          "node 24 of part 'balloon', at (5, 0, 0) (as a node set: `{part: balloon, nodes: [24]}`): held "
                          "so, the body can still inflate freely"),
            std::string::npos)
      << o.output;
  // Held as proposed, it is held.
  const std::string held = replace(sphere, "boundary:\n",
                                   "node_sets:\n  turn: {part: balloon, nodes: [24]}\nboundary:\n"
                                   "  north: {node_set: balloon.north, dofs: [x, y]}\n  turn: {node_set: turn, dofs: [y]}\n");
  const Outcome h = run_cli("check " + write_deck("rigid-sphere-held", held));
  EXPECT_EQ(h.exit_code, 0) << h.output;
  EXPECT_EQ(h.output.find("warning"), std::string::npos) << h.output;
}

TEST(BadInput, ACylindricalFrameThatDoesNotFitItsSurfaceIsWarnedAbout) {
  // The 3-D quarter tube runs along z: its frame's axis given as x, or its point far off the
  // tube's axis, gives valid but unmeant fibre directions; the warning names the part, the
  // fraction of its area and the axis its normals are perpendicular to.
  const std::string quarter = std::string(TUNICA_SOURCE_DIR) + "/examples/rat-aorta-3d.yaml";
  const std::string frame = "frame: {type: cylindrical, axis: [0, 0, 1]}";
  const std::string along_x =
      write_deck("frame-axis", replace(read_text(quarter), frame, "frame: {type: cylindrical, axis: [1, 0, 0]}"));
  Outcome o = run_cli("check " + along_x);
  EXPECT_EQ(o.exit_code, 0) << o.output;
  // At the part's own `frame` (it stood at `parts`).
  EXPECT_NE(o.output.find("frame-axis.yaml:" + std::to_string(line_of(read_text(along_x), "    frame: {")) +
                          ":12: key 'parts.wall.frame': part 'wall': its cylindrical frame (axis [1, 0, 0] "
                          "through (0, 0, 0)) does not fit the surface over"),
            std::string::npos)
      << o.output;
  EXPECT_NE(o.output.find("most nearly perpendicular to [0, 0, 1] (a tube's axis)"), std::string::npos) << o.output;
  const std::string off_axis = write_deck(
      "frame-point", replace(read_text(quarter), frame, "frame: {type: cylindrical, axis: [0, 0, 1], point: [3 mm, 0 mm, 0 mm]}"));
  o = run_cli("check " + off_axis);
  EXPECT_NE(o.output.find("its cylindrical frame (axis [0, 0, 1] through (3, 0, 0)) does not fit"), std::string::npos)
      << o.output;
}

TEST(BadInput, AMeridianMeshOnA3DPartNamesTheAxisymmetricElement) {
  // `element: membrane` with the axisymmetric example's `line` mesh: the mesh type is the
  // mistake, not the missing frame its anisotropic material would also need.
  expect_error("meridian-on-3d", "    element: axisymmetric_membrane\n", "    element: membrane\n", "parts.wall.mesh.type",
               "unknown mesh type 'line' for a membrane part (known: gmsh, octant, sphere, tube); `line` meshes a "
               "meridian: for an axisymmetric part write `element: axisymmetric_membrane`",
               "    mesh: {type: line,");
}

TEST(BadInput, ASurfaceMeshOnAnAxisymmetricPartNamesThe3dElement) {
  // `type: tube` under `element: axisymmetric_membrane`: the part wants a meridian.
  expect_error("tube-on-axisymmetric", "    mesh: {type: line, from: [0.763 mm, 0 mm], to: [0.763 mm, 1 mm], elements: 1}",
               "    mesh: {type: tube, radius: 0.763 mm, length: 1 mm, around: 16, along: 4}", "parts.wall.mesh.type",
               "unknown mesh type 'tube' for an axisymmetric part (known: line, arc, points); `tube` meshes a 3-D "
               "surface: for a 3-D part write `element: membrane`, or describe the meridian with `line`, `arc` or "
               "`points`",
               "    mesh: {type: tube,");
}

TEST(BadInput, AHistoryQuantityWithoutItsSetNamesTheDecksChoices) {
  expect_error("history-no-part", "{quantity: lambda_1, part: wall, name: lambda_theta}",
               "{quantity: lambda_1, name: lambda_theta}", "output.history[1].quantity",
               "quantity 'lambda_1' needs the key 'part' (e.g. `part: wall`; the deck's: wall)");
  expect_error("history-no-load", "{quantity: pressure, load: lumen, unit: mmHg}", "{quantity: pressure, unit: mmHg}",
               "output.history[0].quantity",
               "quantity 'pressure' needs the key 'load' (e.g. `load: lumen`; the deck's: lumen)");
}

TEST(BadInput, AnotherCodesMaterialConstantIsRelatedToTunicasOwn) {
  const std::string fung = "    type: fung              # two-dimensional approach: a3 = a5 = a6 = 0\n    c: 61.163 kPa\n"
                           "    a1: 0.68238\n    a2: 0.60558\n    a4: 0.1067";
  expect_error("abaqus-c10", fung, "    type: mooney_rivlin\n    C10: 30 kPa\n    C01: 3 kPa", "materials.aorta.C10",
               "unknown key 'C10' (allowed here: type, b1, b2): W = b1 (I1 − 3) + b2 (I2 − 3) here, Abaqus' and "
               "FEBio's Mooney–Rivlin form: C10 is `b1` and C01 is `b2`",
               "    C10: 30 kPa");
  expect_error("febio-e", fung, "    type: neo_hookean\n    E: 300 kPa\n    v: 0.49", "materials.aorta.E",
               "unknown key 'E' (allowed here: type, mu): write the shear modulus `mu`: for an incompressible "
               "material μ = E/3",
               "    E: 300 kPa");
  expect_error("febio-v", fung, "    type: neo_hookean\n    mu: 100 kPa\n    v: 0.49", "materials.aorta.v",
               "Tunica's membrane materials are exactly incompressible (ν = 0.5, no bulk modulus or D1): leave it out",
               "    v: 0.49");
}

TEST(BadInput, AMassForTheForceUnitSaysItIsAMass) {
  expect_error("force-kg", "units: {length: mm, force: N}", "units: {length: mm, force: kg}", "units.force",
               "unit 'kg' is not a force (a force unit, e.g. N, mN, kN); 'kg' is a mass: forces are in newtons (1 kgf "
               "= 9.80665 N), e.g. `force: N`");
}

TEST(BadInput, APartHeldAtEveryNodeInEveryDofIsWarnedAbout) {
  // `base` given `wall.all` and both DOFs: the wall cannot deform, the pressure does nothing.
  const std::string text =
      replace(replace(replace(read_text(kExample), "base:    {node_set: wall.start, dofs: [z]}",
                              "base:    {node_set: wall.all, dofs: [r, z]}"),
                      "  stretch: {node_set: wall.end, dofs: [z]}", ""),
              "set: {stretch: 0.6 mm}", "set: {lumen: 10 mmHg}");
  const std::string path = write_deck("held-part", text);
  const Outcome o = run_cli("check " + path);
  EXPECT_EQ(o.exit_code, 0) << o.output;
  EXPECT_NE(o.output.find(fmt::format("warning: {}:{}:", path, line_of(text, "base:    {node_set: wall.all"))),
            std::string::npos)
      << o.output;
  EXPECT_NE(o.output.find("key 'boundary.base': every node of part 'wall' is held in every DOF (r, z) by boundary "
                          "'base': the part cannot deform"),
            std::string::npos)
      << o.output;
  EXPECT_NE(o.output.find("the ends ('wall.start', 'wall.end')"), std::string::npos) << o.output;
  // The example as it is: no such warning.
  EXPECT_EQ(run_cli("check " + kExample).output.find("cannot deform"), std::string::npos);
}

TEST(BadInput, AReactionOnADofNothingHoldsIsWarnedAboutWithWhatTheSetHolds) {
  // wall.end holds z only (boundary `stretch`): its r reaction would be 0 throughout.
  const std::string text = replace(read_text(kExample), "{quantity: reaction_z, node_set: wall.end,",
                                   "{quantity: reaction_r, node_set: wall.end,");
  const std::string path = write_deck("reaction-free", text);
  const Outcome o = run_cli("check " + path);
  EXPECT_EQ(o.exit_code, 0) << o.output;
  EXPECT_NE(o.output.find(fmt::format("warning: {}:{}:", path, line_of(text, "{quantity: reaction_r"))), std::string::npos)
      << o.output;
  EXPECT_NE(o.output.find("key 'output.history[8].node_set': 'reaction_r' is the reaction on prescribed r DOFs, and no "
                          "boundary holds r at any node of 'wall.end' (the boundaries on it, stretch, hold z)"),
            std::string::npos)
      << o.output;
  // A set some of whose nodes hold the DOF is fine: the sum over them.
  const Outcome some = run_cli("check " + write_deck("reaction-some-held",
                                                     replace(read_text(kExample), "{quantity: reaction_z, node_set: wall.end,",
                                                             "{quantity: reaction_z, node_set: wall.all,")));
  EXPECT_EQ(some.exit_code, 0) << some.output;
  EXPECT_EQ(some.output.find("warning"), std::string::npos) << some.output;
}

TEST(BadInput, ABinaryOrNonUtf8DeckIsNamedAsSuch) {
  const std::string binary = write_deck("binary", "units: {length: mm, force: N}\n\x7f" "ELF\x01\x02");
  const Outcome b = run_cli("check " + binary);
  EXPECT_EQ(b.exit_code, 2) << b.output;
  EXPECT_NE(b.output.find(binary + ":2:1: the deck is not a text file: byte 0x7F at line 2, column 1, is a control "
                                   "character"),
            std::string::npos)
      << b.output;
  const std::string latin = write_deck("latin-1", "title: 5 \xb5m wall\nunits: {length: mm, force: N}\n");
  const Outcome l = run_cli("check " + latin);
  EXPECT_EQ(l.exit_code, 2) << l.output;
  EXPECT_NE(l.output.find(latin + ":1:10: byte 0xB5 at line 1, column 10, is not UTF-8"), std::string::npos) << l.output;
  EXPECT_NE(l.output.find("save the deck as UTF-8"), std::string::npos) << l.output;
}

TEST(BadInput, AMeshOrSurfaceGivenAsTheDeckIsNamedWithWhereItGoes) {
  const std::string msh = write_deck("given-msh", "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n");
  const Outcome m = run_cli("check " + msh);
  EXPECT_EQ(m.exit_code, 2) << m.output;
  EXPECT_NE(m.output.find(msh + ":1:1: a deck is a YAML map"), std::string::npos) << m.output;
  EXPECT_NE(m.output.find("(this file is a Gmsh mesh (.msh), not a deck: give the YAML deck, whose part names it in its "
                          "mesh, `mesh: {type: gmsh, file: wall.msh, surface: wall}`)"),
            std::string::npos)
      << m.output;
  const std::string stl = write_deck("given-stl", "solid vessel\n  facet normal 0 0 1\n");
  const Outcome s = run_cli("check " + stl);
  EXPECT_EQ(s.exit_code, 2) << s.output;
  EXPECT_NE(s.output.find("this file is an ASCII STL surface, not a deck"), std::string::npos) << s.output;
  EXPECT_NE(s.output.find("`Merge \"vessel.stl\"; Physical Surface(\"wall\") = {1};`"), std::string::npos) << s.output;
  // A YAML scalar that is none of these: the plain message.
  const std::string word = write_deck("given-word", "hello\n");
  const Outcome w = run_cli("check " + word);
  EXPECT_EQ(w.exit_code, 2) << w.output;
  EXPECT_EQ(w.output.find("this file is"), std::string::npos) << w.output;
}

TEST(BadInput, AContactOffsetLargerThanTheStartingGapIsRefusedAtTheOffset) {
  // A tube at r = 1.5 mm in a sleeve of 2 mm with an offset of 0.6 mm: penetrated by 0.1 mm at rest.
  std::string deck = R"(units: {length: mm, force: N}
materials:
  mr: {type: mooney_rivlin, b1: 0.5 MPa, b2: 0.1 MPa}
parts:
  tube: {element: axisymmetric_membrane, material: mr, thickness: 0.05 mm, mesh: {type: line, from: [1.5 mm, 0 mm], to: [1.5 mm, 5 mm], elements: 20}}
rigid_surfaces:
  sleeve: {type: cylinder, radius: 2.0 mm, side: inside}
contact:
  tube_sleeve: {slave: tube, rigid: sleeve, penalty: 1e3 N/mm^3, offset: 0.6 mm}
boundary:
  z0: {node_set: tube.start, dofs: [z]}
  z1: {node_set: tube.end, dofs: [z]}
loads:
  p: {type: pressure, part: tube}
steps:
  - {name: inflate, increments: 20, set: {p: 60 kPa}}
)";
  const Outcome o = run_cli("check " + write_deck("offset-big", deck));
  EXPECT_EQ(o.exit_code, 2) << o.output;
  EXPECT_NE(o.output.find("key 'contact.tube_sleeve.offset': contact pair 'tube_sleeve': the offset, 0.6 mm, is larger "
                          "than the gap the slave starts with: slave node 0 (at r = 1.5 mm, z = 0 mm; its elements are "
                          "0.25 mm long) starts 0.5 mm from the surface, so it counts as penetrated by 0.1 mm"),
            std::string::npos)
      << o.output;
  // An offset below the gap is fine.
  const Outcome fine = run_cli("check " + write_deck("offset-fine", replace(deck, "offset: 0.6 mm", "offset: 0.4 mm")));
  EXPECT_EQ(fine.exit_code, 0) << fine.output;
}

TEST(BadInput, AMeridianLineOfNoLengthOrOnTheAxisSaysHowToWriteOne) {
  expect_error("line-no-length", "to: [0.763 mm, 1 mm]", "to: [0.763 mm, 0 mm]", "parts.wall.mesh.to",
               "`to` is `from`, [0.763, 0] mm: the line has no length");
  expect_error("line-on-axis", "from: [0.763 mm, 0 mm], to: [0.763 mm, 1 mm]", "from: [0 mm, 0 mm], to: [0 mm, 1 mm]",
               "parts.wall.mesh.from", "the line lies on the axis (r = 0 at both ends)");
}

TEST(BadInput, TwoStepsOfOneNameAndAnUnusedMaterialAreWarnedAbout) {
  std::string text = replace(read_text(kExample), "name: inflation", "name: prestretch");
  text = replace(text, "materials:\n", "materials:\n  spare: {type: neo_hookean, mu: 10 kPa}\n");
  const std::string path = write_deck("names", text);
  const Outcome o = run_cli("check " + path);
  EXPECT_EQ(o.exit_code, 0) << o.output;
  EXPECT_NE(o.output.find("key 'steps[1].name': step name 'prestretch' is also the name of the step on line " +
                          std::to_string(line_of(text, "name: prestretch"))),
            std::string::npos)
      << o.output;
  EXPECT_NE(o.output.find("key 'materials.spare': material 'spare' is used by no part ('wall' uses 'aorta')"),
            std::string::npos)
      << o.output;
}

TEST(BadInput, ANumberBeyondADoubleIsTooLargeNotNoNumber) {
  expect_error("huge", "c: 61.163 kPa", "c: 1e400 kPa", "materials.aorta.c",
               "the number in '1e400 kPa' is too large for any value (beyond 1.8e308)");
}

TEST(BadInput, AnOutputUnitOfTheWrongCaseAndANodeSetForAPartsQuantityNameTheFix) {
  // Unit symbols are case-sensitive (UDUNITS-2): `kpa` gets the common units and the nearest.
  expect_error("output-unit-case", "    - {quantity: pressure, load: lumen, unit: mmHg}",
               "    - {quantity: pressure, load: lumen, unit: kpa}", "output.history[0].unit",
               "unknown unit 'kpa' (the common units of pressure (stress) are: Pa, kPa, MPa");
  expect_error("output-unit-case-2", "    - {quantity: pressure, load: lumen, unit: mmHg}",
               "    - {quantity: pressure, load: lumen, unit: kpa}", "output.history[0].unit", "did you mean 'kPa'?");
  // The radius of a node set's nodes is a node quantity.
  expect_error("radius-of-a-node-set", "    - {quantity: radius, part: wall, unit: mm}",
               "    - {quantity: radius, node_set: wall.end, unit: mm}", "output.history[7].node_set",
               "quantity 'radius' takes a part; the quantities of a node set's nodes are position_r, position_z");
  expect_error("radius-of-a-node-set-2", "    - {quantity: radius, part: wall, unit: mm}",
               "    - {quantity: radius, node_set: wall.end, unit: mm}", "output.history[7].node_set",
               "(the radius of its nodes is `position_r`, with `reduce: mean|min|max`)");
  // A part's set named without the part.
  expect_error("node-set-without-its-part", "stretch: {node_set: wall.end,", "stretch: {node_set: end,",
               "boundary.stretch.node_set", "undefined node set 'end' (the node sets are: wall.start, wall.end, "
               "wall.all; did you mean 'wall.end'?)");
}

TEST(BadInput, AContactPenaltyWithoutAUnitIsValidButSaid) {
  const std::string deck = R"(units: {length: mm, force: N}
materials:
  mr: {type: mooney_rivlin, b1: 0.5 MPa, b2: 0.1 MPa}
parts:
  tube: {element: axisymmetric_membrane, material: mr, thickness: 0.1 mm, mesh: {type: line, from: [1 mm, 0 mm], to: [1 mm, 2 mm], elements: 4}}
boundary:
  ends: {node_set: tube.all, dofs: [z]}
rigid_surfaces:
  sleeve: {type: cylinder, radius: 1.3 mm, side: inside}
contact:
  tube_sleeve: {slave: tube, rigid: sleeve, penalty: 1000}
loads:
  p: {type: pressure, part: tube}
steps:
  - {increments: 4, set: {p: 50 kPa}}
)";
  const Outcome o = run_cli("check " + write_deck("penalty-no-unit", deck));
  EXPECT_EQ(o.exit_code, 0) << o.output;
  EXPECT_NE(o.output.find(":11:54: key 'contact.tube_sleeve.penalty': 1000 has no unit and is taken in the deck's unit "
                          "of a penalty (contact pressure per unit penetration), N/mm³; write the unit to be sure, e.g. "
                          "`1000 N/mm³` (this value)"),
            std::string::npos)
      << o.output;
  const Outcome ok = run_cli("check " + write_deck("penalty-unit", replace(deck, "penalty: 1000}", "penalty: 1000 N/mm^3}")));
  EXPECT_EQ(ok.exit_code, 0) << ok.output;
  EXPECT_EQ(ok.output.find("has no unit"), std::string::npos) << ok.output;
}
