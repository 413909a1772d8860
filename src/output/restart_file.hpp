#pragma once
// The restart file `restart.txt` in a run's output directory: the Checkpoint
// of the last converged increment (values as hexadecimal floating point, so a
// resumed run continues bit for bit), the manifest of the files the run
// continues from (file_manifest.hpp: each with its recorded byte length and
// CRC-32) and, last, the CRC-32 of its own content. It is written atomically
// and synced, after every file it records has been synced, so it never claims
// more than the other files hold. Its size does not grow with the run: the
// ParaView frames are listed in frames.csv, which the manifest records.
#include <string>
#include <vector>

#include "output/file_manifest.hpp"
#include "solver/analysis.hpp"

namespace tunica {

struct RestartRecord {
  Checkpoint checkpoint;
  int history_rows = 0;            ///< data rows of history.csv
  int newton_rows = 0;             ///< data rows of newton.csv
  long frames = 0;                 ///< ParaView frames written (rows of each series in frames.csv)
  std::string deck;                ///< path of the deck the run was started with
  std::vector<FileRecord> files;   ///< history.csv, newton.csv and, with frames, frames.csv and the .pvd files
  /// What the converged states depend on (io/deck_fingerprint.hpp), as the run's deck had it.
  std::vector<FingerprintEntry> fingerprint;
  /// False for a restart file of format 3, written before fingerprints: nothing to compare.
  bool has_fingerprint = true;
};

/// Text of a restart file.
std::string restart_text(const RestartRecord& r);
/// Reads a restart file (at most 1 GiB); throws InputError naming the file and line if it is
/// malformed, or naming the file if its checksum does not match its content (it was edited).
RestartRecord read_restart(const std::string& path);
/// The largest restart file read_restart accepts.
constexpr std::size_t kMaxRestartBytes = std::size_t{1} << 30;

}  // namespace tunica
