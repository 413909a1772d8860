#include "output/output_folder.hpp"

#include <filesystem>
#include <fstream>
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

/// What Tunica writes at the start of each of its files (by name): a file of that name that starts
/// otherwise is the user's and stays.
bool starts_as_written(const fs::path& file) {
  const std::string name = file.filename().string();
  const auto ends = [&](const char* suffix) {
    const std::string s = suffix;
    return name.size() >= s.size() && name.compare(name.size() - s.size(), s.size(), s) == 0;
  };
  std::string prefix;
  if (name == "history.csv") prefix = "step,increment,time";
  else if (name == "newton.csv") prefix = "step,increment,attempt,iteration,";
  else if (name == "frames.csv") prefix = "series,frame,time,file,";
  else if (name == "fixed_point.csv") prefix = "step,iteration,max_distance_";
  else if (name == "restart.txt") prefix = "tunica-restart ";
  else if (ends(".pvd") || ends(".vtu")) prefix = "<?xml version=\"1.0\"?>\n<VTKFile ";
  else if (ends(".msh")) prefix = "$MeshFormat\n";
  else if (ends(".csv")) prefix = "node,R_";
  std::ifstream in(file, std::ios::binary);
  std::string head(prefix.size(), '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  // An empty file (a run stopped before its first write) is Tunica's as well.
  return in.gcount() == 0 || (in.gcount() == static_cast<std::streamsize>(prefix.size()) && head == prefix);
}

bool is_temporary_of(const std::string& name, const std::regex& own) {
  std::smatch m;
  return std::regex_match(name, m, kTemporary) && std::regex_match(m[1].str(), own);
}

}  // namespace

int remove_earlier_run(const std::string& directory) {
  const fs::path dir(directory);
  // A file of one of Tunica's names is removed when it starts as Tunica writes it: a user's own
  // history.csv in the folder stays (and the run then stops at it, RunWriter).
  int n = remove_files(dir, [&](const std::string& f) {
    return (std::regex_match(f, kTopFile) && starts_as_written(dir / f)) || is_temporary_of(f, kTopFile);
  });
  n += remove_files(dir / "vtk", [&](const std::string& f) {
    return (std::regex_match(f, kFrame) && starts_as_written(dir / "vtk" / f)) || is_temporary_of(f, kFrame);
  });
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

std::string foreign_file(const std::string& directory) {
  const fs::path dir(directory);
  std::error_code ec;
  for (const fs::path& d : {dir, dir / "vtk"}) {
    if (!fs::is_directory(d, ec)) continue;
    for (const auto& entry : fs::directory_iterator(d, ec)) {
      const std::string name = entry.path().filename().string();
      if (std::regex_match(name, d == dir ? kTopFile : kFrame)) return entry.path().string();
    }
  }
  return "";
}

}  // namespace tunica
