#pragma once
// A reader of Gmsh .msh files of its own, for the formats Gmsh writes by
// default and on request: 4.1 and 2.2 (2.0, 2.1), ASCII and binary. The file is
// data only: nothing in it is executed, and every count it announces is checked
// against the limits below and against the bytes left in the file before
// anything is allocated. Unknown sections are skipped. No interpretation
// beyond the syntax happens here (msh_surface.hpp does that).
#include <cstddef>
#include <string>
#include <string_view>

#include "mesh/msh_file.hpp"

namespace tunica {

constexpr long kMaxMshNodes = 10'000'000;     ///< nodes a .msh file may hold (the model's node limit)
constexpr long kMaxMshElements = 40'000'000;  ///< elements of all dimensions
constexpr std::size_t kMaxMshBytes = 2'000'000'000;  ///< 2 GB (line numbers stay within int)

/// Parses `bytes`, the contents of the file `path` (named in messages). Throws InputError
/// (file = path; line = the line in an ASCII file, 0 once binary data has been read) on
/// a file that does not begin with $MeshFormat, an unsupported version, a malformed or
/// truncated section, a count beyond the limits or the file's size, an unknown element
/// type, a missing $Nodes or $Elements section, or a section given twice.
/// With `lines` false, no line numbers are recorded or reported (for a file the user
/// did not write, such as the mesh Gmsh makes of a script).
MshFile parse_msh(std::string_view bytes, const std::string& path, bool lines = true);

}  // namespace tunica
