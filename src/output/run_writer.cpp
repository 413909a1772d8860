#include "output/run_writer.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "output/atomic_file.hpp"
#include "output/history.hpp"
#include "output/stop_signal.hpp"

namespace tunica {

namespace {

/// The first `rows` data rows of a CSV file written by an earlier run, after checking its header.
std::string csv_prefix(const std::string& path, const std::string& header, int rows) {
  std::ifstream in(path);
  if (!in) throw InputError({path, 0, 0, ""}, "cannot read the file of the run to resume");
  std::string line, out;
  if (!std::getline(in, line) || line + "\n" != header)
    throw InputError({path, 1, 0, ""}, "its columns differ from what this deck writes:\n  file: " + line +
                                           "\n  deck: " + header.substr(0, header.size() - 1));
  out = header;
  for (int k = 0; k < rows; ++k) {
    if (!std::getline(in, line)) throw InputError({path, k + 2, 0, ""}, "holds fewer rows than the restart file records");
    out += line + "\n";
  }
  return out;
}

std::string frame_file(const char* series, std::size_t frame) { return fmt::format("vtk/{}_{:06d}.vtu", series, frame); }

}  // namespace

RunWriter::RunWriter(const Model& model, std::string directory, std::FILE* progress, const RestartRecord* resume)
    : model_(model),
      dir_(std::move(directory)),
      progress_(progress),
      meridian_(dir_ + "/meridian.pvd"),
      surface_(dir_ + "/surface.pvd") {
  std::error_code ec;
  std::filesystem::create_directories(dir_ + "/vtk", ec);
  if (ec) throw std::runtime_error("cannot create the output directory '" + dir_ + "': " + ec.message());
  history_ = "step,increment,time";
  for (const auto& r : model.output.history) history_ += "," + r.column;
  history_ += "\n";
  newton_ = "step,increment,attempt,iteration,time,residual,relative_residual,energy,relative_energy,"
            "backtracks,active_contacts,active_changes,solver,assembly_s,factor_s,solve_s\n";
  if (resume) {
    history_ = csv_prefix(dir_ + "/history.csv", history_, resume->history_rows);
    newton_ = csv_prefix(dir_ + "/newton.csv", newton_, resume->newton_rows);
    history_rows_ = resume->history_rows;
    newton_rows_ = resume->newton_rows;
    frame_times_ = resume->frame_times;
    for (std::size_t f = 0; f < frame_times_.size(); ++f) {
      if (model_.geometry == Geometry::axisymmetric) meridian_.preload(frame_times_[f], frame_file("meridian", f));
      surface_.preload(frame_times_[f], frame_file("surface", f));
    }
  }
}

void RunWriter::on_iteration(const IncrementInfo& info, const IterationRecord& r) {
  newton_ += fmt::format("{},{},{},{},{:.12g},{:.6e},{:.6e},{:.6e},{:.6e},{},{},{},{},{:.3e},{:.3e},{:.3e}\n", info.step,
                         info.increment, info.attempt, r.iteration, info.time, r.residual, r.relative_residual,
                         r.energy, r.relative_energy, r.backtracks, r.active_contacts, r.active_changes, r.solver,
                         r.assembly_seconds, r.factor_seconds, r.solve_seconds);
  ++newton_rows_;
  if (progress_)
    std::fprintf(progress_, "  step %d increment %d iteration %d  residual %.3e  relative %.3e\n", info.step,
                 info.increment, r.iteration, r.residual, r.relative_residual);
}

void RunWriter::on_cutback(const IncrementInfo& info, const std::string& why) {
  if (progress_)
    std::fprintf(progress_, "  step %d increment %d: %s; cutting the increment back\n", info.step, info.increment,
                 why.c_str());
}

void RunWriter::on_increment(const Analysis& analysis, const IncrementInfo& info) {
  const std::vector<double> values = history_values(analysis, info);
  history_ += fmt::format("{},{},{:.12g}", info.step, info.increment, info.time);
  for (double v : values) history_ += fmt::format(",{:.12g}", v);
  history_ += "\n";
  ++history_rows_;
  write_file_atomically(dir_ + "/history.csv", history_);
  write_file_atomically(dir_ + "/newton.csv", newton_);
  if (model_.output.vtk) {
    const std::size_t frame = frame_times_.size();
    if (model_.geometry == Geometry::axisymmetric) {
      write_file_atomically(dir_ + "/" + frame_file("meridian", frame), meridian_vtu(analysis));
      write_file_atomically(dir_ + "/" + frame_file("surface", frame), surface_vtu(analysis, model_.output.vtk_segments));
      meridian_.add(info.time, frame_file("meridian", frame));
    } else {
      write_file_atomically(dir_ + "/" + frame_file("surface", frame), surface3d_vtu(analysis));
    }
    surface_.add(info.time, frame_file("surface", frame));
    frame_times_.push_back(info.time);
  }
  // Last: the restart file never claims more than the other files hold.
  RestartRecord r{analysis.checkpoint(), history_rows_, newton_rows_, frame_times_, model_.deck_file};
  write_file_atomically(dir_ + "/restart.txt", restart_text(r));
  if (progress_) {
    if (info.step == 0)
      std::fprintf(progress_, "reference state written\n");
    else
      std::fprintf(progress_, "step %d '%s' increment %d (fraction %.4g) converged in %d iteration(s)\n", info.step,
                   info.step_name.c_str(), info.increment, info.fraction, info.iterations);
    std::fflush(progress_);
  }
}

bool RunWriter::stop_requested() { return stop_signal() != 0; }

void RunWriter::write_newton_log() { write_file_atomically(dir_ + "/newton.csv", newton_); }

}  // namespace tunica
