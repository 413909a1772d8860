#pragma once
// Whether a run recorded in an output folder's restart.txt can be continued with a deck: the
// same model (its DOFs, boundaries and loads, and the fingerprint of what the converged
// increments depend on, io/deck_fingerprint.hpp) and a step left to run. Each refusal says what
// differs and the way out: the deck that wrote the folder, a fresh folder, or a step to add.
#include <string>

#include "model/model.hpp"
#include "output/restart_file.hpp"

namespace tunica {

/// Throws InputError unless the run in `r` (read from `file`, <folder>/restart.txt) continues
/// with the model `m`. Returns a warning ("" if none): a restart file older than fingerprints,
/// whose deck cannot be compared.
std::string check_restart_fits(const Model& m, const RestartRecord& r, const std::string& file);

}  // namespace tunica
