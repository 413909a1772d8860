// Resource limits: absurd sizes are refused with a clear message before
// anything large is allocated — a generator asked for 10¹² elements, parts
// that together exceed the node limit, a step with 10¹² increments, a deeply
// nested deck, an oversized deck, a restart file announcing more values than
// it holds.
#include <gtest/gtest.h>

#include "../support/capture.hpp"
#include "io/deck_limits.hpp"
#include "output/restart_file.hpp"

using namespace tunica;
using namespace tunica::test;

namespace {

const std::string kExample = std::string(TUNICA_SOURCE_DIR) + "/examples/rat-aorta-inflation.yaml";

std::string error_of(const std::string& text) {
  try {
    read_deck_text(text, "limits.yaml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST(ResourceLimits, GeneratorAskedForTenToTheTwelveElements) {
  const std::string e = error_of(replace(read_text(kExample), "elements: 1}", "elements: 1000000000000}"));
  EXPECT_NE(e.find("limits.yaml:21:"), std::string::npos) << e;
  EXPECT_NE(e.find("key 'parts.wall.mesh.elements': value 1000000000000 is out of range (must be >= 1, <= 1e+07)"),
            std::string::npos)
      << e;
}

TEST(ResourceLimits, PartsTogetherAboveTheNodeLimit) {
  std::string text = replace(read_text(kExample), "elements: 1}", "elements: 6000000}");
  text = replace(text, "parts:\n", "parts:\n  sleeve: {element: axisymmetric_membrane, material: aorta, thickness: 0.1,\n"
                                   "           mesh: {type: line, from: [1, 0], to: [1, 1], elements: 6000000}}\n");
  const std::string e = error_of(text);
  EXPECT_NE(e.find("the model would have more than 10000000 nodes"), std::string::npos) << e;
}

TEST(ResourceLimits, StepWithTenToTheTwelveIncrements) {
  const std::string e = error_of(replace(read_text(kExample), "increments: 20", "increments: 1000000000000"));
  EXPECT_NE(e.find("key 'steps[1].increments': value 1000000000000 is out of range (must be >= 1, <= 1e+06)"), std::string::npos)
      << e;
}

TEST(ResourceLimits, DeeplyNestedDeck) {
  const std::string flow = "title: x\nunits: " + std::string(100000, '[') + std::string(100000, ']') + "\n";
  EXPECT_NE(error_of(flow).find("limits.yaml:2:71: maps and lists nest deeper than 64 levels"), std::string::npos)
      << error_of(flow);
  std::string block;
  for (int i = 0; i < 100; ++i) block += std::string(i, ' ') + "k:\n";
  EXPECT_NE(error_of(block).find("limits.yaml:65:65: maps and lists nest deeper than 64 levels"), std::string::npos)
      << error_of(block);
  EXPECT_NE(error_of("a:\n" + std::string(200, ' ').replace(0, 0, "") + "- " + [] {
              std::string s;
              for (int i = 0; i < 70; ++i) s += "- ";
              return s + "x\n";
            }())
                .find("nest deeper than 64 levels"),
            std::string::npos);
  // Real decks are far from the limit.
  EXPECT_NO_THROW(check_deck_limits(read_text(kExample), "example"));
}

TEST(ResourceLimits, OversizedDeck) {
  const std::string e = error_of("title: '" + std::string(17u << 20, 'x') + "'\n");
  EXPECT_NE(e.find("limits.yaml: the deck is 17825802 bytes, more than the 16 MiB a deck may have"), std::string::npos) << e;
}

TEST(ResourceLimits, RestartFileAnnouncingMoreValuesThanItHolds) {
  const std::string path = testing::TempDir() + "/announcing-restart.txt";
  std::ofstream(path) << "tunica-restart 3\ndeck d.yaml\nstep 0\nfraction 0x0p+0\ndt 0x0p+0\nincrement 0\n"
                         "reduced_successes 0\nhistory_rows 1\nnewton_rows 0\nframes 1\nfiles 0\n"
                         "step_start_boundary 0\nstep_start_pressure 0\nstep_start_volume 0\nboundary 0\npressure 0\nvolume 0\n"
                         "u 99999999 0x0p+0\n";
  try {
    read_restart(path);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(path + ":18: malformed restart file: 'u' announces 99999999 values and holds 1"),
              std::string::npos)
        << e.what();
  }
  std::ofstream(path) << "tunica-restart 3\ndeck d.yaml\nstep 0\nfraction 0x0p+0\ndt 0x0p+0\nincrement 0\n"
                         "reduced_successes 0\nhistory_rows 1\nnewton_rows 0\nframes 1000000000000\n";
  try {
    read_restart(path);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(":10: malformed restart file: not a count in [0, 100000000]: '1000000000000'"),
              std::string::npos)
        << e.what();
  }
}
