// A fresh run into a folder that holds a user's own file under a name Tunica writes (history.csv
// that Tunica did not write) leaves it alone and stops before writing, naming it; files an
// earlier Tunica run wrote are removed as before (output/output_folder.hpp).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "../support/capture.hpp"
#include "../support/cli.hpp"
#include "../support/scratch.hpp"

using namespace tunica::test;

TEST(OutputFolderForeign, AUsersOwnHistoryCsvIsKeptAndTheRunRefusesToWriteOverIt) {
  const std::string dir = scratch("output-foreign", "run").string();
  const std::string deck = std::string(TUNICA_SOURCE_DIR) + "/examples/balloon-sphere.yaml";
  std::ofstream(dir + "/history.csv") << "my,own,data\n";
  std::ofstream(dir + "/notes.txt") << "mine\n";
  const Outcome o = run_cli("run " + deck + " -o " + dir + " -q -j 1");
  EXPECT_EQ(o.exit_code, 4) << o.output;
  EXPECT_NE(o.output.find("history.csv' is not a file Tunica wrote"), std::string::npos) << o.output;
  EXPECT_EQ(read_text(dir + "/history.csv"), "my,own,data\n");
  EXPECT_EQ(read_text(dir + "/notes.txt"), "mine\n");
  EXPECT_FALSE(std::filesystem::exists(dir + "/vtk")) << "the refused run leaves the folder as it found it";
  // A folder of an earlier Tunica run is cleared and rewritten.
  std::filesystem::remove(dir + "/history.csv");
  ASSERT_EQ(run_cli("run " + deck + " -o " + dir + " -q -j 1").exit_code, 0);
  const Outcome again = run_cli("run " + deck + " -o " + dir + " -j 1");
  EXPECT_EQ(again.exit_code, 0) << again.output;
  EXPECT_NE(again.output.find("of an earlier Tunica run"), std::string::npos) << again.output;
  EXPECT_EQ(read_text(dir + "/notes.txt"), "mine\n");
}
