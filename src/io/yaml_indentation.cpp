#include "io/yaml_indentation.hpp"

#include <fmt/format.h>

#include <vector>

#include "core/printable.hpp"

namespace tunica {

namespace {

/// A line of block YAML as indentation sees it.
struct BlockLine {
  int number = 0;        ///< 1-based
  int indent = 0;        ///< spaces before its content
  std::string content;   ///< without the indentation and a trailing comment
  bool item = false;     ///< starts with `- `
  int item_indent = -1;  ///< an item whose content is a block map (`- name: x`): its keys' indentation
  bool opens = false;    ///< ends with `:` or is a bare `-`: the lines below it may be deeper
  bool balanced = true;  ///< its `{` and `[` close on the line
  /// What the line holds, for messages: "'base'", "an item".
  std::string label() const {
    std::string s = item ? (content.size() > 2 ? content.substr(2) : std::string()) : content;
    const std::size_t colon = s.find(':');
    if (colon == std::string::npos || s.empty() || s[0] == '{' || s[0] == '[')
      return item ? "an item" : "a value";
    std::string key = s.substr(0, colon);
    while (!key.empty() && key.back() == ' ') key.pop_back();
    return (item ? "the item starting '" : "'") + printable(key, 60) + "'";
  }
};

std::vector<BlockLine> block_lines(const std::string& text, int last) {
  std::vector<BlockLine> out;
  int number = 1;
  for (std::size_t start = 0; start <= text.size() && number <= last; ++number) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::string raw = text.substr(start, end - start);
    start = end + 1;
    if (!raw.empty() && raw.back() == '\r') raw.pop_back();
    BlockLine b;
    b.number = number;
    while (b.indent < static_cast<int>(raw.size()) && raw[b.indent] == ' ') ++b.indent;
    // The content without a comment (a `#` after a space, outside quotes); brackets counted.
    char quote = 0;
    int depth = 0;
    std::string c;
    for (std::size_t i = b.indent; i < raw.size(); ++i) {
      const char ch = raw[i];
      if (quote) {
        if (ch == quote) quote = 0;
      } else if (ch == '#' && (i == static_cast<std::size_t>(b.indent) || raw[i - 1] == ' ')) {
        break;
      } else if (ch == '"' || ch == '\'') {
        quote = ch;
      } else if (ch == '{' || ch == '[') {
        ++depth;
      } else if (ch == '}' || ch == ']') {
        --depth;
      }
      c += ch;
    }
    while (!c.empty() && c.back() == ' ') c.pop_back();
    if (c.empty() || c == "---") continue;
    b.content = c;
    b.balanced = depth == 0;
    b.item = c == "-" || c.rfind("- ", 0) == 0;
    b.opens = c.back() == ':' || c == "-";
    if (b.item && c.size() > 2) {
      std::size_t k = 2;
      while (k < c.size() && c[k] == ' ') ++k;
      if (c[k] != '{' && c[k] != '[' && c.find(": ") != std::string::npos) b.item_indent = b.indent + static_cast<int>(k);
      else if (c[k] != '{' && c[k] != '[' && c.back() == ':') b.item_indent = b.indent + static_cast<int>(k);
    }
    out.push_back(b);
  }
  return out;
}

}  // namespace

std::string indentation_cause(const std::string& text, int line) {
  if (line <= 1) return "";
  const std::vector<BlockLine> lines = block_lines(text, line);
  if (lines.size() < 2 || lines.back().number != line) return "";
  for (const BlockLine& b : lines)
    if (!b.balanced) return "";  // a flow collection across lines: no block structure to read
  const BlockLine& at = lines.back();
  const BlockLine& prev = lines[lines.size() - 2];
  // The levels open at `at`: each with the line that shows it (the last line at that level) and
  // the line that holds the block (the nearest line above that with less indentation).
  struct Level {
    int indent;
    const BlockLine* sibling;
  };
  std::vector<Level> levels;  // deepest first
  int bound = 1 << 30;
  for (auto it = lines.rbegin() + 1; it != lines.rend(); ++it) {
    if (it->item_indent >= 0 && it->item_indent < bound && it->item_indent > it->indent &&
        (levels.empty() || levels.back().indent > it->item_indent))
      levels.push_back({it->item_indent, &*it});
    if (it->indent < bound) {
      levels.push_back({it->indent, &*it});
      bound = it->indent;
    }
  }
  const auto holder = [&](const Level& l) -> std::string {
    // The line whose block holds this level: the nearest line above the sibling with less indentation.
    const int from = l.sibling->number;
    if (l.sibling->item_indent == l.indent) return fmt::format("{} (line {})", l.sibling->label(), from);
    for (auto it = lines.rbegin(); it != lines.rend(); ++it)
      if (it->number < from && (it->indent < l.indent || it->item_indent == l.indent))
        return fmt::format("{} (line {})", it->label(), it->number);
    return "the deck's top level";
  };
  const auto suggest = [&](const Level& l) {
    const std::string of = holder(l);
    return fmt::format("by {} space(s), as line {} ({}) is, to make it another entry of {}", l.indent,
                       l.sibling->number, l.sibling->label(), of == "the deck's top level" ? "the deck's top level" : of);
  };
  const int i = at.indent;
  std::string why;
  if (i > prev.indent && !prev.opens) {
    why = fmt::format("line {} is indented by {} space(s), deeper than line {} ({}), which already has its value and "
                      "holds nothing below it",
                      line, i, prev.number, prev.label());
  } else {
    for (const Level& l : levels)
      if (l.indent == i) return "";  // a level of the block: the indentation fits
    if (i > prev.indent) return "";   // under a line that opens a block
    why = fmt::format("line {} is indented by {} space(s), which matches no level of the lines above it", line, i);
  }
  // The level just below the line's indentation, and the one just above (if any).
  const Level* below = nullptr;
  const Level* above = nullptr;
  for (const Level& l : levels) {
    if (l.indent < i && (!below || l.indent > below->indent)) below = &l;
    if (l.indent > i && (!above || l.indent < above->indent)) above = &l;
  }
  std::string fix;
  if (above && below)
    fix = fmt::format("indent it {}, or {}", suggest(*above), suggest(*below));
  else if (below)
    fix = fmt::format("indent it {}", suggest(*below));
  else if (above)
    fix = fmt::format("indent it {}", suggest(*above));
  if (fix.empty()) return "";
  return fmt::format(" ({}: YAML nests by indentation, each entry of a block at the same number of spaces; {})", why,
                     fix);
}

}  // namespace tunica
