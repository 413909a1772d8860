#include "output/output_folder.hpp"

#include <filesystem>
#include <regex>
#include <stdexcept>

namespace tunica {

namespace {

namespace fs = std::filesystem;

const std::regex kTopFile(
    "(history\\.csv|newton\\.csv|frames\\.csv|fixed_point\\.csv|restart\\.txt|meridian\\.pvd|surface\\.pvd|reference_[A-Za-z0-9_-]+\\.(msh|csv))");
const std::regex kFrame("(meridian|surface)_([0-9]{6,})\\.vtu");
const std::regex kTemporary("(.*)\\.tmp\\.[0-9]+");

/// Removes the regular files of `dir` for which `pick(name)` holds.
template <class Pick>
int remove_files(const fs::path& dir, Pick pick) {
  int removed = 0;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return 0;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    if (!entry.is_regular_file(ec) || !pick(name)) continue;
    if (fs::remove(entry.path(), ec)) ++removed;  // false: already gone
    if (ec) throw std::runtime_error("cannot remove '" + entry.path().string() + "': " + ec.message());
  }
  return removed;
}

bool is_temporary_of(const std::string& name, const std::regex& own) {
  std::smatch m;
  return std::regex_match(name, m, kTemporary) && std::regex_match(m[1].str(), own);
}

}  // namespace

int remove_earlier_run(const std::string& directory) {
  const fs::path dir(directory);
  int n = remove_files(dir, [](const std::string& f) { return std::regex_match(f, kTopFile) || is_temporary_of(f, kTopFile); });
  n += remove_files(dir / "vtk", [](const std::string& f) { return std::regex_match(f, kFrame) || is_temporary_of(f, kFrame); });
  return n;
}

int remove_after_checkpoint(const std::string& directory, long first_frame) {
  const fs::path dir(directory);
  int n = remove_files(dir, [](const std::string& f) { return is_temporary_of(f, kTopFile); });
  n += remove_files(dir / "vtk", [&](const std::string& f) {
    std::smatch m;
    if (std::regex_match(f, m, kFrame)) return std::stol(m[2].str()) >= first_frame;
    return is_temporary_of(f, kFrame);
  });
  return n;
}

}  // namespace tunica
