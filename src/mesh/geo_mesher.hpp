#pragma once
// Meshing a Gmsh geometry script (.geo) through the Gmsh SDK, contained: Gmsh runs
// in a child process, so that a crash, an abort or an exit inside the library, or a
// parser left in a bad state, cannot take the run down or affect a later read. The
// child writes a .msh file, which is then read by Tunica's own .msh reader like any
// other. A script can run commands (Gmsh's `System`): callers run one only when the
// user has allowed it (--allow-scripts). The child's files are in a temporary folder
// `tunica-geo-<pid>-XXXXXX` in $TMPDIR (else /tmp), removed when the meshing ends, however it
// ends; the folders of processes killed outright (SIGKILL) are removed by the next meshing.
#include <stdexcept>
#include <string>

namespace tunica {

struct GeoMeshFormat {
  double version = 4.1;  ///< 4.1 or 2.2
  bool binary = false;
};

/// SIGINT or SIGTERM arrived while Gmsh meshed a script: Gmsh, and the commands the script
/// started, have been ended and the temporary folder removed. The caller reports it and
/// exits (128 + signal(), as a run stopped by the signal does).
class MeshingInterrupted : public std::runtime_error {
public:
  MeshingInterrupted(int signal, const std::string& script);
  int signal() const { return signal_; }

private:
  int signal_;
};

/// Opens the script `path` in a child process, meshes its surfaces in 2-D if it
/// holds no 2-D mesh yet, and returns the bytes of the .msh file Gmsh writes (its
/// physical groups only). Throws InputError naming `path` (and the line of a syntax
/// error) when Gmsh reports an error, and when the child dies (its signal named);
/// MeshingInterrupted on SIGINT or SIGTERM, within 0.1 s.
std::string mesh_geo_script(const std::string& path, const GeoMeshFormat& format = {});

}  // namespace tunica
