#pragma once
// Limits a deck must respect before it is parsed, so that absurd input is
// refused with a clear message before anything large is allocated or a
// parser recurses deeply.
#include <cstddef>
#include <string>

#include "core/limits.hpp"

namespace tunica {

constexpr std::size_t kMaxDeckBytes = 16u << 20;  ///< 16 MiB of YAML is far beyond any real deck
constexpr int kMaxDeckNesting = 64;                ///< nesting levels of maps and lists

/// Throws InputError (file, line, column) if `text` is larger than kMaxDeckBytes or nests
/// maps and lists (block indentation, "- " items, flow brackets) deeper than kMaxDeckNesting.
void check_deck_limits(const std::string& text, const std::string& file);

}  // namespace tunica
