#pragma once
// Reading an outside file whole, with its size limit enforced while reading:
// a device (/dev/zero), a FIFO or a file that grows is cut off at the limit
// instead of being read to exhaustion. Every reader of user files (decks,
// meshes, restart files, fit data) goes through this.
#include <cstddef>
#include <string>

namespace tunica {

/// Reads `path` whole. Throws InputError naming `path` (file, no line) when it does not
/// exist, is a directory, is not a regular file (a device, FIFO or socket: "it is not a
/// regular file"), cannot be read, or holds more than `max_bytes` bytes ("the <what> is
/// larger than N MiB"). At most max_bytes + 1 bytes are ever read or allocated.
std::string read_file_bounded(const std::string& path, std::size_t max_bytes, const std::string& what);

}  // namespace tunica
