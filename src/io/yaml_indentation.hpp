#pragma once
// The indentation cause of a YAML syntax error in block style. yaml-cpp says "end of map not
// found", "end of sequence not found" or "illegal map value" at a line indented to no level of
// the block it continues (an entry one space off its siblings) or deeper than a line that already
// has its value; the cause says which, and the indentation that makes the line an entry of the
// block it was likely meant for (its siblings' level, with the line that shows it).
#include <string>

namespace tunica {

/// ", …" naming the cause and the fix for line `line` (1-based) of `text`, or "" where its
/// indentation fits the lines above it (the error lies elsewhere) or a multi-line flow
/// collection (`{`, `[` left open across lines) makes the block structure unclear.
std::string indentation_cause(const std::string& text, int line);

}  // namespace tunica
