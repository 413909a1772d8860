#pragma once
// What `tunica run` writes into its output directory, increment by increment:
//   history.csv   one row per converged increment (and the reference state),
//   newton.csv    one row per Newton iteration,
//   meridian.pvd / surface.pvd and vtk/*.vtu   ParaView series (output.vtk_every),
//   frames.csv    one row per .vtu frame file: its byte length and CRC-32,
//   fixed_point.csv   one row per iteration of a fixed-point inverse step (Analysis, FixedPointRecord),
// restart.txt (see restart_file.hpp) and the progress lines on the terminal.
// The CSV files and the .pvd series are appended (append_file.hpp) and each frame
// is written atomically. At a checkpoint all are synced, and then restart.txt is
// rewritten atomically (synced) with the length and CRC-32 of each: a stopped or
// killed run leaves files a restart can check and continue. Checkpoints are taken
// at the reference state, at the end of each step, when a stop is asked for, when
// the run ends on an error (finish(), or the destructor), and otherwise at most
// every output.checkpoint_every_s seconds, so that a run of many small increments
// does not wait for the disk at each. The caller holds the
// folder's lock (output_lock.hpp) for the writer's whole life.
#include <chrono>
#include <cstdio>
#include <optional>
#include <string>

#include "output/append_file.hpp"
#include "output/restart_file.hpp"
#include "output/vtk_writer.hpp"
#include "solver/analysis.hpp"

namespace tunica {

class RunWriter final : public AnalysisObserver {
public:
  /// Creates `directory` (and vtk/ in it). `progress` receives the terminal lines (nullptr = quiet).
  /// A fresh run first removes the files of an earlier run there (output_folder.hpp). With
  /// `resume`, checks every file its restart file records (InputError naming a damaged file),
  /// cuts them back to the recorded lengths and continues them.
  RunWriter(const Model& model, std::string directory, std::FILE* progress, const RestartRecord* resume = nullptr);
  /// Commits the last converged increment's checkpoint if it is still waiting.
  ~RunWriter() override;

  void on_iteration(const IncrementInfo& info, const IterationRecord& rec) override;
  void on_cutback(const IncrementInfo& info, const std::string& why) override;
  void on_retry(const IncrementInfo& info, const std::string& why, const std::string& how) override;
  void on_increment(const Analysis& analysis, const IncrementInfo& info) override;
  /// A row of fixed_point.csv (rewritten whole, atomically: a fixed-point step is redone from its
  /// start by a restart) and a progress line.
  void on_fixed_point(const FixedPointRecord& rec) override;
  /// True once SIGINT or SIGTERM has been received.
  bool stop_requested() override;
  /// Appends the attempts since the last converged increment to newton.csv (for a run that stops).
  void write_newton_log();
  /// A run that stops on an error, with `analysis` still at its last converged increment:
  /// writes that state's ParaView frame if output.vtk_every skipped it, and commits its
  /// checkpoint if it is still waiting (the attempts written after it are not part of it).
  void finish(const Analysis& analysis);
  /// After a run that reached its end from the reference state: a note on standard error per
  /// contact pair whose slave never touched its surface (no active node at any converged
  /// increment), naming the loads when none acts on the slave but one on its master (a load on
  /// the wrong part).
  void note_untouched_contacts() const;

private:
  void resume_from(const RestartRecord& r);
  /// Syncs every file and writes restart.txt from last_, unless it is committed already.
  void commit_checkpoint();
  void write_frame(const Analysis& analysis, const IncrementInfo& info);
  bool wants_frame(const IncrementInfo& info) const;
  /// The notes on a membrane part's state, from one evaluation of its points: the first time it is
  /// in compression over more than 1 % of its reference area (elements/membrane_compression.hpp),
  /// and the first time it is stretched or crushed beyond what a membrane reaches
  /// (output/jump_notes.hpp); each once per part.
  void note_membrane_states(const Analysis& analysis, const IncrementInfo& info);
  /// The compression note on part `p`, if its points call for it.
  void note_compression(std::size_t p, const std::vector<MembranePoint>& points, const IncrementInfo& info);
  /// The first time a contact pair's penetration is far beyond the penalty's scale, a warning on
  /// standard error at the pair (assembly/contact_penetration.hpp), once per pair.
  void note_penetration(const Analysis& analysis, const IncrementInfo& info);
  /// The first time a load's volume jumps onto a far branch of its curve: a note on standard
  /// error (output/jump_notes.hpp), once per load.
  void note_jumps(const Analysis& analysis, const IncrementInfo& info);

  const Model& model_;
  std::string dir_;
  std::FILE* progress_;
  std::string history_header_, newton_header_;
  std::string newton_pending_;  ///< rows since the last converged increment
  std::string fixed_point_rows_;  ///< fixed_point.csv of the fixed-point inverse step
  int history_rows_ = 0, newton_rows_ = 0;
  long frames_ = 0;
  AppendFile history_, newton_, frames_csv_, meridian_pvd_, surface_pvd_;
  std::optional<RestartRecord> last_;  ///< the last converged increment's record
  bool committed_ = false;             ///< last_ is in restart.txt
  IncrementInfo last_info_;            ///< the last converged increment
  bool last_framed_ = false;           ///< it has its ParaView frame
  std::vector<char> compression_noted_;  ///< per part
  std::vector<char> penetration_noted_;  ///< per contact pair
  std::vector<char> touched_;            ///< per contact pair: an active slave node at some increment
  bool resumed_ = false;                 ///< the run continues a restart: touched_ misses its start
  std::vector<char> jump_noted_;         ///< per load
  std::vector<char> stretch_noted_;      ///< per part
  std::chrono::steady_clock::time_point last_checkpoint_ = std::chrono::steady_clock::now();
};

}  // namespace tunica
