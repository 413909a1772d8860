// docs/fit.md documents the specimen keys and the synthesis-plan keys with the tables
// generated from their declarations; this test fails when the two drift apart.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "fit/specimen.hpp"
#include "fit/synthetic_data.hpp"

TEST(FitDocs, TablesAreTheGeneratedOnes) {
  std::ifstream in(std::string(TUNICA_SOURCE_DIR) + "/docs/fit.md");
  std::stringstream s;
  s << in.rdbuf();
  const std::string doc = s.str();
  EXPECT_NE(doc.find(tunica::params_markdown(tunica::specimen_spec())), std::string::npos)
      << "docs/fit.md: specimen table is stale; it should read\n"
      << tunica::params_markdown(tunica::specimen_spec());
  EXPECT_NE(doc.find(tunica::params_markdown(tunica::synthesis_plan_spec())), std::string::npos)
      << "docs/fit.md: plan table is stale; it should read\n"
      << tunica::params_markdown(tunica::synthesis_plan_spec());
}
