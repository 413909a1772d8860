#pragma once
// System::for_each_coloured (system.hpp), shared by the assembly files
// (system.cpp, system_shell.cpp): each colour of a block is one OpenMP loop.
#include <exception>

#include "assembly/system.hpp"

namespace tunica {

template <class Kernel>
void System::for_each_coloured(const Block& data, Kernel&& kernel) {
  std::exception_ptr error;
  int error_element = -1;
  // Small colours run on one thread: below ~1000 elements the fork/join costs more than it saves.
  constexpr int kMinParallel = 1024;
  for (std::size_t c = 0; c + 1 < data.colour_start.size(); ++c) {
    const int begin = data.colour_start[c], end = data.colour_start[c + 1];
#pragma omp parallel for schedule(static) if (end - begin >= kMinParallel)
    for (int k = begin; k < end; ++k) {
      const int e = data.order[k];
      try {
        kernel(e);
      } catch (...) {
#pragma omp critical(tunica_assembly_error)
        if (error_element < 0 || e < error_element) {
          error = std::current_exception();
          error_element = e;
        }
      }
    }
    if (error) std::rethrow_exception(error);
  }
}

}  // namespace tunica
