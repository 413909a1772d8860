// A run whose progress output goes to a pipe that closes (`tunica run … | head -1`) finishes its
// steps and exits 0: the progress lines after the close are dropped, the results are all written.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "../support/capture.hpp"
#include "../support/scratch.hpp"

using namespace tunica::test;

TEST(ClosedOutputPipe, TheRunFinishesAndExitsZero) {
  const std::string dir = scratch("closed-pipe", "run").string();
  const std::string deck = std::string(TUNICA_SOURCE_DIR) + "/examples/balloon-sphere.yaml";
  FILE* p = popen((std::string(TUNICA_BINARY) + " run " + deck + " -o " + dir + " -j 1").c_str(), "r");
  ASSERT_NE(p, nullptr);
  char line[512];
  ASSERT_NE(std::fgets(line, sizeof line, p), nullptr);
  const int status = pclose(p);  // the reader leaves after one line
  ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << WTERMSIG(status);
  EXPECT_EQ(WEXITSTATUS(status), 0);
  std::ifstream history(dir + "/history.csv");
  std::string row, last;
  int rows = 0;
  while (std::getline(history, row)) {
    last = row;
    ++rows;
  }
  EXPECT_EQ(rows, 22) << last;  // the header, the reference state and the step's 20 increments
  EXPECT_EQ(last.rfind("1,20,", 0), 0u) << last;
}
