// Fuzzes Tunica's .msh reader (4.1 and 2.2, ASCII and binary) with the mesh checks
// and the direction view: any input must either give a SurfaceMesh or raise an
// InputError whose message is one printable line (ASCII or well-formed UTF-8); any other exception, crash, hang
// or leak is a bug.
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "core/errors.hpp"
#include "core/printable.hpp"
#include "mesh/msh_parser.hpp"
#include "mesh/msh_surface.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  for (const char* view : {"", "fibre"}) {
    try {
      const tunica::MshFile f = tunica::parse_msh(bytes, "fuzz.msh");
      tunica::surface_mesh_from_msh(f, "fuzz.msh", view);
    } catch (const tunica::InputError& e) {
      if (!tunica::is_printable_line(e.what())) std::abort();
    }
  }
  return 0;
}
