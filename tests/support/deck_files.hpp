#pragma once
// Deck files for the command-line tests: write a deck into a scratch directory, find the
// line a message must name, and expect `tunica check` to refuse a deck with one such message.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli.hpp"

namespace tunica::test {

/// Writes `text` to <tmp>/<dir>/<name>.yaml and returns the path.
inline std::string write_deck_file(const std::string& dir, const std::string& name, const std::string& text) {
  const std::filesystem::path d = std::filesystem::temp_directory_path() / dir;
  std::filesystem::create_directories(d);
  const std::filesystem::path path = d / (name + ".yaml");
  std::ofstream(path) << text;
  return path.string();
}

/// 1-based line of the first occurrence of `needle` in `text`.
inline int line_of(const std::string& text, const std::string& needle) {
  const auto pos = text.find(needle);
  if (pos == std::string::npos) throw std::runtime_error("not found: " + needle);
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(pos), '\n'));
}

/// `pattern` with each "{}" replaced by the line of the next of `needles` in `text`.
inline std::string fmt_lines(std::string pattern, const std::string& text, const std::vector<std::string>& needles) {
  for (const std::string& n : needles) pattern.replace(pattern.find("{}"), 2, std::to_string(line_of(text, n)));
  return pattern;
}

/// Writes `text` as <tmp>/<dir>/<name>.yaml, runs `tunica check` on it and expects exit 2 and
/// one line of message "<file>:<line of line_text>: ...key '<key>'...<what>..." (an empty `key`:
/// the message need not name one). Returns the outcome, for further checks.
inline Outcome expect_check_error(const std::string& dir, const std::string& name, const std::string& text,
                                  const std::string& line_text, const std::string& key, const std::string& what) {
  const std::string path = write_deck_file(dir, name, text);
  const Outcome o = run_cli("check " + path);
  EXPECT_EQ(o.exit_code, 2) << o.output;
  const int line = line_of(text, line_text);
  EXPECT_NE(o.output.find(path + ":" + std::to_string(line) + ":"), std::string::npos)
      << "expected line " << line << " in: " << o.output;
  if (!key.empty()) {
    EXPECT_NE(o.output.find("key '" + key + "'"), std::string::npos) << o.output;
  }
  EXPECT_NE(o.output.find(what), std::string::npos) << o.output;
  EXPECT_EQ(std::count(o.output.begin(), o.output.end(), '\n'), 1) << "one line of message: " << o.output;
  return o;
}

}  // namespace tunica::test
