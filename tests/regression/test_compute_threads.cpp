// `tunica run -j N` computes on N threads at most, whichever library does the computing: the
// element loops (OpenMP), CHOLMOD's own OpenMP loops and the BLAS under the factorizations
// (linalg/compute_threads.hpp). The run is the built binary, as a child process, on a 10k-element
// tube whose CHOLMOD factorizations dominate the run; the test samples /proc/<pid>/task every
// 2 ms while it runs. And the results of -j 1 and -j 2 are the same bit for bit, the BLAS's
// rounding included (the restart file holds the displacements in hexadecimal floating point).
#include <fcntl.h>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "../support/capture.hpp"
#include "../support/fung_tube.hpp"

using namespace tunica::test;
namespace fs = std::filesystem;

namespace {

fs::path scratch(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / fmt::format("tunica-threads-{}", getpid()) / name;
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

/// The benchmark's tube at 72 × 72 split quads (10,368 elements, 15,476 unknowns), 4 prestretch
/// and 2 inflation increments: 30-odd CHOLMOD factorizations, about a second on one thread.
std::string tube_deck(const fs::path& dir) {
  const std::string path = (dir / "tube.yaml").string();
  std::ofstream(path) << fung_tube_deck(72, "", 2);
  return path;
}

/// A thread's CPU time so far in ns (the first field of /proc/<pid>/task/<tid>/schedstat), -1 if
/// the thread has gone.
long long cpu_ns(const fs::path& task) {
  std::ifstream in(task / "schedstat");
  long long ns = -1;
  in >> ns;
  return in ? ns : -1;
}

struct Sampled {
  int exit_code = -1;
  int samples = 0;       ///< samples taken while the run was computing
  int most = 0;          ///< the most compute threads in one sample
  std::string at_most;   ///< those threads and their CPU time, for the failure message
};

/// Runs `tunica run DECK -q -j n -o out` and samples its threads every 2 ms from the moment it
/// creates newton.csv (the model is read and the analysis starts) until it exits.
///
/// A compute thread, in one sample, is a thread of the process that exists and has run: its CPU
/// time is above zero. A pool's worker thus counts from its first job until it ends, whether it
/// computes or waits at that instant (a worker that waits may compute again at any moment); a
/// thread that was created and never ran does not count. The samples start once the run writes
/// newton.csv, after the start-up: `tunica` executes itself once more with its thread settings in
/// the environment (linalg/compute_threads.hpp), and the first image's threads end with it.
/// With `marker`, the child starts with TUNICA_THREADS=n in its environment and nothing else of
/// the thread settings, as a wrapper script may leave it.
Sampled run_sampled(const std::string& deck, const fs::path& out, int n, bool marker = false) {
  const std::string threads = std::to_string(n);
  const pid_t pid = fork();
  if (pid == 0) {
    if (marker) {
      setenv("TUNICA_THREADS", threads.c_str(), 1);
      for (const char* v : {"OMP_NUM_THREADS", "OMP_THREAD_LIMIT", "OPENBLAS_NUM_THREADS"}) unsetenv(v);
    }
    const int devnull = open("/dev/null", O_WRONLY);
    dup2(devnull, 1);
    dup2(devnull, 2);
    execl(TUNICA_BINARY, TUNICA_BINARY, "run", deck.c_str(), "-q", "-j", threads.c_str(), "-o", out.c_str(),
          static_cast<char*>(nullptr));
    _exit(127);
  }
  Sampled s;
  const fs::path tasks = fs::path("/proc") / std::to_string(pid) / "task";
  for (;;) {
    int status = 0;
    if (waitpid(pid, &status, WNOHANG) == pid) {
      s.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
      break;
    }
    std::error_code ec;
    if (fs::exists(out / "newton.csv", ec)) {
      int computing = 0;
      std::ostringstream list;
      for (const auto& task : fs::directory_iterator(tasks, ec)) {
        const long long ns = cpu_ns(task.path());
        if (ns > 0) {
          ++computing;
          list << " thread " << task.path().filename().string() << " (" << ns / 1000 << " µs)";
        }
      }
      ++s.samples;
      if (computing > s.most) {
        s.most = computing;
        s.at_most = list.str();
      }
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  return s;
}

/// The rows of a CSV file without the named columns.
std::vector<std::string> rows_without(const std::string& text, const std::vector<std::string>& drop) {
  std::istringstream in(text);
  std::string line;
  std::vector<bool> keep;
  std::vector<std::string> out;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::istringstream fields(line);
    for (std::string c; std::getline(fields, c, ',');) cells.push_back(c);
    if (keep.empty())
      for (const auto& c : cells) keep.push_back(std::find(drop.begin(), drop.end(), c) == drop.end());
    std::string row;
    for (std::size_t k = 0; k < cells.size(); ++k)
      if (k >= keep.size() || keep[k]) row += cells[k] + ",";
    out.push_back(row);
  }
  return out;
}

/// The lines of restart.txt that hold the converged state (u, volumes, loads), in hexadecimal.
std::vector<std::string> state_lines(const fs::path& out) {
  std::istringstream in(read_text((out / "restart.txt").string()));
  std::vector<std::string> lines;
  for (std::string l; std::getline(in, l);)
    if (l.rfind("file ", 0) != 0 && l.rfind("checksum ", 0) != 0) lines.push_back(l);
  return lines;
}

}  // namespace

TEST(ComputeThreads, ARunComputesOnNoMoreThreadsThanItsCount) {
  const fs::path dir = scratch("count");
  const std::string deck = tube_deck(dir);
  for (const int n : {1, 2}) {
    const Sampled s = run_sampled(deck, dir / fmt::format("j{}", n), n);
    ASSERT_EQ(s.exit_code, 0) << "-j " << n;
    ASSERT_GT(s.samples, 10) << "-j " << n << ": the run ended before it could be observed";
    // Not more than n; and n, not fewer: the element loops do use the threads they are given.
    EXPECT_EQ(s.most, n) << "-j " << n << ": " << s.samples << " samples, the most compute threads in one:"
                         << s.at_most;
    // TUNICA_THREADS left in the environment without the settings it marks: still n.
    const Sampled m = run_sampled(deck, dir / fmt::format("marker{}", n), n, true);
    ASSERT_EQ(m.exit_code, 0) << "-j " << n << ", TUNICA_THREADS preset";
    ASSERT_GT(m.samples, 10) << "-j " << n << ", TUNICA_THREADS preset: the run ended before it could be observed";
    EXPECT_LE(m.most, n) << "-j " << n << ", TUNICA_THREADS preset: " << m.samples
                         << " samples, the most compute threads in one:" << m.at_most;
  }
}

TEST(ComputeThreads, ResultsAreIdenticalBitForBitWithOneAndTwoThreads) {
  const fs::path dir = scratch("bits");
  const std::string deck = tube_deck(dir);
  for (const char* j : {"1", "2"}) {
    const std::string out = (dir / fmt::format("j{}", j)).string();
    const int status = std::system((std::string(TUNICA_BINARY) + " run " + deck + " -q -j " + j + " -o " + out +
                                    " > /dev/null 2>&1").c_str());
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "-j " << j;
  }
  EXPECT_EQ(state_lines(dir / "j1"), state_lines(dir / "j2"));
  EXPECT_EQ(read_text((dir / "j1" / "history.csv").string()), read_text((dir / "j2" / "history.csv").string()));
  const std::vector<std::string> varying = {"threads", "assembly_s", "factor_s", "solve_s"};
  EXPECT_EQ(rows_without(read_text((dir / "j1" / "newton.csv").string()), varying),
            rows_without(read_text((dir / "j2" / "newton.csv").string()), varying));
  // Each row of newton.csv says how many threads computed it.
  for (const char* j : {"1", "2"}) {
    const auto all = rows_without(read_text((dir / fmt::format("j{}", j) / "newton.csv").string()), {});
    const auto without = rows_without(read_text((dir / fmt::format("j{}", j) / "newton.csv").string()),
                                      {"step", "increment", "attempt", "iteration", "time", "residual", "relative_residual",
                                       "energy", "relative_energy", "backtracks", "active_contacts", "active_changes",
                                       "solver", "assembly_s", "factor_s", "solve_s"});
    ASSERT_GT(all.size(), 30u);
    EXPECT_EQ(without[0], "threads,");
    for (std::size_t r = 1; r < without.size(); ++r) EXPECT_EQ(without[r], std::string(j) + ",") << all[r];
  }
}
