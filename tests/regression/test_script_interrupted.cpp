// A Gmsh script meshed by `tunica check --allow-scripts` (mesh/geo_mesher.hpp): SIGTERM or
// SIGINT while Gmsh runs ends the check at once with a message and exit 128 + signal, and
// leaves no temporary folder; the folder of a check killed outright (SIGKILL) is removed by the
// next meshing, and that of a meshing still running is not.
#include <gtest/gtest.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <thread>
#include <vector>

#include "../support/capture.hpp"
#include "../support/scratch.hpp"

using namespace tunica::test;
namespace fs = std::filesystem;

namespace {

/// An empty folder, with `tmp/` as the checks' TMPDIR.
fs::path folder(const std::string& name) {
  const fs::path d = scratch("script-interrupted", name);
  fs::create_directories(d / "tmp");
  return d;
}

/// A quarter cylinder (physical surface `wall`, curves `bottom`, `top`) and a deck meshing it;
/// `before`: script text run first (a command that keeps Gmsh busy).
std::string write_deck(const fs::path& dir, const std::string& before) {
  std::ofstream(dir / "wall.geo") << before
                                  << "lc = 0.25;\n"
                                     "Point(1) = {0, 0, 0, lc}; Point(2) = {1, 0, 0, lc}; Point(3) = {0, 1, 0, lc};\n"
                                     "Circle(1) = {2, 1, 3};\n"
                                     "out[] = Extrude {0, 0, 3} { Curve{1}; };\n"
                                     "Physical Surface(\"wall\") = {out[1]};\n"
                                     "Physical Curve(\"bottom\") = {1};\n";
  std::ofstream(dir / "deck.yaml") << "units: {length: mm, force: N}\n"
                                      "materials:\n  rubber: {type: neo_hookean, mu: 1 MPa}\n"
                                      "parts:\n  wall:\n    element: membrane\n    material: rubber\n"
                                      "    thickness: 0.1 mm\n    mesh: {type: gmsh, file: wall.geo, surface: wall}\n"
                                      "boundary:\n  fixed: {node_set: bottom, dofs: [x, y, z]}\n"
                                      "loads:\n  p: {type: pressure, part: wall}\n"
                                      "steps:\n  - {increments: 1, set: {p: 1 kPa}}\n";
  return (dir / "deck.yaml").string();
}

/// The temporary folders of meshings in `tmp`.
std::vector<fs::path> geo_folders(const fs::path& tmp) {
  std::vector<fs::path> out;
  for (const auto& e : fs::directory_iterator(tmp))
    if (e.path().filename().string().rfind("tunica-geo-", 0) == 0) out.push_back(e.path());
  return out;
}

/// Starts `tunica check --allow-scripts deck` with TMPDIR = tmp, its output to `log`.
pid_t start_check(const std::string& deck, const fs::path& tmp, const fs::path& log) {
  const pid_t pid = fork();
  if (pid == 0) {
    const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    dup2(fd, 1);
    dup2(fd, 2);
    setenv("TMPDIR", tmp.c_str(), 1);
    // As from a terminal: a test started in the background by a shell ignores SIGINT, and an
    // ignored signal would stay ignored across exec.
    signal(SIGINT, SIG_DFL);
    signal(SIGTERM, SIG_DFL);
    execl(TUNICA_BINARY, TUNICA_BINARY, "check", "--allow-scripts", deck.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  return pid;
}

/// Waits (at most 60 s) until process `pid` meshes: its temporary folder holds its lock.
bool wait_for_meshing(const fs::path& tmp, pid_t pid) {
  const std::string prefix = "tunica-geo-" + std::to_string(pid) + "-";
  for (int k = 0; k < 6000; ++k) {
    for (const fs::path& d : geo_folders(tmp))
      if (d.filename().string().rfind(prefix, 0) == 0 && fs::exists(d / "lock")) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return false;
}

/// A started check, killed and reaped if the test stops before it has ended.
struct Child {
  pid_t pid;
  ~Child() {
    if (pid > 0) {
      kill(pid, SIGKILL);
      waitpid(pid, nullptr, 0);
    }
  }
  /// Exit status, and the seconds it took to end.
  std::pair<int, double> wait_timed() {
    const auto t0 = std::chrono::steady_clock::now();
    int status = 0;
    waitpid(pid, &status, 0);
    pid = -1;
    return {status, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count()};
  }
};

// The script's own command keeps Gmsh busy for 20 s.
const std::string kBusy = "System \"sleep 20\";\n";

}  // namespace

TEST(ScriptInterrupted, SigtermOrCtrlCWhileGmshMeshesEndsAtOnceWithAMessageAndNoTemporaryFolder) {
  for (const int sig : {SIGTERM, SIGINT}) {
    const fs::path dir = folder("signal-" + std::to_string(sig));
    const std::string deck = write_deck(dir, kBusy);
    Child check{start_check(deck, dir / "tmp", dir / "check.log")};
    ASSERT_TRUE(wait_for_meshing(dir / "tmp", check.pid)) << read_text((dir / "check.log").string());
    kill(check.pid, sig);
    const auto [status, seconds] = check.wait_timed();
    const std::string log = read_text((dir / "check.log").string());
    ASSERT_TRUE(WIFEXITED(status)) << "ended by signal " << WTERMSIG(status) << ", without a message: " << log;
    EXPECT_EQ(WEXITSTATUS(status), 128 + sig) << log;
    EXPECT_LT(seconds, 5.0);
    EXPECT_NE(log.find("tunica: interrupted by signal " + std::to_string(sig) + " (" + strsignal(sig) +
                       ") while Gmsh meshed the script " + (dir / "wall.geo").string() +
                       ": Gmsh was ended and its temporary folder removed; nothing was written"),
              std::string::npos)
        << log;
    EXPECT_TRUE(geo_folders(dir / "tmp").empty());
  }
}

TEST(ScriptInterrupted, TheFolderOfAKilledCheckIsRemovedByTheNextMeshingButNotThatOfARunningOne) {
  const fs::path dir = folder("stale");
  const fs::path tmp = dir / "tmp";
  const std::string busy = write_deck(dir, kBusy);
  // Killed outright while Gmsh runs: its folder stays behind.
  Child killed{start_check(busy, tmp, dir / "killed.log")};
  const pid_t pid = killed.pid;
  ASSERT_TRUE(wait_for_meshing(tmp, pid)) << read_text((dir / "killed.log").string());
  kill(pid, SIGKILL);
  killed.wait_timed();
  const std::vector<fs::path> left = geo_folders(tmp);
  ASSERT_EQ(left.size(), 1u);
  EXPECT_EQ(left[0].filename().string().rfind("tunica-geo-" + std::to_string(pid) + "-", 0), 0u)
      << left[0] << ": the folder names its process";
  // A check that meshes: it removes the killed check's folder before it makes its own.
  Child running{start_check(busy, tmp, dir / "running.log")};
  ASSERT_TRUE(wait_for_meshing(tmp, running.pid)) << read_text((dir / "running.log").string());
  const std::vector<fs::path> now = geo_folders(tmp);
  ASSERT_EQ(now.size(), 1u) << "the stale folder is still there";
  EXPECT_NE(now[0], left[0]);
  // A quick check meanwhile: it meshes, and leaves the running check's folder alone.
  const fs::path quick_dir = dir / "quick";
  fs::create_directories(quick_dir);
  const std::string quick = write_deck(quick_dir, "");
  const int status = Child{start_check(quick, tmp, dir / "quick.log")}.wait_timed().first;
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << read_text((dir / "quick.log").string());
  EXPECT_EQ(geo_folders(tmp), now);
  kill(running.pid, SIGTERM);
  running.wait_timed();
  EXPECT_TRUE(geo_folders(tmp).empty());
}
