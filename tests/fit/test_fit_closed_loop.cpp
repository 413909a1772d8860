// Closing the loop: the FE solver's own output for the rat aorta (paper §4.1,
// examples/rat-aorta-inflation.yaml, one axisymmetric Fung membrane element) is fitted
// with `tunica fit`, and the deck's constants come back. The history's radius is the
// mid-surface radius, its axial force the end reaction 2π r h σz (open ends), its
// E_z the axial stretch; the specimen is R = 0.763 mm, H = 0.122 mm.
#include <gtest/gtest.h>
#include <unistd.h>
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "fit/inflation_fit.hpp"
#include "fit_test_support.hpp"
#include "io/deck.hpp"

using namespace tunica;
using namespace tunica::fit_test;
namespace fs = std::filesystem;

namespace {

const std::string kSpecimen = "{radius: 0.763 mm, thickness: 0.122 mm, ends: open}";

/// Runs the example deck once (into a temporary directory) and returns its history.csv.
const std::string& fe_history() {
  static const std::string path = [] {
    const fs::path dir = fs::temp_directory_path() / ("tunica-fit-closed-loop-" + std::to_string(getpid()));
    fs::remove_all(dir);
    const std::string cmd = std::string(TUNICA_BINARY) + " run " + TUNICA_SOURCE_DIR +
                            "/examples/rat-aorta-inflation.yaml -q -o " + dir.string() + " 2>&1";
    if (std::system(cmd.c_str()) != 0) throw std::runtime_error("FE run failed: " + cmd);
    return (dir / "history.csv").string();
  }();
  return path;
}

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

// All rows (prestretch at p = 0 with λz from E_z, then inflation at λz = 1.6): the paper's
// constants to 1e-6 (the history carries 12 digits; the FE solution converged to 1e-10).
TEST(FitClosedLoop, PaperConstantsFromTheFeHistory) {
  InflationDataOptions read;
  read.specimen = specimen_node_from_argument(kSpecimen);
  const InflationData data = read_inflation_data(fe_history(), read);
  EXPECT_EQ(data.size, SizeMeasure::mid_radius);
  const FitResult fit = fit_inflation_data(data, FitOptions{});
  const Eigen::VectorXd truth = paper_fung();
  for (int i = 0; i < truth.size(); ++i)
    EXPECT_NEAR(fit.constants(i), truth(i), 1e-6 * truth(i)) << fit.constant_names[i].name;
  EXPECT_GT(fit.r2_pressure, 1 - 1e-12);
  EXPECT_GT(fit.r2_force, 1 - 1e-12);
}

// The same through the command line, with the inflation step only (λz = 1.6 fixed):
// exit 0, and material.yaml is a deck block with the paper's constants.
TEST(FitClosedLoop, CommandLineInflationStepOnly) {
  const fs::path out = fs::temp_directory_path() / ("tunica-fit-closed-loop-cli-" + std::to_string(getpid()));
  fs::remove_all(out);
  const std::string cmd = std::string(TUNICA_BINARY) + " fit " + fe_history() + " --model fung2d --specimen '" +
                          kSpecimen + "' --select step=2 --no-plot -q -o " + out.string() + " 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  const std::string yaml = read_text((out / "material.yaml").string());
  EXPECT_NE(yaml.find("type: fung"), std::string::npos) << yaml;
  for (const char* line : {"c: 61.163 kPa", "a1: 0.68238 ", "a2: 0.60558 ", "a4: 0.1067 "})
    EXPECT_NE(yaml.find(line), std::string::npos) << line << "\n" << yaml;
  for (const char* file : {"report.md", "points.csv", "curves.csv"}) EXPECT_TRUE(fs::exists(out / file)) << file;

  // Pasted over the example deck's `materials:` block, it makes a valid deck.
  std::string deck = read_text(std::string(TUNICA_SOURCE_DIR) + "/examples/rat-aorta-inflation.yaml");
  const auto from = deck.find("materials:"), to = deck.find("parts:");
  ASSERT_TRUE(from != std::string::npos && to != std::string::npos);
  deck = deck.substr(0, from) + yaml + "\n" + deck.substr(to);
  deck.replace(deck.find("material: aorta"), 15, "material: fitted");
  EXPECT_NO_THROW(read_deck_text(deck, "pasted.yaml"));
}
