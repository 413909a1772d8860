// Replays every input the fuzzers ever found a bug with (fuzz/regressions/<reader>/)
// and the fuzzing seeds: each must be read or refused with an InputError — no
// other exception, crash or leak (this suite also runs under ASan + UBSan).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "../support/capture.hpp"
#include "fit/inflation_data.hpp"
#include "core/printable.hpp"
#include "mesh/gmsh_reader.hpp"
#include "mesh/meridian_csv.hpp"
#include "output/restart_file.hpp"

namespace fs = std::filesystem;

namespace {
std::vector<fs::path> inputs(const std::string& reader) {
  std::vector<fs::path> out;
  for (const char* kind : {"regressions", "corpus"}) {
    const fs::path dir = fs::path(TUNICA_SOURCE_DIR) / "fuzz" / kind / reader;
    if (fs::exists(dir))
      for (const auto& f : fs::directory_iterator(dir))
        if (f.is_regular_file() && f.path().filename() != ".gitkeep") out.push_back(f.path());
  }
  return out;
}
}  // namespace

TEST(FuzzRegressions, DeckInputsAreReadOrRefusedWithAnInputError) {
  const auto files = inputs("deck");
  EXPECT_GE(files.size(), 2u);
  for (const auto& f : files) {
    try {
      tunica::read_deck_text(tunica::test::read_text(f.string()), f.string());
    } catch (const tunica::InputError&) {
    }
  }
}

TEST(FuzzRegressions, RestartInputsAreReadOrRefusedWithAnInputError) {
  const auto files = inputs("restart");
  EXPECT_GE(files.size(), 1u);
  for (const auto& f : files) {
    try {
      tunica::read_restart(f.string());
    } catch (const tunica::InputError&) {
    }
  }
}

TEST(FuzzRegressions, FitDataInputsAreReadOrRefusedWithAnInputError) {
  const auto files = inputs("fit_data");
  EXPECT_GE(files.size(), 1u);
  for (const auto& f : files) {
    try {
      tunica::read_inflation_data(f.string());
    } catch (const tunica::InputError&) {
    }
  }
}

TEST(FuzzRegressions, MshInputsAreReadOrRefusedWithAnInputError) {
  const auto files = inputs("msh");
  EXPECT_GE(files.size(), 9u);
  for (const auto& f : files) {
    for (const char* view : {"", "fibre"}) {
      try {
        tunica::read_gmsh(f.string(), view);
      } catch (const tunica::InputError& e) {
        const std::string m = e.what();
        EXPECT_TRUE(tunica::is_printable_line(m)) << m;
      }
    }
  }
}

TEST(FuzzRegressions, MeridianCsvInputsAreReadOrRefusedWithAnInputError) {
  const auto files = inputs("meridian_csv");
  EXPECT_GE(files.size(), 2u);
  const tunica::UnitSystem units("mm", "N");
  for (const auto& f : files) {
    try {
      const tunica::Meridian m = tunica::parse_meridian_csv(tunica::test::read_text(f.string()), f.string(), units, 0, 0);
      EXPECT_GE(m.size(), 2u) << f;
    } catch (const tunica::InputError&) {
    }
  }
}
