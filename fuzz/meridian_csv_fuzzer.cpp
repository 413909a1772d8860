// Fuzzes the meridian CSV reader (`mesh: {type: points, file: ...}`, mesh/meridian_csv.hpp): any
// input must either be read or raise an InputError naming the file and line.
#include <cstdint>
#include <string>

#include "core/errors.hpp"
#include "mesh/meridian_csv.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  static const tunica::UnitSystem units("mm", "N");
  try {
    (void)tunica::parse_meridian_csv(text, "fuzz.csv", units, 0, 0);
    (void)tunica::parse_meridian_csv(text, "fuzz.csv", units, 2, 4);
  } catch (const tunica::InputError&) {
  }
  return 0;
}
