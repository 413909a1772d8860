// The parent's side of meshing a script: tunica-gmsh (src/app/gmsh_child.cpp) runs
// Gmsh in a process of its own, started by fork and exec. Between the two the child
// calls only async-signal-safe functions, as POSIX requires after fork in a process
// with threads (the element loops' OpenMP team, a caller's threads): nothing of the
// parent's locks or library state reaches Gmsh.
#include "mesh/geo_mesher.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/file.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <fmt/format.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <regex>
#include <vector>

#include "core/bounded_file.hpp"
#include "core/errors.hpp"
#include "core/printable.hpp"
#include "mesh/msh_parser.hpp"

namespace tunica {

namespace {

constexpr int kReportFd = 3;      // where tunica-gmsh writes its failure message
constexpr int kExecFailed = 127;  // the child's status when exec failed

std::mutex gmsh_mutex;  // one child at a time: the temporary folder and the pipe are per call anyway

/// The parent received SIGINT or SIGTERM while Gmsh ran: thrown after the child has been
/// ended, so that the temporary folder is removed on the way out; MeshingInterrupted then.
struct SignalDuringMeshing {
  int signal;
};

/// The helper executable that runs Gmsh: beside the running executable (tunica, or an
/// installed copy), else where the build put it (tests and benchmarks run from
/// subfolders of the build).
std::string helper_path() {
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const std::filesystem::path beside = self.parent_path() / "tunica-gmsh";
    if (::access(beside.c_str(), X_OK) == 0) return beside.string();
  }
  if (::access(TUNICA_GMSH_HELPER, X_OK) == 0) return TUNICA_GMSH_HELPER;
  throw std::runtime_error("cannot find the Gmsh helper tunica-gmsh beside the executable or at " +
                           std::string(TUNICA_GMSH_HELPER) + " (it is built with tunica)");
}

/// SIGINT / SIGTERM while Gmsh runs: remembered here, so that the parent can end the
/// child and remove the temporary folder before it lets the signal take effect.
volatile std::sig_atomic_t pending_signal = 0;
extern "C" void remember_signal(int sig) { pending_signal = sig; }

/// Installs remember_signal for SIGINT and SIGTERM (without SA_RESTART, so that a blocked
/// read or waitpid returns EINTR) and restores the previous handlers on exit.
class SignalGuard {
public:
  SignalGuard() {
    pending_signal = 0;
    struct sigaction sa {};
    sa.sa_handler = remember_signal;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = 0;
    // A signal the process ignores (SIGINT of a job started in the background by a shell)
    // stays ignored.
    sigaction(SIGINT, nullptr, &old_int_);
    sigaction(SIGTERM, nullptr, &old_term_);
    if (old_int_.sa_handler != SIG_IGN) sigaction(SIGINT, &sa, nullptr);
    if (old_term_.sa_handler != SIG_IGN) sigaction(SIGTERM, &sa, nullptr);
  }
  ~SignalGuard() {
    sigaction(SIGINT, &old_int_, nullptr);
    sigaction(SIGTERM, &old_term_, nullptr);
  }

private:
  struct sigaction old_int_ {}, old_term_ {};
};

/// Where the temporary folders are made: $TMPDIR, else /tmp.
std::string temp_base() {
  const char* base = std::getenv("TMPDIR");
  return base && *base ? base : "/tmp";
}

constexpr const char* kFolderPrefix = "tunica-geo-";
constexpr const char* kLockName = "lock";

/// Removes the temporary folders of meshings whose process has ended without removing its
/// own (killed with SIGKILL, a power loss): each folder holds a file `lock` that its process
/// holds locked (flock) for as long as it meshes, and the kernel releases the lock with the
/// process however it ends. A folder whose lock this process can take is stale. Only this
/// user's folders are considered; one without a `lock` (being made this instant, or of a
/// Tunica before locks) is left alone.
void remove_stale_folders(const std::string& base) {
  namespace fs = std::filesystem;
  std::vector<fs::path> stale;
  std::error_code ec;
  std::size_t seen = 0;
  for (fs::directory_iterator it(base, ec), end; !ec && it != end && seen < 10000; it.increment(ec), ++seen) {
    if (it->path().filename().string().rfind(kFolderPrefix, 0) != 0) continue;
    struct stat st {};
    if (::lstat(it->path().c_str(), &st) != 0 || !S_ISDIR(st.st_mode) || st.st_uid != ::geteuid()) continue;
    stale.push_back(it->path());
  }
  for (const fs::path& dir : stale) {
    const int fd = ::open((dir / kLockName).c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW);
    if (fd < 0) continue;
    if (::flock(fd, LOCK_EX | LOCK_NB) == 0) fs::remove_all(dir, ec);  // removed while holding its lock
    ::close(fd);
  }
}

/// A temporary folder `tunica-geo-<pid>-XXXXXX`, removed on every exit, and locked for as long
/// as it exists (remove_stale_folders). Made after the stale ones are removed.
struct TempDir {
  std::string path;
  int lock = -1;
  TempDir() {
    const std::string base = temp_base();
    remove_stale_folders(base);
    std::string templ = base + "/" + kFolderPrefix + std::to_string(::getpid()) + "-XXXXXX";
    std::vector<char> buf(templ.begin(), templ.end());
    buf.push_back('\0');
    if (!::mkdtemp(buf.data())) throw std::runtime_error(std::string("cannot create a temporary folder: ") + std::strerror(errno));
    path = buf.data();
    // The lock is taken under another name and then renamed: a `lock` is always held. Where
    // locks are not supported (some network file systems) the folder goes without one: it
    // is still removed at the end, only not after a SIGKILL.
    const std::string fresh = path + "/" + kLockName + ".new";
    lock = ::open(fresh.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC | O_NOFOLLOW, 0600);
    if (lock >= 0 && (::flock(lock, LOCK_EX) != 0 || ::rename(fresh.c_str(), (path + "/" + kLockName).c_str()) != 0)) {
      ::close(lock);
      lock = -1;
      ::unlink(fresh.c_str());
    }
  }
  ~TempDir() { remove(); }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

private:
  void remove() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);  // before the lock is let go
    if (lock >= 0) ::close(lock);
    lock = -1;
  }
};

}  // namespace

static std::string mesh_in_child(const std::string& path, const GeoMeshFormat& format) {
  const auto fail = [&](const std::string& what, int line = 0) -> void {
    throw InputError(SourceLocation{path, line, 0, ""}, what);
  };
  {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) fail("cannot read the Gmsh script: no such regular file");
  }
  std::lock_guard<std::mutex> lock(gmsh_mutex);
  // The handlers first: a signal from the moment the temporary folder (and its lock) exists is
  // remembered and ends the meshing below, which removes the folder (a signal before them would end
  // the process and leave it).
  SignalGuard signals;
  TempDir dir;
  const std::string out = dir.path + "/mesh.msh";
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) throw std::runtime_error(std::string("cannot create a pipe: ") + std::strerror(errno));
  // Everything the child needs is made before fork: it may not allocate.
  const std::string helper = helper_path();
  std::string version = format.version == 2.2 ? "2.2" : "4.1", binary = format.binary ? "1" : "0";
  std::string program = helper, script = path, target = out;
  std::vector<char*> argv{program.data(), script.data(), target.data(), version.data(), binary.data(), nullptr};
  std::fflush(nullptr);
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    throw std::runtime_error(std::string("cannot start the Gmsh process: ") + std::strerror(errno));
  }
  if (pid == 0) {
    // Async-signal-safe calls only, up to exec. The child ends with its parent, whatever
    // ends the parent.
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) ::_exit(3);
    ::setpgid(0, 0);  // a group of its own, with the commands the script runs: ended together
    struct sigaction dfl {};
    dfl.sa_handler = SIG_DFL;
    sigaction(SIGINT, &dfl, nullptr);
    sigaction(SIGTERM, &dfl, nullptr);
    // In a group of its own, Gmsh is a background job: reading from or writing to the
    // terminal would stop it (SIGTTIN, SIGTTOU). Its input is /dev/null and the two are
    // ignored (an ignored signal stays ignored across exec).
    struct sigaction ign {};
    ign.sa_handler = SIG_IGN;
    sigaction(SIGTTIN, &ign, nullptr);
    sigaction(SIGTTOU, &ign, nullptr);
    const int null_fd = ::open("/dev/null", O_RDONLY);
    if (null_fd >= 0 && null_fd != 0) {
      ::dup2(null_fd, 0);
      if (null_fd != kReportFd && null_fd != fds[1]) ::close(null_fd);
    }
    sigset_t none;
    sigemptyset(&none);
    sigprocmask(SIG_SETMASK, &none, nullptr);
    // The report pipe becomes descriptor 3, open across exec.
    if (fds[1] == kReportFd) {
      ::fcntl(kReportFd, F_SETFD, 0);
    } else if (::dup2(fds[1], kReportFd) < 0) {
      ::_exit(kExecFailed);
    }
    ::execv(helper.c_str(), argv.data());
    ::_exit(kExecFailed);
  }
  ::close(fds[1]);
  ::setpgid(pid, pid);  // also here: whichever of the two runs first
  std::string message;
  char buf[4096];
  int status = 0;
  const auto stop_child_if_signalled = [&] {
    if (!pending_signal) return;
    ::kill(-pid, SIGKILL);
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    ::close(fds[0]);
    throw SignalDuringMeshing{pending_signal};
  };
  // Read the report pipe until Gmsh has exited and the pipe is drained. The pipe alone
  // does not say when: a command the script left running in the background holds its
  // write end too. A Gmsh stopped by a signal (SIGSTOP) is ended rather than waited for.
  bool exited = false;
  for (;;) {
    struct pollfd ready {fds[0], POLLIN, 0};
    const int r = ::poll(&ready, 1, exited ? 0 : 100);
    stop_child_if_signalled();
    if (r < 0 && errno == EINTR) continue;
    if (r > 0) {
      const ssize_t n = ::read(fds[0], buf, sizeof buf);
      stop_child_if_signalled();
      if (n < 0 && errno == EINTR) continue;
      if (n > 0) {
        if (message.size() < 65536) message.append(buf, static_cast<std::size_t>(n));
        continue;
      }
    } else if (!exited) {
      const pid_t w = ::waitpid(pid, &status, WNOHANG | WUNTRACED);
      if (w == pid && WIFSTOPPED(status)) {
        const int sig = WSTOPSIG(status);
        ::kill(-pid, SIGKILL);
        while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
        }
        ::close(fds[0]);
        fail(fmt::format("Gmsh was stopped by signal {} ({}) while meshing the script, and was ended", sig,
                         strsignal(sig)));
      }
      exited = w == pid;
      continue;
    }
    // End of the pipe (or nothing left to read after Gmsh exited).
    if (exited) break;
    for (;;) {
      const pid_t w = ::waitpid(pid, &status, 0);
      stop_child_if_signalled();
      if (w >= 0 || errno != EINTR) break;
    }
    break;
  }
  ::kill(-pid, SIGKILL);  // commands the script left running end with Gmsh
  ::close(fds[0]);
  if (WIFSIGNALED(status))
    fail(fmt::format("Gmsh stopped with signal {} ({}) while meshing the script", WTERMSIG(status),
                     strsignal(WTERMSIG(status))));
  if (WIFEXITED(status) && WEXITSTATUS(status) == kExecFailed && message.empty())
    throw std::runtime_error("cannot start the Gmsh helper " + helper);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    if (message.empty()) message = fmt::format("Gmsh exited with status {} while meshing the script", WEXITSTATUS(status));
    // Gmsh's "'file', line N: what" gives the line in the script.
    int line = 0;
    static const std::regex located(R"(^(Gmsh error while [^:]*: )'[^']*', line (\d+): (.*)$)");
    std::smatch m;
    if (std::regex_match(message, m, located)) {
      line = std::stoi(m[2].str());
      message = m[1].str() + m[3].str();
    }
    // One line, printable: the message is Gmsh's, which may quote the script.
    std::string text = printable(message, 400);
    // Gmsh names no curve or point for a boundary that does not close: the likely causes.
    if (message.find("closed loop") != std::string::npos)
      text += ". The curves around a surface do not join end to end; likely causes: points at the same position "
              "that are not merged (curves that end at coincident but distinct points, e.g. after "
              "`Geometry.AutoCoherence = 0` or from two imported pieces: add `Coherence;` after the geometry, or "
              "use one point for both), or curves that do not meet (a gap, or a curve missing, in a `Curve Loop`)";
    fail(text, line);
  }
  std::error_code ec;
  if (!std::filesystem::exists(out, ec))
    fail("the script ended before Gmsh wrote a mesh (does it call Exit, or define no surface?)");
  return read_file_bounded(out, kMaxMshBytes, "mesh Gmsh wrote");
}

MeshingInterrupted::MeshingInterrupted(int signal, const std::string& script)
    : std::runtime_error(fmt::format("interrupted by signal {} ({}) while Gmsh meshed the script {}: Gmsh was ended "
                                     "and its temporary folder removed",
                                     signal, strsignal(signal), printable(script, 200))),
      signal_(signal) {}

std::string mesh_geo_script(const std::string& path, const GeoMeshFormat& format) {
  try {
    return mesh_in_child(path, format);
  } catch (const SignalDuringMeshing& i) {
    // The child has ended and the temporary folder is gone (the SignalGuard has restored the
    // handlers): the caller says so and exits.
    throw MeshingInterrupted(i.signal, path);
  }
}

}  // namespace tunica
