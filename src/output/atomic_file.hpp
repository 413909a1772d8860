#pragma once
// Writing a file atomically: the text goes to a temporary file beside it,
// which is then renamed over the target, so a reader (or a killed run) never
// sees a half-written file.
#include <string>

namespace tunica {

/// Writes `text` to `path` atomically. Throws std::runtime_error naming the path on failure.
void write_file_atomically(const std::string& path, const std::string& text);

}  // namespace tunica
