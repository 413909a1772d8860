// Faults during a run: a run killed with SIGKILL mid-way leaves only complete
// files (every CSV row whole, every VTU/PVD closed, no temporary file), and
// `tunica run --restart DIR` continues it to the same results as an
// uninterrupted run, bit for bit in history.csv. SIGTERM stops a run after the
// current increment with exit code 143. A model with shell parts restarts too.
#include <gtest/gtest.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <thread>

#include "../support/capture.hpp"
#include "../support/cli.hpp"
#include "../support/deck_files.hpp"
#include "../support/scratch.hpp"
#include "../support/shell_decks.hpp"

using namespace tunica::test;
namespace fs = std::filesystem;

namespace {


/// A long run of the balloon example: 300 increments (20 elements, small ParaView frames).
std::string long_deck(const fs::path& dir) {
  const std::string path = (dir / "long.yaml").string();
  std::string text = read_text(std::string(TUNICA_SOURCE_DIR) + "/examples/balloon-sphere.yaml");
  text = replace(replace(text, "increments: 20", "increments: 300"), "elements: 100}", "elements: 20}");
  std::ofstream(path) << replace(text, "output:\n", "output:\n  vtk_segments: 8\n");
  return path;
}

int run(const std::string& args) {
  const int status = std::system((std::string(TUNICA_BINARY) + " " + args + " > /dev/null 2>&1").c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// Starts `tunica run`, waits until history.csv has at least `rows` lines, then sends `sig`.
int start_and_signal(const std::string& deck, const fs::path& out, int rows, int sig) {
  const pid_t pid = fork();
  if (pid == 0) {
    const int devnull = open("/dev/null", O_WRONLY);
    dup2(devnull, 1);
    dup2(devnull, 2);
    execl(TUNICA_BINARY, TUNICA_BINARY, "run", deck.c_str(), "-q", "-o", out.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  for (int k = 0; k < 20000; ++k) {
    std::error_code ec;
    if (fs::exists(out / "history.csv", ec)) {
      const std::string h = read_text((out / "history.csv").string());
      if (std::count(h.begin(), h.end(), '\n') >= rows) break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  kill(pid, sig);
  int status = 0;
  waitpid(pid, &status, 0);
  return status;
}

/// Every result file is complete. A SIGKILL can land while a file is being written: its
/// `<file>.tmp.<pid>` (written, then renamed over the file) stays behind, the file itself is
/// whole, and the restart removes it; `allow_tmp` accepts such leftovers.
void expect_complete_files(const fs::path& out, bool allow_tmp = false) {
  for (const auto& f : fs::recursive_directory_iterator(out)) {
    if (!f.is_regular_file()) continue;
    const std::string name = f.path().filename().string();
    const bool temporary = name.find(".tmp.") != std::string::npos;
    if (allow_tmp && temporary) continue;
    const std::string text = read_text(f.path().string());
    EXPECT_FALSE(temporary) << name;
    if (f.path().extension() == ".csv") {
      std::istringstream in(text);
      std::string line;
      std::getline(in, line);
      const auto fields = std::count(line.begin(), line.end(), ',');
      while (std::getline(in, line)) EXPECT_EQ(std::count(line.begin(), line.end(), ','), fields) << name << ": " << line;
      EXPECT_EQ(text.back(), '\n') << name;
    } else if (f.path().extension() == ".vtu" || f.path().extension() == ".pvd") {
      EXPECT_NE(text.find("</VTKFile>"), std::string::npos) << name;
    }
  }
}

std::vector<std::string> rows_without_timing(const std::string& csv) {
  std::vector<std::string> out;
  std::istringstream in(csv);
  // Drop the last three columns: assembly_s, factor_s, solve_s.
  for (std::string l; std::getline(in, l);) out.push_back(l.substr(0, l.rfind(',', l.rfind(',', l.rfind(',') - 1) - 1)));
  return out;
}

}  // namespace

TEST(Restart, KilledRunLeavesCompleteFilesAndTheRestartReproducesTheUninterruptedRun) {
  const fs::path dir = scratch("restart", "kill");
  const std::string deck = long_deck(dir);
  ASSERT_EQ(run("run " + deck + " -q -o " + (dir / "full").string()), 0);

  const int status = start_and_signal(deck, dir / "killed", 40, SIGKILL);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the run finished before it could be killed";
  expect_complete_files(dir / "killed", /*allow_tmp=*/true);
  const std::string partial = read_text((dir / "killed" / "history.csv").string());
  EXPECT_LT(std::count(partial.begin(), partial.end(), '\n'), 302);

  ASSERT_EQ(run("run " + deck + " -q --restart " + (dir / "killed").string()), 0);
  expect_complete_files(dir / "killed");
  EXPECT_EQ(read_text((dir / "killed" / "history.csv").string()), read_text((dir / "full" / "history.csv").string()));
  EXPECT_EQ(rows_without_timing(read_text((dir / "killed" / "newton.csv").string())),
            rows_without_timing(read_text((dir / "full" / "newton.csv").string())));
  EXPECT_EQ(read_text((dir / "killed" / "surface.pvd").string()), read_text((dir / "full" / "surface.pvd").string()));
  EXPECT_EQ(read_text((dir / "killed" / "vtk" / "surface_000301.vtu").string()),
            read_text((dir / "full" / "vtk" / "surface_000301.vtu").string()));
}

TEST(Restart, SigtermStopsAfterTheCurrentIncrementAndTheRunCanContinue) {
  const fs::path dir = scratch("restart", "term");
  const std::string deck = long_deck(dir);
  const int status = start_and_signal(deck, dir / "out", 20, SIGTERM);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 128 + SIGTERM);
  expect_complete_files(dir / "out");
  EXPECT_EQ(run("run " + deck + " -q --restart " + (dir / "out").string()), 0);
  const std::string h = read_text((dir / "out" / "history.csv").string());
  EXPECT_EQ(std::count(h.begin(), h.end(), '\n'), 302);
}

TEST(Restart, ACompletedRunOrAnotherModelIsRefusedWithTheWayOut) {
  const fs::path dir = scratch("restart", "refuse");
  const std::string example = std::string(TUNICA_SOURCE_DIR) + "/examples/rat-aorta-inflation.yaml";
  const std::string done = (dir / "done").string();
  ASSERT_EQ(run("run " + example + " -q -o " + done), 0);
  // Nothing left to run: add a step, or run afresh.
  Outcome o = run_cli("run " + example + " --restart " + done);
  EXPECT_EQ(o.exit_code, 2) << o.output;
  EXPECT_NE(o.output.find("the run in " + done + " has already completed every step of this deck (the last is step 2 "
                          "'inflation'), so nothing is left to run. To continue it, add a step after step 2 'inflation' "
                          "to `steps` (e.g. `- {name: more, increments: 10, set: {lumen: <its new value>}}`)"),
            std::string::npos)
      << o.output;
  EXPECT_NE(o.output.find("leave out --restart (`tunica run " + example + " -o <new folder>`"), std::string::npos)
      << o.output;
  // Completed, and a key it depends on changed: the key, and a fresh folder for the changed deck.
  const std::string changed = (dir / "changed.yaml").string();
  const std::string changed_text = replace(read_text(example), "a1: 0.68238", "a1: 0.7");
  std::ofstream(changed) << changed_text;
  o = run_cli("run " + changed + " --restart " + done);
  EXPECT_EQ(o.exit_code, 2) << o.output;
  const std::string line = std::to_string(line_of(changed_text, "a1: 0.7"));
  EXPECT_NE(o.output.find(changed + ":" + line + ":"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("line " + line + ": materials.aorta.a1 (was '0.68238', now '0.7')"), std::string::npos)
      << o.output;
  EXPECT_NE(o.output.find("That run has already completed every step of this deck, so a restart could only continue "
                          "it, with the values it had. To run the changed deck, start it in a fresh output folder"),
            std::string::npos)
      << o.output;
  EXPECT_EQ(o.output.find("nothing is left to run"), std::string::npos) << o.output;
  // Another model: which keys differ, and both ways out.
  const std::string other = (dir / "other.yaml").string();
  std::ofstream(other) << replace(read_text(example), "elements: 1}", "elements: 3}");
  o = run_cli("run " + other + " --restart " + done);
  EXPECT_EQ(o.exit_code, 2) << o.output;
  EXPECT_NE(o.output.find("the run in " + done + " is of another model than this deck: it was started with the deck '" +
                          example + "' and has 4 DOFs, 2 boundary condition(s) and 1 load(s), where this deck has 8, 2 "
                          "and 1;"),
            std::string::npos)
      << o.output;
  EXPECT_NE(o.output.find("parts.wall.mesh.elements (was '1', now '3')"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("Run this deck in a fresh output folder (`tunica run " + other + " -o <new folder>`), or "
                          "continue that run with the deck that wrote it (`tunica run " + example + " --restart " +
                          done + "`)."),
            std::string::npos)
      << o.output;
  EXPECT_EQ(run("run " + example + " --restart " + (dir / "nothing-here").string()), 2);
}

// The same for a model with shell parts: the restart file carries the slope unknowns of the
// Kirchhoff–Love shells, the part that enters in step 2 and the contact between shells, and
// the continued run reproduces the uninterrupted one bit for bit in history.csv.
TEST(Restart, AKilledShellRunRestartsToTheUninterruptedResults) {
  const fs::path dir = scratch("restart", "shell");
  const std::string deck = (dir / "shell.yaml").string();
  std::ofstream(deck) << replace(kShellArteryBalloon, "{name: inflate, increments: 8,", "{name: inflate, increments: 400,");
  ASSERT_EQ(run("run " + deck + " -q -o " + (dir / "full").string()), 0);
  const std::string full = read_text((dir / "full" / "history.csv").string());
  ASSERT_EQ(std::count(full.begin(), full.end(), '\n'), 1 + 1 + 2 + 400);  // header, reference state, increments

  const int status = start_and_signal(deck, dir / "killed", 120, SIGKILL);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the run finished before it could be killed";
  expect_complete_files(dir / "killed", /*allow_tmp=*/true);
  const std::string partial = read_text((dir / "killed" / "history.csv").string());
  EXPECT_LT(std::count(partial.begin(), partial.end(), '\n'), 1 + 1 + 2 + 400);
  ASSERT_EQ(run("run " + deck + " -q --restart " + (dir / "killed").string()), 0);
  EXPECT_EQ(read_text((dir / "killed" / "history.csv").string()), full);
  EXPECT_EQ(rows_without_timing(read_text((dir / "killed" / "newton.csv").string())),
            rows_without_timing(read_text((dir / "full" / "newton.csv").string())));
}

TEST(Restart, CheckpointsFollowTheIntervalAndAStopCommitsTheLastIncrement) {
  // checkpoint_every_s: 1000 — within the run's first step only its reference state is checkpointed.
  const fs::path dir = scratch("restart", "interval");
  std::string text = read_text(long_deck(dir));
  const std::string deck = (dir / "sparse.yaml").string();
  std::ofstream(deck) << replace(text, "output:\n", "output:\n  checkpoint_every_s: 1000\n");
  ASSERT_EQ(run("run " + deck + " -q -o " + (dir / "full").string()), 0);
  // Killed: restart.txt still records the reference state (increment 0); the restart cuts the
  // rows written after it and reproduces the uninterrupted run.
  int status = start_and_signal(deck, dir / "killed", 40, SIGKILL);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the run finished before it could be killed";
  const std::string restart = read_text((dir / "killed" / "restart.txt").string());
  EXPECT_NE(restart.find("\nincrement 0\n"), std::string::npos) << restart.substr(0, 300);
  ASSERT_EQ(run("run " + deck + " -q --restart " + (dir / "killed").string()), 0);
  EXPECT_EQ(read_text((dir / "killed" / "history.csv").string()), read_text((dir / "full" / "history.csv").string()));
  // Stopped by SIGTERM: the increment it stopped after is committed, whatever the interval.
  status = start_and_signal(deck, dir / "term", 40, SIGTERM);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 128 + SIGTERM);
  const std::string h = read_text((dir / "term" / "history.csv").string());
  const long rows = std::count(h.begin(), h.end(), '\n') - 2;  // header and reference state
  EXPECT_NE(read_text((dir / "term" / "restart.txt").string()).find("\nincrement " + std::to_string(rows) + "\n"),
            std::string::npos);
}

TEST(Restart, ARunThatStopsOnAFailedIncrementHasAFrameOfItsLastConvergedState) {
  // The balloon pressed past its pressure maximum (about 0.0124 MPa) under pressure control:
  // the run stops with exit 3. With vtk_every: 100 no increment of the step would have a
  // frame; the last converged state gets one, recorded in the checkpoint.
  const fs::path dir = scratch("restart", "limit");
  std::string text = read_text(std::string(TUNICA_SOURCE_DIR) + "/examples/balloon-sphere.yaml");
  text = replace(replace(replace(text, "increments: 20", "increments: 10"), "elements: 100}", "elements: 20}"),
                 "inflation: 0.0118 MPa", "inflation: 0.015 MPa");
  const std::string deck = (dir / "limit.yaml").string();
  std::ofstream(deck) << replace(text, "output:\n", "output:\n  vtk_segments: 8\n  vtk_every: 100\n");
  ASSERT_EQ(run("run " + deck + " -q -o " + (dir / "out").string()), 3);
  const std::string h = read_text((dir / "out" / "history.csv").string());
  const std::string last_row = h.substr(h.rfind('\n', h.size() - 2) + 1);
  const std::string last_time = last_row.substr(0, last_row.find(',', last_row.find(',') + 1) + 1);  // "step,increment,"
  const std::string pvd = read_text((dir / "out" / "surface.pvd").string());
  EXPECT_EQ(std::count(pvd.begin(), pvd.end(), '\n') - 5, 2) << pvd;  // the reference state and the last state
  const std::string time = last_row.substr(last_time.size(), last_row.find(',', last_time.size()) - last_time.size());
  EXPECT_NE(pvd.find("timestep=\"" + time + "\""), std::string::npos) << time << "\n" << pvd;
  EXPECT_TRUE(fs::exists(dir / "out" / "vtk" / "surface_000001.vtu"));
  // The folder is consistent: a restart accepts it (and stops at the same limit point).
  EXPECT_EQ(run("run " + deck + " -q --restart " + (dir / "out").string()), 3);
}

TEST(Restart, ARestartedRunThatStopsAtTheLimitPointGivesTheSameHint) {
  // The balloon pushed past its pressure maximum stops with the hint that names volume control,
  // from the pressure–volume curve of the step's converged increments. Restarted from its last
  // converged increment, the run fails there again and the hint is the same: the restart file
  // keeps what the hint reads of the increments before it.
  const fs::path dir = scratch("restart", "hint");
  std::string text = read_text(std::string(TUNICA_SOURCE_DIR) + "/examples/balloon-sphere.yaml");
  text = replace(replace(replace(text, "increments: 20", "increments: 10"), "elements: 100}", "elements: 20}"),
                 "inflation: 0.0118 MPa", "inflation: 0.015 MPa");
  const std::string deck = (dir / "limit.yaml").string();
  std::ofstream(deck) << replace(text, "output:\n", "output:\n  vtk_segments: 8\n");
  const Outcome first = run_cli("run " + deck + " -q -o " + (dir / "out").string());
  ASSERT_EQ(first.exit_code, 3) << first.output;
  const std::size_t hint = first.output.find("Hint: the pressure–volume curve of load 'inflation' has flattened");
  ASSERT_NE(hint, std::string::npos) << first.output;
  EXPECT_NE(first.output.find("`volume_control: {load: inflation, volume: <enclosed volume>}`"), std::string::npos)
      << first.output;
  const Outcome again = run_cli("run " + deck + " -q --restart " + (dir / "out").string());
  ASSERT_EQ(again.exit_code, 3) << again.output;
  EXPECT_NE(again.output.find(first.output.substr(hint)), std::string::npos) << again.output;
}
