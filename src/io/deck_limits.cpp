#include "io/deck_limits.hpp"

#include <fmt/format.h>

#include <vector>

#include "core/errors.hpp"

namespace tunica {

void check_deck_limits(const std::string& text, const std::string& file) {
  if (text.size() > kMaxDeckBytes)
    throw InputError({file, 0, 0, ""},
                     fmt::format("the deck is {} bytes, more than the {} MiB a deck may have", text.size(), kMaxDeckBytes >> 20));
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
