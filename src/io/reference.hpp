#pragma once
#include <string>

namespace tunica {
/// The deck reference as Markdown, generated from the parameter declarations
/// of every section, material and mesh generator (docs/deck-reference.md).
std::string deck_reference_markdown();
}  // namespace tunica
