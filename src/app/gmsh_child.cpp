// tunica-gmsh: the process in which a Gmsh script is meshed (mesh/geo_mesher.hpp).
//
//   tunica-gmsh SCRIPT OUT.msh VERSION BINARY
//
// started by Tunica through fork and exec, so that Gmsh runs in a fresh process image:
// nothing of the parent's threads, locks or library state is inherited. It opens the
// script, meshes its surfaces in 2-D if it holds no 2-D mesh yet, writes OUT.msh in
// format VERSION (4.1 or 2.2), binary if BINARY is 1, and exits 0. On failure it
// writes one message to file descriptor 3 (the pipe its parent reads) and exits 2.
//
// How the Gmsh 4.8 API reports errors: gmsh::initialize sets "General.AbortOnError"
// to 2, with which every error Gmsh reports is thrown as a C++ exception of type
// std::string holding the message (e.g. "'x.geo', line 1: syntax error (a)"). This
// process sets it to 0 (errors are only logged, the parser finishes), records Gmsh's
// messages with gmsh::logger and turns the first "Error: ..." after each API call
// into its failure message.
#include <gmsh.h>
#include <unistd.h>

#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

namespace {

/// A failure: its text goes to the parent.
struct Failure {
  std::string message;
};

/// Runs a Gmsh API call; throws Failure on an exception or on an error it logged.
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
      throw Failure{"Gmsh error while " + doing + ": " + s};
    } catch (const std::exception& e) {
      throw Failure{"Gmsh error while " + doing + ": " + e.what()};
    } catch (...) {
      throw Failure{"Gmsh error while " + doing + ": unknown error"};
    }
    std::vector<std::string> log;
    gmsh::logger::get(log);
    for (std::size_t i = seen_; i < log.size(); ++i)
      if (log[i].rfind("Error: ", 0) == 0) throw Failure{"Gmsh error while " + doing + ": " + log[i].substr(7)};
    seen_ = log.size();
  }

private:
  std::size_t seen_ = 0;
};

void mesh(const std::string& script, const std::string& out, double version, bool binary) {
  try {
    gmsh::initialize(0, nullptr, false);  // argc, argv, readConfigFiles
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::option::setNumber("General.Verbosity", 2);
    gmsh::option::setNumber("General.AbortOnError", 0);
    gmsh::option::setNumber("General.NumThreads", 1);
    gmsh::logger::start();
  } catch (...) {
    throw Failure{"could not initialize Gmsh"};
  }
  Reporter r;
  r.call("reading the script", [&] { gmsh::open(script); });
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> tags, nodes;
  gmsh::vectorpair surfaces;
  r.call("reading the elements", [&] {
    gmsh::model::mesh::getElements(types, tags, nodes, 2, -1);
    gmsh::model::getEntities(surfaces, 2);
  });
  if (types.empty() && !surfaces.empty()) r.call("meshing the surfaces", [&] { gmsh::model::mesh::generate(2); });
  r.call("writing the mesh", [&] {
    gmsh::option::setNumber("Mesh.MshFileVersion", version);
    gmsh::option::setNumber("Mesh.Binary", binary ? 1 : 0);
    gmsh::option::setNumber("Mesh.SaveAll", 0);
    gmsh::write(out);
  });
}

}  // namespace

int main(int argc, char** argv) {
  constexpr int report_fd = 3;
  std::string message;
  if (argc != 5) {
    message = "tunica-gmsh is started by Tunica: tunica-gmsh SCRIPT OUT.msh VERSION BINARY";
  } else {
    try {
      mesh(argv[1], argv[2], std::atof(argv[3]), std::string(argv[4]) == "1");
      ::_exit(0);  // Gmsh's global state is not torn down: the process ends here
    } catch (const Failure& f) {
      message = f.message;
    } catch (...) {
      message = "Gmsh error: unknown failure";
    }
  }
  std::size_t done = 0;
  while (done < message.size()) {
    const ssize_t n = ::write(report_fd, message.data() + done, message.size() - done);
    if (n <= 0) break;
    done += static_cast<std::size_t>(n);
  }
  ::_exit(2);
}
