// A restart refuses a deck that changed what the converged increments depend on, naming the
// key with its old and new values (io/deck_fingerprint.hpp), and accepts changes that do not:
// the solver settings, the steps not yet reached. The run to resume is the rat-aorta example
// whose second step is made to fail (one increment, one iteration): its prestretch step is
// converged, the inflation step not begun.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>

#include "../support/capture.hpp"

using namespace tunica::test;
namespace fs = std::filesystem;

namespace {

struct Outcome {
  int code = -1;
  std::string output;
};

Outcome tunica_cli(const std::string& args, const fs::path& log) {
  const int status =
      std::system((std::string(TUNICA_BINARY) + " " + args + " > " + log.string() + " 2>&1").c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_text(log.string())};
}

/// 1-based line of the first occurrence of `needle` in `text`.
int line_in(const std::string& text, const std::string& needle) {
  const auto pos = text.find(needle);
  EXPECT_NE(pos, std::string::npos) << needle;
  return pos == std::string::npos ? 0 : 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(pos), '\n'));
}

const std::string kExample = std::string(TUNICA_SOURCE_DIR) + "/examples/rat-aorta-inflation.yaml";
const std::string kInflation = "  - name: inflation\n    increments: 20\n";

class RestartFingerprint : public ::testing::Test {
protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("tunica-fingerprint-" + std::to_string(getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    original_ = read_text(kExample);
    ASSERT_NE(original_.find(kInflation), std::string::npos);
    const std::string failing =
        replace(original_, kInflation, "  - name: inflation\n    increments: 1\n    solver: {max_iterations: 1, max_cutbacks: 0}\n");
    const Outcome o = tunica_cli("run " + write("failing.yaml", failing) + " -q -o " + out(), dir_ / "first.log");
    ASSERT_EQ(o.code, 3) << o.output;
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& name, const std::string& text) {
    const fs::path p = dir_ / name;
    std::ofstream(p) << text;
    return p.string();
  }
  std::string out() const { return (dir_ / "out").string(); }
  Outcome restart(const std::string& name, const std::string& text) {
    return tunica_cli("run " + write(name, text) + " -q --restart " + out(), dir_ / (name + ".log"));
  }

  fs::path dir_;
  std::string original_;
};

}  // namespace

TEST_F(RestartFingerprint, AChangedMaterialIsRefusedWithItsKeyAndValues) {
  const std::string changed = replace(original_, "a1: 0.68238", "a1: 0.7");
  const Outcome o = restart("material.yaml", changed);
  EXPECT_EQ(o.code, 2) << o.output;
  // The deck, the line and column of the changed value (as other deck errors), and the key
  // with its line in the list.
  const std::string line = std::to_string(line_in(changed, "a1: 0.7"));
  EXPECT_NE(o.output.find((dir_ / "material.yaml").string() + ":" + line + ":9: the deck differs"), std::string::npos)
      << o.output;
  EXPECT_NE(o.output.find("line " + line + ": materials.aorta.a1 (was '0.68238', now '0.7')"), std::string::npos)
      << o.output;
  // Nothing of the run was touched: it still restarts with the deck it had.
  EXPECT_EQ(restart("unchanged.yaml", original_).code, 0);
}

TEST_F(RestartFingerprint, EachChangedKeyIsListedWithItsDeckLine) {
  // Two changes: the message stands at the first; a key no longer given is placed at the map
  // that held it.
  const std::string changed =
      replace(replace(original_, "c: 61.163 kPa", "c: 0.061163 MPa"), "    - {quantity: E_2, part: wall, name: E_z}",
              "    - {quantity: E_2, part: wall}");
  const Outcome o = restart("two.yaml", changed);
  EXPECT_EQ(o.code, 2) << o.output;
  const std::string c_line = std::to_string(line_in(changed, "c: 0.061163 MPa"));
  const std::string e2_line = std::to_string(line_in(changed, "{quantity: E_2"));
  EXPECT_NE(o.output.find((dir_ / "two.yaml").string() + ":" + c_line + ":8: the deck differs"), std::string::npos)
      << o.output;
  EXPECT_NE(o.output.find("(2 keys in"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("line " + c_line + ": materials.aorta.c (was '61.163 kPa', now '0.061163 MPa')"),
            std::string::npos)
      << o.output;
  EXPECT_NE(o.output.find("line " + e2_line + " ('output.history[3]'): output.history[3].name (was 'E_z', now not given)"),
            std::string::npos)
      << o.output;
}

TEST_F(RestartFingerprint, AConvergedStepsTargetAndTheMeshAreRefused) {
  Outcome o = restart("target.yaml", replace(original_, "set: {stretch: 0.6 mm}", "set: {stretch: 0.5 mm}"));
  EXPECT_EQ(o.code, 2) << o.output;
  EXPECT_NE(o.output.find("steps[0].set.stretch (was '0.6 mm', now '0.5 mm')"), std::string::npos) << o.output;
  o = restart("radius.yaml", replace(original_, "from: [0.763 mm, 0 mm], to: [0.763 mm, 1 mm]",
                                     "from: [0.8 mm, 0 mm], to: [0.8 mm, 1 mm]"));
  EXPECT_EQ(o.code, 2) << o.output;
  EXPECT_NE(o.output.find("parts.wall.mesh.from[0]"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("parts.wall (its mesh: node positions and elements)"), std::string::npos) << o.output;
  // Values recorded as a digest (a mesh, a node list) say that they changed, not their digests.
  EXPECT_NE(o.output.find("parts.wall (its mesh: node positions and elements) (changed)"), std::string::npos) << o.output;
  EXPECT_EQ(o.output.find("digest"), std::string::npos) << o.output;
  o = restart("added.yaml", replace(original_, "    a4: 0.1067", "    a4: 0.1067\n    a3: 0"));
  EXPECT_EQ(o.code, 2) << o.output;
  EXPECT_NE(o.output.find("line " + std::to_string(line_in(original_, "    a4: 0.1067") + 1) +
                          ": materials.aorta.a3 (not given before, now '0')"),
            std::string::npos)
      << o.output;
}

TEST_F(RestartFingerprint, SolverSettingsAndStepsNotReachedMayChange) {
  // The failing step's increments and solver are changed back: the run continues to the end,
  // and its history is the uninterrupted run's.
  const Outcome o = restart("fixed.yaml", replace(original_, "solver: {residual_tolerance: 1e-10,",
                                                  "solver: {residual_tolerance: 1e-10, max_iterations: 14,"));
  ASSERT_EQ(o.code, 0) << o.output;
  ASSERT_EQ(tunica_cli("run " + kExample + " -q -o " + (dir_ / "full").string(), dir_ / "full.log").code, 0);
  EXPECT_EQ(read_text(out() + "/history.csv"), read_text((dir_ / "full" / "history.csv").string()));
}
