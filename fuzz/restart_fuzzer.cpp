// Fuzzes the restart-file reader: any input must either parse or raise an
// InputError naming the file and line.
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <string>

#include "output/restart_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string path = "/tmp/tunica-restart-fuzz-" + std::to_string(getpid()) + ".txt";
  if (FILE* f = std::fopen(path.c_str(), "wb")) {
    std::fwrite(data, 1, size, f);
    std::fclose(f);
  }
  try {
    (void)tunica::read_restart(path);
  } catch (const tunica::InputError&) {
  }
  return 0;
}
