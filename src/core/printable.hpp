#pragma once
// Quoting text taken from an input file in a one-line message: control
// characters and bytes that are not well-formed UTF-8 are escaped (\n, \xNN),
// printable UTF-8 (a physical group named "Wand_ä") is kept, and long text is cut
// with "...", so a message never spans lines or carries raw bytes to the terminal.
#include <string>
#include <string_view>

namespace tunica {

/// `text` made printable, at most `max_chars` characters of it.
std::string printable(std::string_view text, std::size_t max_chars = 40);

/// `text` for the terminal, whole: line breaks and backslashes kept, every other control
/// character, ill-formed or invisible byte escaped as \xNN (a message that already quotes a
/// file through printable() passes unchanged).
std::string terminal_safe(std::string_view text);

/// True if `text` holds only printable ASCII and well-formed printable UTF-8 (no control
/// characters, no line breaks): what every message quoting an input must be.
bool is_printable_line(std::string_view text);

}  // namespace tunica
