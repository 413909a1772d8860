// Increment control: an increment too large for Newton is cut back and the
// step still reaches the same state; a load beyond what the structure can
// carry (a balloon above its pressure maximum, under pressure control) stops
// the run cleanly with exit code 3, a message naming step, increment and
// residual, and every converged increment kept in complete files.
#include <gtest/gtest.h>
#include <unistd.h>
#include <sys/wait.h>

#include <fmt/format.h>

#include <filesystem>

#include "../support/capture.hpp"

using namespace tunica;
using namespace tunica::test;
namespace fs = std::filesystem;

TEST(IncrementControl, CutBacksRecoverAndReachTheSameState) {
  const std::string path = std::string(TUNICA_SOURCE_DIR) + "/examples/rat-aorta-inflation.yaml";
  const std::string text = read_text(path);
  const Model coarse = read_deck_text(replace(text, "increments: 20", "increments: 1\n    solver: {max_iterations: 5}"), path);
  const Model fine = read_deck_text(text, path);
  Capture c1, c2;
  Analysis a1(coarse), a2(fine);
  a1.run(c1);
  a2.run(c2);
  EXPECT_GT(c1.cutbacks, 0);
  EXPECT_EQ(c1.rows.back().info.fraction, 1.0);
  for (std::size_t k = 0; k < c1.rows.back().values.size(); ++k)
    EXPECT_NEAR(c1.rows.back().values[k], c2.rows.back().values[k], 1e-9 * std::max(1.0, std::abs(c2.rows.back().values[k])))
        << coarse.output.history[k].column;
}

namespace {
void expect_clean_stop_beyond_the_maximum(int max_cutbacks);
}

TEST(IncrementControl, ALoadBeyondTheMaximumStopsCleanlyAndKeepsConvergedIncrements) {
  expect_clean_stop_beyond_the_maximum(3);
}

TEST(IncrementControl, ManyAllowedCutBacksStillStop) {
  // Halvings carried over from earlier increments count too: the increment never falls
  // below nominal / 2^max_cutbacks, so time advances and the run ends.
  expect_clean_stop_beyond_the_maximum(20);
}

namespace {
void expect_clean_stop_beyond_the_maximum(int max_cutbacks) {
  const std::string src = std::string(TUNICA_SOURCE_DIR) + "/examples/balloon-sphere.yaml";
  const fs::path dir = fs::temp_directory_path() / ("tunica-increment-control-" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string deck = (dir / "over.yaml").string();
  // p_max = 2μ(H/R)(7^(−1/6) − 7^(−7/6)) ≈ 0.012395 MPa; ask for 0.0135 MPa.
  std::ofstream(deck) << replace(replace(read_text(src), "{inflation: 0.0118 MPa}", "{inflation: 0.0135 MPa}"), "increments: 20",
                                 "increments: 10\n    solver: {max_cutbacks: " + std::to_string(max_cutbacks) + "}");
  const std::string cmd = std::string(TUNICA_BINARY) + " run " + deck + " -q -o " + (dir / "out").string() + " 2>&1";
  FILE* p = popen(cmd.c_str(), "r");
  std::string out;
  char buf[4096];
  while (std::size_t n = std::fread(buf, 1, sizeof buf, p)) out.append(buf, n);
  const int status = pclose(p);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 3) << out;
  EXPECT_NE(out.find("the run stopped: step 1 'inflate', increment"), std::string::npos) << out;
  // fmt::format, not "(" + std::to_string(...): GCC 12 warns falsely on that (-Wrestrict, GCC bug 105651).
  EXPECT_NE(out.find(fmt::format("({} cut-back(s) allowed)", max_cutbacks)), std::string::npos) << out;
  EXPECT_NE(out.find("relative residual"), std::string::npos) << out;
  // history.csv: complete rows only, pressures rising and below the maximum.
  std::istringstream h(read_text((dir / "out" / "history.csv").string()));
  std::string line;
  std::getline(h, line);
  const auto fields = std::count(line.begin(), line.end(), ',');
  int rows = 0;
  double last_p = -1;
  const double p_max = 2 * 1.0 * 0.01 * (std::pow(7.0, -1.0 / 6) - std::pow(7.0, -7.0 / 6)) * 1e3;  // kPa
  while (std::getline(h, line)) {
    EXPECT_EQ(std::count(line.begin(), line.end(), ','), fields) << line;
    const double pk = std::stod(line.substr(line.find(',', line.find(',', line.find(',') + 1) + 1) + 1));
    EXPECT_GT(pk, last_p);
    EXPECT_LT(pk, p_max * (1 + 2e-4));  // the discrete model's maximum is within its mesh error (7e-5)
    last_p = pk;
    ++rows;
  }
  EXPECT_GT(rows, 9);
  EXPECT_LT(rows, 10 + 3 * max_cutbacks);  // a bounded number of reduced increments
  EXPECT_GT(last_p, 0.99 * p_max);  // it got close to the maximum before stopping
  EXPECT_TRUE(fs::exists(dir / "out" / "surface.pvd"));
  for (const auto& f : fs::directory_iterator(dir / "out")) EXPECT_NE(f.path().extension(), ".tmp");
  // newton.csv also holds the failed attempts of the increment that stopped the run.
  const std::string newton = read_text((dir / "out" / "newton.csv").string());
  std::istringstream hist(read_text((dir / "out" / "history.csv").string()));
  std::string l, last;
  while (std::getline(hist, l)) last = l;
  const int last_increment = std::stoi(last.substr(2, last.find(',', 2) - 2));
  EXPECT_NE(newton.find("\n1," + std::to_string(last_increment + 1) + ","), std::string::npos)
      << "no row of the failed increment " << last_increment + 1;
}
}  // namespace

TEST(IncrementControl, NoCutBackAllowedIsSaidSo) {
  // Issue #17 C3: with `max_cutbacks: 0` nothing is cut back, and the message says so instead of
  // "cut back to 0.5 of the step (0 cut-back(s) allowed)".
  const std::string src = std::string(TUNICA_SOURCE_DIR) + "/examples/balloon-sphere.yaml";
  const fs::path dir = fs::temp_directory_path() / ("tunica-no-cutback-" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string deck = (dir / "over.yaml").string();
  std::ofstream(deck) << replace(replace(read_text(src), "{inflation: 0.0118 MPa}", "{inflation: 0.0135 MPa}"),
                                 "increments: 20", "increments: 2\n    solver: {max_cutbacks: 0}");
  const std::string cmd = std::string(TUNICA_BINARY) + " run " + deck + " -q -o " + (dir / "out").string() + " 2>&1";
  FILE* p = popen(cmd.c_str(), "r");
  std::string out;
  char buf[4096];
  while (std::size_t n = std::fread(buf, 1, sizeof buf, p)) out.append(buf, n);
  const int status = pclose(p);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 3) << out;
  EXPECT_NE(out.find("no convergence with the step's increment of 0.5 of the step (`max_cutbacks: 0` in `solver` "
                     "allows no cut-back"),
            std::string::npos)
      << out;
  EXPECT_EQ(out.find("cut back to"), std::string::npos) << out;
  EXPECT_EQ(out.find("0 cut-back(s) allowed"), std::string::npos) << out;
  fs::remove_all(dir);
}
