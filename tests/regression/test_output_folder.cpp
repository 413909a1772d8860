// The output folder: one run at a time (a second run into a locked folder is
// refused and writes nothing), a fresh run leaves no file of an earlier run,
// `--restart` checks every file it continues from against the manifest in
// restart.txt (a deleted, truncated or changed file is refused by name; a tail
// written after the checkpoint is cut and the continued run matches the
// uninterrupted one bit for bit), and the ParaView frames follow
// output.vtk_every and decode to the same values in every output.vtk_format.
#include <gtest/gtest.h>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>

#include "../support/capture.hpp"
#include "../support/cli.hpp"
#include "../support/scratch.hpp"
#include "../support/vtu.hpp"
#include "model/model.hpp"

using namespace tunica::test;
namespace fs = std::filesystem;

namespace {

const std::string kExample = std::string(TUNICA_SOURCE_DIR) + "/examples/rat-aorta-inflation.yaml";

/// The rat aorta example (1 element, prestretch 6 increments then inflation 20) with a small
/// revolved surface and the given extra output keys; `one_step` keeps the prestretch only.
std::string deck(const fs::path& dir, const std::string& name, const std::string& output_keys, bool one_step = false) {
  std::string text = replace(read_text(kExample), "output:\n", "output:\n  vtk_segments: 8\n" + output_keys);
  if (one_step) {
    const auto at = text.find("  - name: inflation");
    text.erase(at, text.find("\noutput:") + 1 - at);
  }
  const std::string path = (dir / name).string();
  std::ofstream(path) << text;
  return path;
}

std::string run_quiet(const std::string& deck_path, const fs::path& out) {
  return deck_path + " -q -o " + out.string();
}

std::set<std::string> files_in(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& f : fs::recursive_directory_iterator(dir))
    if (f.is_regular_file()) names.insert(fs::relative(f.path(), dir).string());
  return names;
}

void expect_same_files(const fs::path& a, const fs::path& b, const std::vector<std::string>& names) {
  for (const auto& n : names) EXPECT_EQ(read_text((a / n).string()), read_text((b / n).string())) << n;
}

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

void append(const fs::path& file, const std::string& text) { std::ofstream(file, std::ios::app | std::ios::binary) << text; }

/// Overwrites one byte of `file` at `at` (from the end if negative).
void flip_byte(const fs::path& file, long at) {
  std::string text = read_text(file.string());
  const std::size_t k = at >= 0 ? static_cast<std::size_t>(at) : text.size() - static_cast<std::size_t>(-at);
  text[k] = text[k] == '1' ? '2' : '1';
  std::ofstream(file, std::ios::binary) << text;
}

}  // namespace

TEST(OutputFolder, ARunIntoALockedFolderIsRefusedAndWritesNothing) {
  const fs::path dir = scratch("folder", "locked");
  const fs::path out = dir / "out";
  fs::create_directories(out);
  const int fd = open((out / ".tunica.lock").c_str(), O_RDWR | O_CREAT, 0644);
  ASSERT_EQ(flock(fd, LOCK_EX | LOCK_NB), 0);
  const Outcome o = run_cli("run " + run_quiet(deck(dir, "d.yaml", ""), out));
  EXPECT_EQ(o.exit_code, 2) << o.output;
  EXPECT_EQ(o.output, "tunica: input error: " + out.string() + ": another Tunica run is writing into this output folder "
                      "(it holds .tunica.lock); wait for it to end or choose another folder\n");
  EXPECT_EQ(files_in(out), std::set<std::string>{".tunica.lock"});
  const Outcome r = run_cli("run " + deck(dir, "d.yaml", "") + " -q --restart " + out.string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("another Tunica run is writing into this output folder"), std::string::npos) << r.output;
  close(fd);
  EXPECT_EQ(run_cli("run " + run_quiet(deck(dir, "d.yaml", ""), out)).exit_code, 0);
}

TEST(OutputFolder, TwoRunsStartedTogetherIntoOneFolderNeverMix) {
  const fs::path dir = scratch("folder", "together");
  const std::string d = deck(dir, "d.yaml", "", /*one_step=*/true);
  ASSERT_EQ(run_cli("run " + run_quiet(d, dir / "alone")).exit_code, 0);
  const std::set<std::string> alone = files_in(dir / "alone");
  std::vector<std::string> compared;
  for (const auto& f : alone)
    if (f != ".tunica.lock" && f != "newton.csv" && f != "restart.txt" && f != "frames.csv") compared.push_back(f);
  int refused = 0;
  for (int trial = 0; trial < 20; ++trial) {
    const fs::path out = dir / ("trial" + std::to_string(trial));
    pid_t pids[2];
    for (pid_t& pid : pids) {
      pid = fork();
      if (pid == 0) {
        const std::string log = out.string() + "." + std::to_string(getpid()) + ".log";
        const int f = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        dup2(f, 1);
        dup2(f, 2);
        execl(TUNICA_BINARY, TUNICA_BINARY, "run", d.c_str(), "-q", "-o", out.c_str(), static_cast<char*>(nullptr));
        _exit(127);
      }
    }
    for (pid_t pid : pids) {
      int status = 0;
      waitpid(pid, &status, 0);
      ASSERT_TRUE(WIFEXITED(status));
      const std::string log = read_text(out.string() + "." + std::to_string(pid) + ".log");
      if (WEXITSTATUS(status) == 2) {
        ++refused;
        EXPECT_NE(log.find("another Tunica run is writing into this output folder"), std::string::npos) << log;
      } else {
        EXPECT_EQ(WEXITSTATUS(status), 0) << log;
      }
    }
    // Whichever ran, the folder holds one complete run: the files of the run alone, no others.
    EXPECT_EQ(files_in(out), alone) << "trial " << trial;
    expect_same_files(out, dir / "alone", compared);
  }
  EXPECT_GT(refused, 0) << "no trial had the two runs overlap";
}

TEST(OutputFolder, AFreshRunRemovesTheFramesOfAnEarlierRunAndOnlyTunicasFiles) {
  const fs::path dir = scratch("folder", "stale");
  ASSERT_EQ(run_cli("run " + run_quiet(deck(dir, "long.yaml", ""), dir / "out")).exit_code, 0);
  ASSERT_TRUE(fs::exists(dir / "out" / "vtk" / "surface_000026.vtu"));
  std::ofstream(dir / "out" / "notes.txt") << "mine\n";
  std::ofstream(dir / "out" / "vtk" / "mine.vtu") << "mine\n";
  const std::string short_deck = deck(dir, "short.yaml", "", /*one_step=*/true);
  const Outcome o = run_cli("run " + short_deck + " -o " + (dir / "out").string());
  ASSERT_EQ(o.exit_code, 0) << o.output;
  EXPECT_NE(o.output.find("removed the 60 file(s) of an earlier Tunica run in " + (dir / "out").string()), std::string::npos)
      << o.output.substr(0, 400);
  ASSERT_EQ(run_cli("run " + run_quiet(short_deck, dir / "alone")).exit_code, 0);
  std::set<std::string> expected = files_in(dir / "alone");
  expected.insert({"notes.txt", "vtk/mine.vtu"});
  EXPECT_EQ(files_in(dir / "out"), expected);  // frames 0–6 of the short run, none of 7–26
  expect_same_files(dir / "out", dir / "alone", {"history.csv", "surface.pvd", "meridian.pvd", "vtk/surface_000006.vtu"});
}

// A folder stopped at the end of the prestretch (the one-step deck), continued by the
// two-step deck, gives the uninterrupted run's history.csv; damaged, it is refused.
class DamagedFolder : public testing::Test {
protected:
  void SetUp() override {
    dir_ = scratch("folder", testing::UnitTest::GetInstance()->current_test_info()->name());
    full_ = deck(dir_, "full.yaml", "");
    ASSERT_EQ(run_cli("run " + run_quiet(full_, dir_ / "full")).exit_code, 0);
    ASSERT_EQ(run_cli("run " + run_quiet(deck(dir_, "one.yaml", "", true), out())).exit_code, 0);
  }
  fs::path out() const { return dir_ / "out"; }
  Outcome restart() const { return run_cli("run " + full_ + " -q --restart " + out().string()); }
  /// The restart is refused with an input error naming `file`, and `saying` in the message.
  void expect_refused(const std::string& file, const std::string& saying) const {
    const Outcome o = restart();
    EXPECT_EQ(o.exit_code, 2) << o.output;
    EXPECT_NE(o.output.find("tunica: input error: " + (out() / file).string() + ": "), std::string::npos) << o.output;
    EXPECT_NE(o.output.find(saying), std::string::npos) << o.output;
  }
  fs::path dir_;
  std::string full_;
};

TEST_F(DamagedFolder, AnUndamagedFolderContinuesToTheUninterruptedResults) {
  const Outcome o = restart();
  ASSERT_EQ(o.exit_code, 0) << o.output;
  expect_same_files(out(), dir_ / "full", {"history.csv", "surface.pvd", "meridian.pvd", "vtk/surface_000026.vtu"});
}

TEST_F(DamagedFolder, ADeletedFrameIsRefused) {
  fs::remove(out() / "vtk" / "surface_000003.vtu");
  expect_refused("vtk/surface_000003.vtu", "unreadable");
}

TEST_F(DamagedFolder, ATruncatedFrameIsRefused) {
  fs::resize_file(out() / "vtk" / "meridian_000004.vtu", fs::file_size(out() / "vtk" / "meridian_000004.vtu") - 10);
  expect_refused("vtk/meridian_000004.vtu", "truncated");
}

TEST_F(DamagedFolder, AChangedFrameIsRefused) {
  flip_byte(out() / "vtk" / "surface_000002.vtu", 40);
  expect_refused("vtk/surface_000002.vtu", "differ from what the restart file records");
}

TEST_F(DamagedFolder, ATruncatedHistoryIsRefused) {
  fs::resize_file(out() / "history.csv", fs::file_size(out() / "history.csv") - 5);
  expect_refused("history.csv", "fewer than the");
}

TEST_F(DamagedFolder, AChangedHistoryPrefixIsRefused) {
  flip_byte(out() / "history.csv", -20);
  expect_refused("history.csv", "differ from what the restart file records");
}

TEST_F(DamagedFolder, AnEditedRestartFileIsRefused) {
  std::string text = read_text((out() / "restart.txt").string());
  text = replace(text, "reduced_successes 0", "reduced_successes 1");
  std::ofstream(out() / "restart.txt", std::ios::binary) << text;
  expect_refused("restart.txt", "changed after Tunica wrote it");
}

TEST_F(DamagedFolder, ATornTailIsCutAndTheRunContinuesBitForBit) {
  append(out() / "history.csv", "1,7,1.1666,0.5,1.2");  // an increment written after the checkpoint, torn
  append(out() / "newton.csv", "1,7,0,0,1.1");
  append(out() / "frames.csv", "meridian,7,1.1,vtk/meridian_000007.vtu,");
  append(out() / "surface.pvd", "<DataSet timestep=\"1.1\" gr");
  std::ofstream(out() / "vtk" / "surface_000007.vtu") << "<?xml";  // a frame after the checkpoint
  std::ofstream(out() / "history.csv.tmp.99999") << "x";          // a killed run's temporary
  const Outcome o = restart();
  ASSERT_EQ(o.exit_code, 0) << o.output;
  expect_same_files(out(), dir_ / "full",
                    {"history.csv", "surface.pvd", "meridian.pvd", "frames.csv", "vtk/surface_000007.vtu"});
  EXPECT_FALSE(fs::exists(out() / "history.csv.tmp.99999"));
}

TEST(OutputFolder, VtkEveryWritesEveryNthIncrementAndTheEndOfEachStep) {
  const fs::path dir = scratch("folder", "every");
  ASSERT_EQ(run_cli("run " + run_quiet(deck(dir, "d.yaml", "  vtk_every: 4\n"), dir / "out")).exit_code, 0);
  // Reference state; prestretch (6 increments): 4, 6; inflation (20): 4, 8, 12, 16, 20.
  const std::string pvd = read_text((dir / "out" / "surface.pvd").string());
  EXPECT_EQ(count(pvd, "<DataSet "), 8);
  for (const char* t : {"\"0\"", "\"0.666666666667\"", "\"1\"", "\"1.2\"", "\"1.4\"", "\"1.6\"", "\"1.8\"", "\"2\""})
    EXPECT_NE(pvd.find(std::string("timestep=") + t), std::string::npos) << t;
  const auto files = files_in(dir / "out" / "vtk");
  EXPECT_EQ(files.size(), 16u);
  EXPECT_TRUE(files.count("surface_000007.vtu"));
  EXPECT_FALSE(files.count("surface_000008.vtu"));
  const std::string frames = read_text((dir / "out" / "frames.csv").string());
  EXPECT_EQ(count(frames, "\n"), 1 + 16);
}

TEST(OutputFolder, EveryVtkFormatDecodesToTheSameValues) {
  const fs::path dir = scratch("folder", "formats");
  for (const char* f : {"ascii", "binary", "compressed"}) {
    const std::string keys = std::string("  vtk_every: 100\n  vtk_format: ") + f + "\n";
    ASSERT_EQ(run_cli("run " + run_quiet(deck(dir, std::string(f) + ".yaml", keys), dir / f)).exit_code, 0);
  }
  for (const char* series : {"meridian", "surface"}) {
    const std::string file = std::string("vtk/") + series + "_000002.vtu";  // the end of step 2
    const std::string ascii = read_text((dir / "ascii" / file).string());
    const std::string binary = read_text((dir / "binary" / file).string());
    const std::string compressed = read_text((dir / "compressed" / file).string());
    EXPECT_NE(ascii.find("format=\"ascii\""), std::string::npos);
    EXPECT_NE(binary.find("<AppendedData encoding=\"raw\">"), std::string::npos);
    EXPECT_EQ(binary.find("compressor="), std::string::npos);
    EXPECT_NE(compressed.find("compressor=\"vtkZLibDataCompressor\""), std::string::npos);
    if (std::string(series) == "surface") {  // the 1-cell meridian is too small to gain
      EXPECT_LT(compressed.size(), binary.size());
    }
    EXPECT_EQ(decode_array<std::int64_t>(binary, "connectivity"), decode_array<std::int64_t>(ascii, "connectivity"));
    EXPECT_EQ(decode_array<std::int64_t>(compressed, "offsets"), decode_array<std::int64_t>(ascii, "offsets"));
    EXPECT_EQ(decode_array<std::uint8_t>(compressed, "types"), decode_array<std::uint8_t>(ascii, "types"));
    int arrays = 0;
    for (std::size_t at = ascii.find("type=\"Float64\" Name=\""); at != std::string::npos;
         at = ascii.find("type=\"Float64\" Name=\"", at + 1)) {
      const auto begin = at + std::strlen("type=\"Float64\" Name=\"");
      const std::string name = ascii.substr(begin, ascii.find('"', begin) - begin);
      const auto a = decode_float64(ascii, name), b = decode_float64(binary, name), c = decode_float64(compressed, name);
      ASSERT_FALSE(a.empty()) << name;
      ASSERT_EQ(a.size(), b.size()) << name;
      ASSERT_EQ(a.size(), c.size()) << name;
      for (std::size_t i = 0; i < a.size(); ++i) {
        if (std::isnan(a[i])) {
          EXPECT_TRUE(std::isnan(b[i]) && std::isnan(c[i])) << name << " " << i;
          continue;
        }
        EXPECT_EQ(a[i], b[i]) << name << " " << i;  // 17 significant digits read back exactly
        EXPECT_EQ(a[i], c[i]) << name << " " << i;
      }
      ++arrays;
    }
    EXPECT_GE(arrays, 20) << series;
  }
}

namespace {
/// The names of a frame's Float64 arrays (Points excluded), in file order.
std::vector<std::string> float_arrays(const std::string& vtu) {
  std::vector<std::string> names;
  const std::string key = "type=\"Float64\" Name=\"";
  for (auto at = vtu.find(key); at != std::string::npos; at = vtu.find(key, at + 1)) {
    const auto begin = at + key.size();
    const std::string name = vtu.substr(begin, vtu.find('"', begin) - begin);
    if (name != "Points") names.push_back(name);
  }
  return names;
}
}  // namespace

TEST(OutputFolder, VtkFieldsSelectTheArraysOfEachFrame) {
  const fs::path dir = scratch("folder", "fields");
  // Every array the writer writes is a name of vtk_field_names with its unit suffix (and the
  // contact pressure, which only models with contact have): the list the deck checks against.
  ASSERT_EQ(run_cli("run " + run_quiet(deck(dir, "all.yaml", "  vtk_every: 100\n"), dir / "all")).exit_code, 0);
  const std::vector<std::string> all = float_arrays(read_text((dir / "all" / "vtk/surface_000002.vtu").string()));
  const std::vector<std::string> expected = {
      "displacement", "lambda_hoop", "lambda_meridional", "lambda_thickness", "S_hoop_N_per_mm2",
      "S_meridional_N_per_mm2", "sigma_hoop_N_per_mm2", "sigma_meridional_N_per_mm2", "thickness_mm", "part",
      "sigma_rr_N_per_mm2", "sigma_thetatheta_N_per_mm2", "sigma_zz_N_per_mm2", "sigma_rz_N_per_mm2",
      "hydrostatic_pressure_N_per_mm2", "J", "M_hoop_N", "M_meridional_N", "sigma_hoop_outer_N_per_mm2",
      "sigma_hoop_inner_N_per_mm2", "sigma_meridional_outer_N_per_mm2", "sigma_meridional_inner_N_per_mm2"};
  EXPECT_EQ(all, expected);
  // A selection: only those arrays, with the same values.
  ASSERT_EQ(run_cli("run " + run_quiet(deck(dir, "some.yaml", "  vtk_every: 100\n  vtk_fields: [thickness, sigma_hoop]\n"),
                                       dir / "some"))
                .exit_code,
            0);
  for (const char* series : {"meridian", "surface"}) {
    const std::string file = std::string("vtk/") + series + "_000002.vtu";
    const std::string some = read_text((dir / "some" / file).string());
    EXPECT_EQ(float_arrays(some), (std::vector<std::string>{"sigma_hoop_N_per_mm2", "thickness_mm"})) << series;
    const std::string full = read_text((dir / "all" / file).string());
    EXPECT_EQ(decode_float64(some, "thickness_mm"), decode_float64(full, "thickness_mm")) << series;
    EXPECT_EQ(some.find("Vectors=\"displacement\""), std::string::npos) << series;
    EXPECT_LT(some.size(), full.size()) << series;
  }
  // A name that is not an array: the key, the name and the names there are.
  const Outcome bad = run_cli("check " + deck(dir, "bad.yaml", "  vtk_fields: [displacement, sigma_max]\n"));
  EXPECT_EQ(bad.exit_code, 2) << bad.output;
  EXPECT_NE(bad.output.find("output.vtk_fields"), std::string::npos) << bad.output;
  EXPECT_NE(bad.output.find("'sigma_max' is not an array of an axisymmetric model's frames"), std::string::npos) << bad.output;
  EXPECT_NE(bad.output.find("sigma_meridional_inner"), std::string::npos) << bad.output;
  const Outcome misspelt = run_cli("check " + deck(dir, "misspelt.yaml", "  vtk_fields: [thicknes]\n"));
  EXPECT_EQ(misspelt.exit_code, 2) << misspelt.output;
  EXPECT_NE(misspelt.output.find("did you mean 'thickness'?"), std::string::npos) << misspelt.output;
  const Outcome suffixed = run_cli("check " + deck(dir, "suffixed.yaml", "  vtk_fields: [sigma_hoop_N_per_mm2]\n"));
  EXPECT_EQ(suffixed.exit_code, 2) << suffixed.output;
  EXPECT_NE(suffixed.output.find("write the name without its unit suffix, 'sigma_hoop'"), std::string::npos)
      << suffixed.output;
  const Outcome contact = run_cli("check " + deck(dir, "contact.yaml", "  vtk_fields: [contact_pressure]\n"));
  EXPECT_EQ(contact.exit_code, 2) << contact.output;
  EXPECT_NE(contact.output.find("only for models with contact pairs"), std::string::npos) << contact.output;
  const Outcome twice = run_cli("check " + deck(dir, "twice.yaml", "  vtk_fields: [J, J]\n"));
  EXPECT_EQ(twice.exit_code, 2) << twice.output;
  EXPECT_NE(twice.output.find("'J' is listed twice"), std::string::npos) << twice.output;
}

TEST(OutputFolder, VtkFieldsOfA3dModelAndTheUserGuidesList) {
  const fs::path dir = scratch("folder", "fields3d");
  std::string text = read_text(std::string(TUNICA_SOURCE_DIR) + "/examples/balloon-sphere-3d.yaml");
  ASSERT_NE(text.find("output:\n"), std::string::npos);
  const std::string all_deck = (dir / "all.yaml").string(), some_deck = (dir / "some.yaml").string();
  std::ofstream(all_deck) << replace(text, "output:\n", "output:\n  vtk_every: 1000\n");
  std::ofstream(some_deck) << replace(text, "output:\n", "output:\n  vtk_every: 1000\n  vtk_fields: [sigma_max, direction_1]\n");
  ASSERT_EQ(run_cli("run " + run_quiet(all_deck, dir / "all")).exit_code, 0);
  ASSERT_EQ(run_cli("run " + run_quiet(some_deck, dir / "some")).exit_code, 0);
  const std::string full = read_text((dir / "all" / "vtk/surface_000001.vtu").string());
  const std::string some = read_text((dir / "some" / "vtk/surface_000001.vtu").string());
  EXPECT_EQ(float_arrays(full),
            (std::vector<std::string>{"displacement", "lambda_1", "lambda_2", "lambda_3", "E_1", "E_2", "E_12",
                                      "S_1_N_per_mm2", "S_2_N_per_mm2", "S_12_N_per_mm2", "sigma_1_N_per_mm2",
                                      "sigma_2_N_per_mm2", "sigma_max_N_per_mm2", "sigma_min_N_per_mm2", "thickness_mm",
                                      "part", "direction_1", "direction_2", "cauchy_stress_N_per_mm2", "compressed"}));
  EXPECT_EQ(float_arrays(some), (std::vector<std::string>{"sigma_max_N_per_mm2", "direction_1"}));
  EXPECT_EQ(decode_float64(some, "sigma_max_N_per_mm2"), decode_float64(full, "sigma_max_N_per_mm2"));
  // The names the deck accepts are the ones the user guide lists.
  const std::string guide = read_text(std::string(TUNICA_SOURCE_DIR) + "/docs/user-guide.md");
  const auto at = guide.find("`output.vtk_fields` selects");
  ASSERT_NE(at, std::string::npos);
  const std::string paragraph = guide.substr(at, guide.find("\n\n", at) - at);
  for (auto g : {tunica::Geometry::axisymmetric, tunica::Geometry::three_d})
    for (const auto& name : tunica::vtk_field_names(g))
      EXPECT_NE(paragraph.find("`" + name + "`"), std::string::npos) << name << " is not in the user guide's list";
}

TEST(OutputFolder, WithoutFramesThereIsNoVtkFolder) {
  const fs::path dir = scratch("folder", "no-vtk");
  ASSERT_EQ(run_cli("run " + run_quiet(deck(dir, "d.yaml", "  vtk: false\n", /*one_step=*/true), dir / "out")).exit_code, 0);
  EXPECT_TRUE(fs::exists(dir / "out" / "history.csv"));
  EXPECT_FALSE(fs::exists(dir / "out" / "vtk"));
  EXPECT_FALSE(fs::exists(dir / "out" / "surface.pvd"));
}
