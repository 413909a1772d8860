#pragma once
// Deck files for the command-line tests: write a deck into a scratch directory, and find the
// line a message must name.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

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

}  // namespace tunica::test
