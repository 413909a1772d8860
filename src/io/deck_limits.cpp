#include "io/deck_limits.hpp"

#include <fmt/format.h>

#include <vector>

#include "core/errors.hpp"

namespace tunica {

namespace {

/// The length of the valid UTF-8 sequence at text[k], or 0 if none starts there.
std::size_t utf8_length(const std::string& text, std::size_t k) {
  const auto b = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
  const unsigned char c = b(k);
  const std::size_t n = c < 0x80 ? 1 : (c >> 5) == 0x6 && c >= 0xC2 ? 2 : (c >> 4) == 0xE ? 3 : (c >> 3) == 0x1E && c <= 0xF4 ? 4 : 0;
  if (n == 0 || k + n > text.size()) return 0;
  for (std::size_t i = 1; i < n; ++i)
    if ((b(k + i) >> 6) != 0x2) return 0;
  return n;
}

/// A deck that is not text (a mesh, a result or an image given as the deck): an error at the first
/// byte that no YAML text holds, a control character or a byte outside UTF-8.
void check_text(const std::string& text, const std::string& file) {
  int line = 1, column = 1;
  for (std::size_t k = 0; k < text.size();) {
    const unsigned char c = static_cast<unsigned char>(text[k]);
    const std::size_t n = utf8_length(text, k);
    if (n == 0)
      throw InputError({file, line, column, ""},
                       fmt::format("byte 0x{:02X} at line {}, column {}, is not UTF-8, the encoding a deck is read in: "
                                   "save the deck as UTF-8 (or, if this is no deck but a mesh or a binary file, give "
                                   "the YAML deck)",
                                   c, line, column));
    if ((c < 0x20 && c != '\n' && c != '\t' && c != '\r') || c == 0x7F)
      throw InputError({file, line, column, ""},
                       fmt::format("the deck is not a text file: byte 0x{:02X} at line {}, column {}, is a control "
                                   "character (was a mesh, a result or another binary file given as the deck?)",
                                   c, line, column));
    if (c == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
    k += n;
  }
}

}  // namespace

void check_deck_limits(const std::string& text, const std::string& file) {
  if (text.size() > kMaxDeckBytes)
    throw InputError({file, 0, 0, ""},
                     fmt::format("the deck is {} bytes, more than the {} MiB a deck may have", text.size(), kMaxDeckBytes >> 20));
  check_text(text, file);
  std::vector<std::size_t> indents;  // block indentation levels open above the current line
  int line = 1, flow = 0;
  std::size_t pos = 0;
  while (pos < text.size()) {
    const std::size_t end = std::min(text.find('\n', pos), text.size());
    std::size_t i = pos;
    while (i < end && text[i] == ' ') ++i;
    const std::size_t indent = i - pos;
    int items = 0;  // "- - - x" opens one level per dash
    while (i + 1 < end && text[i] == '-' && text[i + 1] == ' ') {
      ++items;
      i += 2;
      while (i < end && text[i] == ' ') ++i;
    }
    const bool content = i < end && text[i] != '#';
    if (content && flow == 0) {
      while (!indents.empty() && indents.back() >= indent) indents.pop_back();
      indents.push_back(indent);
    }
    char quote = 0;
    for (std::size_t k = i; k < end; ++k) {
      const char c = text[k];
      if (quote) {
        if (c == quote) quote = 0;
        continue;
      }
      if (c == '"' || c == '\'') quote = c;
      else if (c == '#' && (k == i || text[k - 1] == ' ')) break;
      else if (c == '[' || c == '{') ++flow;
      else if ((c == ']' || c == '}') && flow > 0) --flow;
      const int depth = static_cast<int>(indents.size()) + items + flow;
      if (depth > kMaxDeckNesting)
        throw InputError({file, line, static_cast<int>(k - pos) + 1, ""},
                         fmt::format("maps and lists nest deeper than {} levels", kMaxDeckNesting));
    }
    if (static_cast<int>(indents.size()) + items > kMaxDeckNesting)
      throw InputError({file, line, static_cast<int>(indent) + 1, ""},
                       fmt::format("maps and lists nest deeper than {} levels", kMaxDeckNesting));
    pos = end + 1;
    ++line;
  }
}

}  // namespace tunica
