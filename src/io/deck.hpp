#pragma once
// Reading a YAML deck into a Model, with validation of every key.
#include <string>
#include <vector>

#include "io/read_params.hpp"
#include "model/model.hpp"

namespace tunica {

/// What reading a deck may do beyond reading data.
struct ReadOptions {
  /// Mesh the Gmsh scripts (.geo) that parts name. A script can run commands, so this is
  /// off unless the user asks for it (--allow-scripts); a deck that names one is refused.
  bool allow_scripts = false;
};

/// Reads and validates a deck. Throws InputError naming file, line and key.
Model read_deck(const std::string& path, const ReadOptions& options = {});
/// Same, from text (file name used in messages).
Model read_deck_text(const std::string& text, const std::string& file_name, const ReadOptions& options = {});

/// Declarations of every deck section, in document order, for the reference in docs/.
std::vector<ComponentSpec> deck_sections();

}  // namespace tunica
