// How the Gmsh 4.8 API reports errors: gmsh::initialize sets "General.AbortOnError"
// to 2, with which every error Gmsh reports is thrown as a C++ exception of type
// std::string holding the message (e.g. "'x.geo', line 1: syntax error (a)"). The child
// sets it to 0 (errors are only logged, the parser finishes), records Gmsh's messages
// with gmsh::logger and turns the first "Error: ..." after each API call into its
// failure message, which it sends to the parent through a pipe as "LINE\tMESSAGE".
#include "mesh/geo_mesher.hpp"

#include <fcntl.h>
#include <sys/prctl.h>
#include <fmt/format.h>
#include <gmsh.h>
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

std::mutex gmsh_mutex;  // one child at a time: the temporary folder and the pipe are per call anyway

/// The parent received SIGINT or SIGTERM while Gmsh ran: thrown after the child has been
/// ended, so that the temporary folder is removed on the way out; re-raised then.
struct SignalDuringMeshing {
  int signal;
};

/// A failure inside the child: its text goes to the parent.
struct ChildFailure {
  std::string message;
};

/// Runs a Gmsh API call; throws ChildFailure on an exception or on an error it logged.
class Reporter {
public:
  Reporter() {
    std::vector<std::string> log;
    gmsh::logger::get(log);
    seen_ = log.size();
  }
  template <class F>
  void call(const std::string& doing, F&& f) {
    try {
      f();
    } catch (const std::string& s) {
      throw ChildFailure{"Gmsh error while " + doing + ": " + s};
    } catch (const std::exception& e) {
      throw ChildFailure{"Gmsh error while " + doing + ": " + e.what()};
    } catch (...) {
      throw ChildFailure{"Gmsh error while " + doing + ": unknown error"};
    }
    std::vector<std::string> log;
    gmsh::logger::get(log);
    for (std::size_t i = seen_; i < log.size(); ++i)
      if (log[i].rfind("Error: ", 0) == 0) throw ChildFailure{"Gmsh error while " + doing + ": " + log[i].substr(7)};
    seen_ = log.size();
  }

private:
  std::size_t seen_ = 0;
};

/// The child's work. Returns its exit status; the failure text goes to `fd`.
int child_main(const std::string& path, const std::string& out, const GeoMeshFormat& format, int fd) {
  std::string message;
  try {
    try {
      gmsh::initialize(0, nullptr, false);  // argc, argv, readConfigFiles
      gmsh::option::setNumber("General.Terminal", 0);
      gmsh::option::setNumber("General.Verbosity", 2);
      gmsh::option::setNumber("General.AbortOnError", 0);
      gmsh::option::setNumber("General.NumThreads", 1);
      gmsh::logger::start();
    } catch (...) {
      throw ChildFailure{"could not initialize Gmsh"};
    }
    Reporter r;
    r.call("reading the script", [&] { gmsh::open(path); });
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> tags, nodes;
    gmsh::vectorpair surfaces;
    r.call("reading the elements", [&] {
      gmsh::model::mesh::getElements(types, tags, nodes, 2, -1);
      gmsh::model::getEntities(surfaces, 2);
    });
    if (types.empty() && !surfaces.empty()) r.call("meshing the surfaces", [&] { gmsh::model::mesh::generate(2); });
    r.call("writing the mesh", [&] {
      gmsh::option::setNumber("Mesh.MshFileVersion", format.version);
      gmsh::option::setNumber("Mesh.Binary", format.binary ? 1 : 0);
      gmsh::option::setNumber("Mesh.SaveAll", 0);
      gmsh::write(out);
    });
    return 0;
  } catch (const ChildFailure& f) {
    message = f.message;
  } catch (...) {
    message = "Gmsh error: unknown failure";
  }
  std::size_t done = 0;
  while (done < message.size()) {
    const ssize_t n = ::write(fd, message.data() + done, message.size() - done);
    if (n <= 0) break;
    done += static_cast<std::size_t>(n);
  }
  return 2;
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
    sigaction(SIGINT, &sa, &old_int_);
    sigaction(SIGTERM, &sa, &old_term_);
  }
  ~SignalGuard() {
    sigaction(SIGINT, &old_int_, nullptr);
    sigaction(SIGTERM, &old_term_, nullptr);
  }

private:
  struct sigaction old_int_ {}, old_term_ {};
};

/// A temporary folder, removed on every exit.
struct TempDir {
  std::string path;
  TempDir() {
    const char* base = std::getenv("TMPDIR");
    std::string templ = std::string(base && *base ? base : "/tmp") + "/tunica-geo-XXXXXX";
    std::vector<char> buf(templ.begin(), templ.end());
    buf.push_back('\0');
    if (!::mkdtemp(buf.data())) throw std::runtime_error(std::string("cannot create a temporary folder: ") + std::strerror(errno));
    path = buf.data();
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
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
  TempDir dir;
  const std::string out = dir.path + "/mesh.msh";
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) throw std::runtime_error(std::string("cannot create a pipe: ") + std::strerror(errno));
  std::fflush(nullptr);
  const pid_t parent = ::getpid();
  SignalGuard signals;
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    throw std::runtime_error(std::string("cannot start the Gmsh process: ") + std::strerror(errno));
  }
  if (pid == 0) {
    // The child ends with its parent, whatever ends the parent.
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) ::_exit(3);
    ::setpgid(0, 0);  // a group of its own, with the commands the script runs: ended together
    struct sigaction dfl {};
    dfl.sa_handler = SIG_DFL;
    sigaction(SIGINT, &dfl, nullptr);
    sigaction(SIGTERM, &dfl, nullptr);
    ::close(fds[0]);
    ::_exit(child_main(path, out, format, fds[1]));
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
  for (;;) {
    const ssize_t n = ::read(fds[0], buf, sizeof buf);
    stop_child_if_signalled();
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    if (message.size() < 65536) message.append(buf, static_cast<std::size_t>(n));
  }
  for (;;) {
    const pid_t r = ::waitpid(pid, &status, 0);
    stop_child_if_signalled();
    if (r >= 0 || errno != EINTR) break;
  }
  ::close(fds[0]);
  if (WIFSIGNALED(status))
    fail(fmt::format("Gmsh stopped with signal {} ({}) while meshing the script", WTERMSIG(status),
                     strsignal(WTERMSIG(status))));
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
    fail(printable(message, 400), line);
  }
  std::error_code ec;
  if (!std::filesystem::exists(out, ec))
    fail("the script ended before Gmsh wrote a mesh (does it call Exit, or define no surface?)");
  return read_file_bounded(out, kMaxMshBytes, "mesh Gmsh wrote");
}

std::string mesh_geo_script(const std::string& path, const GeoMeshFormat& format) {
  try {
    return mesh_in_child(path, format);
  } catch (const SignalDuringMeshing& i) {
    // The child has ended and the temporary folder is gone: let the signal take effect
    // as it would have (the previous handler, or the default action).
    std::raise(i.signal);
    throw InputError(SourceLocation{path, 0, 0, ""}, "interrupted while Gmsh meshed the script");
  }
}

}  // namespace tunica
