// Fuzzes the deck reader with its validation and units: any input must either
// build a Model or raise an InputError; any other exception, crash, hang or
// leak is a bug. Small models also get their DOF map and sparsity pattern.
#include <cstdint>
#include <string>

#include "assembly/system.hpp"
#include "io/deck.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const tunica::Model model = tunica::read_deck_text(text, "fuzz.yaml");
    if (model.num_nodes() <= 20000) tunica::System system(model);
  } catch (const tunica::InputError&) {
  }
  return 0;
}
