#pragma once
// Reading a YAML deck into a Model, with validation of every key.
#include <string>
#include <vector>

#include "io/params.hpp"
#include "model/model.hpp"

namespace tunica {

/// Reads and validates a deck. Throws InputError naming file, line and key.
Model read_deck(const std::string& path);
/// Same, from text (file name used in messages).
Model read_deck_text(const std::string& text, const std::string& file_name);

/// Declarations of every deck section, in document order, for the reference in docs/.
std::vector<ComponentSpec> deck_sections();

/// The history quantities: name, what it needs (part, node_set, load), dimension, meaning.
struct HistoryQuantity {
  std::string name;
  std::string target;  ///< "part", "node_set", "load" or ""
  Dimension dim;
  std::string doc;
};
const std::vector<HistoryQuantity>& history_quantities();

}  // namespace tunica
