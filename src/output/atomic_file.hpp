#pragma once
// Writing a file atomically: the text goes to a temporary file beside it
// (`<file>.tmp.<pid>`, unique per process), which is then renamed over the
// target, so a reader (or a killed run) never sees a half-written file.
// With Durability::synced the temporary file is fsync'ed before the rename and
// the directory after it, so the new content survives a power loss too.
#include <string>

namespace tunica {

enum class Durability { buffered, synced };

/// Writes `text` to `path` atomically. Throws std::runtime_error naming the path on failure.
void write_file_atomically(const std::string& path, const std::string& text,
                           Durability durability = Durability::buffered);
/// The temporary name write_file_atomically uses for `path` in this process.
std::string temporary_name(const std::string& path);
/// fsync of a directory (its entries: files created or renamed in it). Throws on failure.
void sync_directory(const std::string& directory);

}  // namespace tunica
