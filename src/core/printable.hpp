#pragma once
// Quoting text taken from an input file in a one-line message: control
// characters, bytes outside printable ASCII and quotes are escaped (\n, \xNN),
// and long text is cut with "...", so a message never spans lines or carries
// raw bytes to the terminal.
#include <string>
#include <string_view>

namespace tunica {

/// `text` made printable, at most `max_chars` characters of it.
std::string printable(std::string_view text, std::size_t max_chars = 40);

}  // namespace tunica
