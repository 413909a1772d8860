#include "io/yaml_syntax.hpp"

#include <fmt/format.h>

#include <climits>
#include <tuple>
#include <vector>

#include "core/printable.hpp"
#include "io/yaml_indentation.hpp"

namespace tunica {

namespace {

/// (line, column) of the first tab in the indentation of a line up to `last_line` (1-based), or (0, 0).
std::pair<int, int> indenting_tab(const std::string& text, int last_line) {
  int line = 1;
  for (std::size_t start = 0; start < text.size() && line <= last_line; ++line) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    for (std::size_t i = start; i < end && (text[i] == ' ' || text[i] == '\t'); ++i)
      if (text[i] == '\t') return {line, static_cast<int>(i - start) + 1};
    start = end + 1;
  }
  return {0, 0};
}

/// An open `{` or `[`: the bracket, its line and column (1-based).
using Open = std::tuple<char, int, int>;

/// The brackets still open before (line, column) (1-based; column 0: the start of the line),
/// outside quotes and comments, innermost last.
std::vector<Open> open_brackets(const std::string& text, int stop_line, int stop_column) {
  std::vector<Open> open;
  int line = 1, column = 0;
  char quote = 0;
  bool comment = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    ++column;
    if (line > stop_line || (line == stop_line && column >= stop_column)) break;
    if (c == '\n') {
      ++line;
      column = 0;
      comment = false;
      continue;
    }
    if (comment) continue;
    if (quote) {
      if (c == quote) quote = 0;
      continue;
    }
    if (c == '#' && (i == 0 || text[i - 1] == ' ' || text[i - 1] == '\t' || text[i - 1] == '\n')) comment = true;
    else if (c == '"' || c == '\'') quote = c;
    else if (c == '{' || c == '[') open.emplace_back(c, line, column);
    else if ((c == '}' || c == ']') && !open.empty()) open.pop_back();
  }
  return open;
}

char closer(char opener) { return opener == '{' ? '}' : ']'; }

/// The text of line `line` (1-based) from column `from` to column `to` (1-based, inclusive).
std::string line_span(const std::string& text, int line, int from, int to) {
  std::size_t start = 0;
  for (int l = 1; l < line; ++l) {
    const std::size_t newline = text.find('\n', start);
    if (newline == std::string::npos) return "";
    start = newline + 1;
  }
  if (from < 1 || to < from) return "";
  const std::size_t end = std::min(text.find('\n', start), text.size());
  if (start + to > end) return "";
  return text.substr(start + from - 1, to - from + 1);
}

/// Line `line` (1-based) of `text`, without its line break ("" past the end).
std::string line_text(const std::string& text, int line) {
  std::size_t start = 0;
  for (int l = 1; l < line; ++l) {
    const std::size_t newline = text.find('\n', start);
    if (newline == std::string::npos) return "";
    start = newline + 1;
  }
  return text.substr(start, std::min(text.find('\n', start), text.size()) - start);
}

/// What may stand where yaml-cpp found a `}` or `]` that closes nothing or the wrong bracket
/// ("illegal flow end"), at (line, column).
std::string flow_end_cause(const std::string& text, int line, int column) {
  const std::string here = line_span(text, line, column, column);
  if (here != "}" && here != "]") return "";
  const char c = here[0];
  const std::vector<Open> open = open_brackets(text, line, column);
  if (open.empty())
    return fmt::format(": this `{}` closes no `{}`, since none is open here. Remove it, or add the `{}` where the {} "
                       "begins; a value that holds a `{}` is written in quotes ('a{}b')",
                       c, c == '}' ? '{' : '[', c == '}' ? '{' : '[', c == '}' ? "map" : "list", c, c);
  const auto [opener, open_line, open_column] = open.back();
  std::string fix = fmt::format("write `{}` before this `{}`", closer(opener), c);
  if (open_line == line && column - open_column <= 40)
    fix += fmt::format(" (`{}{}{}`)", line_span(text, line, open_column, column - 1), closer(opener), c);
  fix += fmt::format(", or `{}` instead of it", closer(opener));
  return fmt::format(": this `{}` would close the `{}` opened on line {}, column {}, which only `{}` closes (a `[` "
                     "list ends with `]`, a `{{` map with `}}`): {}",
                     c, opener, open_line, open_column, closer(opener), fix);
}

/// Why yaml-cpp found a map value where none may be ("illegal map value") at (line, column): the
/// `:` there stands inside the plain (unquoted) value of a key on the same line, and a `: ` (or a
/// `:` ending the line) in a plain value starts another key. "" when that is not the case (the
/// `:` is a key's own, or the value is quoted, a flow collection, an anchor or a tag).
std::string colon_in_value_cause(const std::string& text, int line, int column) {
  const std::string full = line_text(text, line);
  const std::size_t at = static_cast<std::size_t>(column - 1);
  if (full.empty() || at >= full.size() || full[at] != ':') return "";
  const auto ends_value = [&](std::size_t i) { return i + 1 >= full.size() || full[i + 1] == ' ' || full[i + 1] == '\t'; };
  // The key: after the indentation and any `- ` of list items, up to its `: ` (a quoted key whole).
  std::size_t k = 0;
  while (k < full.size()) {
    if (full[k] == ' ') ++k;
    else if (full[k] == '-' && k + 1 < full.size() && full[k + 1] == ' ') k += 2;
    else break;
  }
  std::size_t colon = k;
  if (k < full.size() && (full[k] == '"' || full[k] == '\'')) {
    colon = full.find(full[k], k + 1);
    if (colon == std::string::npos) return "";
    ++colon;
  }
  while (colon < at && !(full[colon] == ':' && ends_value(colon))) {
    if (full[colon] == '#' && colon > 0 && (full[colon - 1] == ' ' || full[colon - 1] == '\t')) return "";
    ++colon;
  }
  if (colon >= at || colon == k) return "";  // the `:` found is the key's own
  const std::string key = full.substr(k, colon - k);
  std::size_t v = colon + 1;
  while (v < full.size() && (full[v] == ' ' || full[v] == '\t')) ++v;
  if (v >= at || std::string("\"'[{|>&*!#%@`").find(full[v]) != std::string::npos) return "";
  // The value runs to a comment (` #`) or the end of the line.
  std::size_t end = full.size();
  for (std::size_t i = v + 1; i < full.size(); ++i)
    if (full[i] == '#' && (full[i - 1] == ' ' || full[i - 1] == '\t')) {
      end = i;
      break;
    }
  while (end > v && (full[end - 1] == ' ' || full[end - 1] == '\t' || full[end - 1] == '\r')) --end;
  if (at >= end) return "";
  const std::string value = full.substr(v, end - v);
  std::string quoted;
  if (value.find('"') == std::string::npos && value.find('\\') == std::string::npos) {
    quoted = '"' + value + '"';
  } else {
    quoted = "'";
    for (char c : value) quoted += c == '\'' ? std::string("''") : std::string(1, c);
    quoted += "'";
  }
  return fmt::format(": the value of '{}' contains {}, and in a value without quotes YAML reads a `:` followed by a "
                     "space or the end of the line as the start of another key: quote the whole value, e.g. `{}: {}`",
                     printable(key), at + 1 >= end ? "a `:` at its end" : "`: `", printable(key),
                     printable(quoted, 200));
}

/// A quoted value on `line` that its own quote character ends early, with more text after the closing
/// quote (`title: "tube with "quoted" word"`): the quote inside it and the fix (escape it, double
/// it, or quote with the other character). "" when the line shows no such value.
std::string quote_in_quoted_value_cause(const std::string& text, int line) {
  const std::string full = line_text(text, line);
  // The value: after the first `: ` outside quotes, past the indentation and any `- `.
  std::size_t colon = std::string::npos;
  for (std::size_t i = 0; i + 1 < full.size(); ++i) {
    if (full[i] == '"' || full[i] == '\'') break;
    if (full[i] == ':' && full[i + 1] == ' ') {
      colon = i;
      break;
    }
  }
  if (colon == std::string::npos) return "";
  std::size_t v = colon + 1;
  while (v < full.size() && full[v] == ' ') ++v;
  if (v >= full.size() || (full[v] != '"' && full[v] != '\'')) return "";
  const char q = full[v];
  std::size_t close = v + 1;
  for (; close < full.size(); ++close) {
    if (q == '"' && full[close] == '\\') {
      ++close;  // an escape
    } else if (q == '\'' && full[close] == '\'' && close + 1 < full.size() && full[close + 1] == '\'') {
      ++close;  // '' inside single quotes
    } else if (full[close] == q) {
      break;
    }
  }
  if (close >= full.size()) return "";
  std::size_t after = close + 1;
  while (after < full.size() && (full[after] == ' ' || full[after] == '\r')) ++after;
  if (after >= full.size() || full[after] == '#' || full[after] == ',' || full[after] == '}' || full[after] == ']')
    return "";
  // The value as meant: from its opening quote to the last such quote on the line.
  const std::size_t last = full.rfind(q);
  if (last <= close) return "";
  const std::string inner = full.substr(v + 1, last - v - 1);
  const std::string key = full.substr(0, colon);
  // Single quotes take `"` as it is and a `'` doubled: the fix needs no backslash.
  std::string fixed = "'";
  for (char c : inner) fixed += c == '\'' ? std::string("''") : std::string(1, c);
  fixed += "'";
  return fmt::format(": the `{}` at column {} ends the value that the `{}` at column {} opened, and text follows it. "
                     "{}, e.g. `{}: {}`",
                     q, close + 1, q, v + 1,
                     q == '"' ? "A `\"` inside a double-quoted value is written `\\\"`; or quote the value with single "
                                "quotes, inside which a `\"` stands as it is and a `'` is written `''`"
                              : "A `'` inside a single-quoted value is written `''`",
                     printable(key), printable(fixed, 200));
}

}  // namespace

InputError yaml_syntax_error(const YAML::Exception& e, const std::string& text, const std::string& file) {
  const int line = e.mark.is_null() ? 0 : e.mark.line + 1;
  const int column = e.mark.is_null() ? 0 : e.mark.column + 1;
  // yaml-cpp says "illegal tab when looking for indentation" or something further off: name the tab.
  if (const auto tab = indenting_tab(text, line > 0 ? line : INT_MAX);
      tab.first > 0 && (tab.first == line || e.msg.find("tab") != std::string::npos))
    return InputError({file, tab.first, tab.second, ""},
                      "a tab indents this line, and YAML allows only spaces for indentation: replace the tab with "
                      "spaces (YAML syntax error: " + e.msg + ")");
  std::string cause;
  if (e.msg.find("flow not found") != std::string::npos) {
    // An unclosed `[` or `{`, noticed where yaml-cpp gave up: the innermost one open at the next line.
    const char bracket = e.msg.find("map") != std::string::npos ? '{' : '[';
    const std::vector<Open> open = open_brackets(text, line > 0 ? line + 1 : INT_MAX, 0);
    for (auto it = open.rbegin(); it != open.rend(); ++it)
      if (std::get<0>(*it) == bracket) {
        cause = fmt::format(" (the `{}` opened on line {}, column {} is not closed: add the `{}` there)", bracket,
                            std::get<1>(*it), std::get<2>(*it), closer(bracket));
        break;
      }
  } else if (e.msg == "illegal flow end" && line > 0) {
    cause = flow_end_cause(text, line, column);
  } else if (e.msg == "illegal map value" && line > 0) {
    cause = colon_in_value_cause(text, line, column);
  }
  if (cause.empty() && line > 0) cause = quote_in_quoted_value_cause(text, line);
  if (cause.empty() && line > 0 &&
      (e.msg == "end of map not found" || e.msg == "end of sequence not found" || e.msg == "illegal map value"))
    cause = indentation_cause(text, line);
  return InputError({file, line, column, ""}, "YAML syntax error: " + e.msg + cause);
}

}  // namespace tunica
