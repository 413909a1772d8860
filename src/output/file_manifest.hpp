#pragma once
// The manifest of a run's output: for each file a resumed run continues from,
// the byte length it had at the checkpoint and the zlib CRC-32 of those bytes.
// A restart checks every recorded file against it before writing anything:
// a file that is missing, shorter than recorded, or whose recorded bytes
// changed is refused; bytes past the recorded length (a tail written after the
// checkpoint) are cut off where the file may grow, refused where it may not.
#include <cstdint>
#include <string>

namespace tunica {

struct FileRecord {
  std::string name;             ///< path relative to the output folder
  std::uint64_t size_bytes = 0;  ///< bytes covered by the checksum (from the start of the file)
  std::uint32_t crc32 = 0;       ///< zlib CRC-32 of those bytes
};

/// CRC-32 of `text` continuing from `crc` (0 to start).
std::uint32_t crc32_of(const std::string& text, std::uint32_t crc = 0);

enum class Tail { cut, refuse };

/// Checks `directory/record.name` against the record; throws InputError naming the file if it
/// is missing, shorter, longer (Tail::refuse) or its first size_bytes bytes have another CRC.
/// With Tail::cut, a longer file is truncated to size_bytes. Reads the file in blocks.
void verify_file(const std::string& directory, const FileRecord& record, Tail tail);

}  // namespace tunica
