#pragma once
// The restart file `restart.txt` in a run's output directory: the Checkpoint
// of the last converged increment (values as hexadecimal floating point, so a
// resumed run continues bit for bit) and how many rows and frames the other
// output files held at that moment. It is written atomically, last, after each
// increment, so it never claims more than the other files hold.
#include <string>
#include <vector>

#include "solver/analysis.hpp"

namespace tunica {

struct RestartRecord {
  Checkpoint checkpoint;
  int history_rows = 0;              ///< data rows of history.csv
  int newton_rows = 0;               ///< data rows of newton.csv
  std::vector<double> frame_times;   ///< times of the ParaView frames written
  std::string deck;                  ///< path of the deck the run was started with
};

/// Text of a restart file.
std::string restart_text(const RestartRecord& r);
/// Reads a restart file; throws InputError naming the file and line if it is malformed.
RestartRecord read_restart(const std::string& path);

}  // namespace tunica
