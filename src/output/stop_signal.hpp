#pragma once
// SIGINT and SIGTERM ask a run to stop after the increment it is solving: the
// handler only records the signal; the run checks it between increments.

namespace tunica {

/// Installs handlers for SIGINT and SIGTERM that record the signal.
void install_stop_handlers();
/// The signal received (0 if none).
int stop_signal();

}  // namespace tunica
