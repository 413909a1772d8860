#pragma once
// A file that only grows: history.csv, newton.csv, frames.csv and the .pvd
// series. Each append is one positioned write at the known end, so the cost
// of an increment does not grow with the run. The length and CRC-32 of what
// has been appended are kept for the restart manifest. An optional tail (the
// closing tags of a .pvd) is written after the content with the same write and
// overwritten by the next append; it is not part of the recorded length.
#include <cstdint>
#include <string>

#include "output/file_manifest.hpp"

namespace tunica {

class AppendFile {
public:
  AppendFile() = default;
  ~AppendFile();
  AppendFile(const AppendFile&) = delete;
  AppendFile& operator=(const AppendFile&) = delete;

  /// Creates (or empties) `directory/name` and writes `initial` (and `tail`).
  void create(const std::string& directory, const std::string& name, const std::string& initial,
              const std::string& tail = "");
  /// Continues `directory/record.name` after verify_file(…, Tail::cut): the file holds exactly
  /// the recorded bytes; `tail` is written after them.
  void resume(const std::string& directory, const FileRecord& record, const std::string& tail = "");
  bool is_open() const { return fd_ >= 0; }
  /// Appends `text` (then the tail) at the recorded end.
  void append(const std::string& text);
  /// fdatasync: the appended bytes are on disk.
  void sync();
  /// Name, length and CRC-32 of the content (without the tail).
  FileRecord record() const { return {name_, size_bytes_, crc_}; }

private:
  void open_file(const std::string& path, int flags);
  int fd_ = -1;
  std::string path_, name_, tail_;
  std::uint64_t size_bytes_ = 0;
  std::uint32_t crc_ = 0;
};

}  // namespace tunica
