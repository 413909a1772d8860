#pragma once
// What `tunica run` writes into its output directory, increment by increment:
//   history.csv   one row per converged increment (and the reference state),
//   newton.csv    one row per Newton iteration,
//   meridian.pvd / surface.pvd and vtk/*.vtu   ParaView series,
// restart.txt (see restart_file.hpp) and the progress lines on the terminal.
// Every file is rewritten atomically after each increment, restart.txt last,
// so a stopped or killed run leaves complete files and can be resumed.
#include <cstdio>
#include <string>

#include "output/restart_file.hpp"
#include "output/vtk_writer.hpp"
#include "solver/analysis.hpp"

namespace tunica {

class RunWriter final : public AnalysisObserver {
public:
  /// Creates `directory` (and vtk/ in it). `progress` receives the terminal lines (nullptr = quiet).
  /// With `resume`, continues the files of an earlier run in `directory`, cut back to what
  /// its restart file records.
  RunWriter(const Model& model, std::string directory, std::FILE* progress, const RestartRecord* resume = nullptr);

  void on_iteration(const IncrementInfo& info, const IterationRecord& rec) override;
  void on_cutback(const IncrementInfo& info, const std::string& why) override;
  void on_increment(const Analysis& analysis, const IncrementInfo& info) override;
  /// True once SIGINT or SIGTERM has been received.
  bool stop_requested() override;
  /// Writes newton.csv with the attempts since the last converged increment (for a run that stops).
  void write_newton_log();

private:
  const Model& model_;
  std::string dir_;
  std::FILE* progress_;
  std::string history_, newton_;
  int history_rows_ = 0, newton_rows_ = 0;
  PvdSeries meridian_, surface_;
  std::vector<double> frame_times_;
};

}  // namespace tunica
