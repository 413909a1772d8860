#pragma once
// One run per output folder: `DIR/.tunica.lock`, locked with flock(LOCK_EX |
// LOCK_NB) for the whole life of the run (fresh or --restart). A second run
// into a locked folder is refused at once, before it reads or writes anything
// there. The kernel releases the lock when the process ends, however it ends
// (a SIGKILL included), so a stale lock file never blocks a later run.
#include <string>

namespace tunica {

class OutputLock {
public:
  /// Locks `directory`, creating it first if `create` (a fresh run). Throws InputError naming
  /// the folder when another process holds the lock, or when the folder does not exist and
  /// `create` is false (a restart of nothing).
  OutputLock(const std::string& directory, bool create);
  ~OutputLock();
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;

  /// The name of the lock file inside the folder.
  static constexpr const char* kFileName = ".tunica.lock";

private:
  int fd_ = -1;
};

}  // namespace tunica
