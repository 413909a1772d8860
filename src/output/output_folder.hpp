#pragma once
// The files Tunica itself writes into an output folder, and removing them.
// Only these names are ever removed; any other file in the folder stays.
//   history.csv, newton.csv, frames.csv, fixed_point.csv, restart.txt, meridian.pvd, surface.pvd,
//   reference_<step>.msh and .csv (an inverse step's zero-pressure geometry, reference_mesh.hpp),
//   vtk/meridian_NNNNNN.vtu, vtk/surface_NNNNNN.vtu,
//   and the temporaries `<one of those>.tmp.<pid>` a killed run leaves behind.
// Called under the folder's lock (output_lock.hpp).
#include <string>

namespace tunica {

/// Removes every file of an earlier run from `directory` (a fresh run); returns how many. A file of
/// one of those names that does not start as Tunica writes it (a user's own history.csv) stays.
int remove_earlier_run(const std::string& directory);
/// After remove_earlier_run: a file left in `directory` under a name Tunica writes (a user's), or "".
std::string foreign_file(const std::string& directory);
/// Removes the frames numbered `first_frame` and above and every temporary (a resumed run:
/// what was written after the checkpoint it continues from); returns how many.
int remove_after_checkpoint(const std::string& directory, long first_frame);

}  // namespace tunica
