// Fuzzes the inflation–extension data reader of `tunica fit` (CSV with units in
// the headers and the `# specimen:` line): any input must either be read or
// raise an InputError naming the file and line.
#include <cstdint>
#include <string>

#include "fit/inflation_data.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    (void)tunica::read_inflation_data_text(text, "fuzz.csv");
  } catch (const tunica::InputError&) {
  }
  return 0;
}
