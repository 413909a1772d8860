#pragma once
// A meridian read from a CSV file of nodes, as an axisymmetric inverse step writes its zero-pressure
// geometry (`reference_<step>.csv`, output/reference_mesh.hpp):
//     node,R_<unit>,Z_<unit>
//     1,<R>,<Z>
//     ...
// node numbers 1, 2, 3, ... in order, <unit> a length unit. The file is data: every line is checked,
// and an error names the file and the line as written.
#include <string>

#include "mesh/meridian.hpp"
#include "params/units.hpp"

namespace tunica {

/// The largest meridian CSV file read (bytes).
constexpr std::size_t kMaxMeridianCsvBytes = std::size_t{256} << 20;

/// The nodes `first` … `last` (node numbers as written; 0, 0 for all) of the meridian CSV `text` of
/// file `file`, in the model's length unit. Throws InputError({file, line, column}) for a header
/// other than node,R_<unit>,Z_<unit> (the same length unit twice), a line without three fields, a
/// node number out of order, a value that is not a finite number, or a range the file does not hold.
Meridian parse_meridian_csv(const std::string& text, const std::string& file, const UnitSystem& units, long first,
                            long last);

}  // namespace tunica
