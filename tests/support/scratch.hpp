#pragma once
// Folders for the files a test writes. The tests run as parallel processes (ctest -j2), so each
// process writes under a folder of its own, named after the process: <tmp>/tunica-<tag>-<pid>.
#include <unistd.h>

#include <filesystem>
#include <string>

namespace tunica::test {

/// <tmp>/tunica-<tag>-<pid>, created if it is not there: this process's folder for the files of
/// the tests that share `tag`.
inline std::filesystem::path scratch(const std::string& tag) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("tunica-" + tag + "-" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  return dir;
}

/// scratch(tag) / name, an empty folder: whatever an earlier test left there is removed first.
inline std::filesystem::path scratch(const std::string& tag, const std::string& name) {
  const std::filesystem::path dir = scratch(tag) / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace tunica::test
