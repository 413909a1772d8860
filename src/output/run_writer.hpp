#pragma once
// What `tunica run` writes into its output directory, increment by increment:
//   history.csv   one row per converged increment (and the reference state),
//   newton.csv    one row per Newton iteration,
//   meridian.pvd / surface.pvd and vtk/*.vtu   ParaView series,
// and the progress lines on the terminal. Every file is rewritten atomically
// after each increment, so a stopped run leaves complete files.
#include <cstdio>
#include <string>

#include "output/vtk_writer.hpp"
#include "solver/analysis.hpp"

namespace tunica {

class RunWriter final : public AnalysisObserver {
public:
  /// Creates `directory` (and vtk/ in it). `progress` receives the terminal lines (nullptr = quiet).
  RunWriter(const Model& model, std::string directory, std::FILE* progress);

  void on_iteration(const IncrementInfo& info, const IterationRecord& rec) override;
  void on_cutback(const IncrementInfo& info, const std::string& why) override;
  void on_increment(const Analysis& analysis, const IncrementInfo& info) override;

private:
  const Model& model_;
  std::string dir_;
  std::FILE* progress_;
  std::string history_, newton_;
  PvdSeries meridian_, surface_;
  int frame_ = 0;
};

}  // namespace tunica
