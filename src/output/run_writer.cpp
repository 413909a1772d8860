#include "output/run_writer.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <stdexcept>

#include "output/atomic_file.hpp"
#include "output/history.hpp"

namespace tunica {

RunWriter::RunWriter(const Model& model, std::string directory, std::FILE* progress)
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
            "assembly_s,solve_s\n";
}

void RunWriter::on_iteration(const IncrementInfo& info, const IterationRecord& r) {
  newton_ += fmt::format("{},{},{},{},{:.12g},{:.6e},{:.6e},{:.6e},{:.6e},{:.3e},{:.3e}\n", info.step, info.increment,
                         info.attempt, r.iteration, info.time, r.residual, r.relative_residual, r.energy,
                         r.relative_energy, r.assembly_seconds, r.solve_seconds);
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
  write_file_atomically(dir_ + "/history.csv", history_);
  write_file_atomically(dir_ + "/newton.csv", newton_);
  if (model_.output.vtk) {
    const std::string m = fmt::format("vtk/meridian_{:06d}.vtu", frame_);
    const std::string s = fmt::format("vtk/surface_{:06d}.vtu", frame_);
    write_file_atomically(dir_ + "/" + m, meridian_vtu(analysis));
    write_file_atomically(dir_ + "/" + s, surface_vtu(analysis, model_.output.vtk_segments));
    meridian_.add(info.time, m);
    surface_.add(info.time, s);
  }
  ++frame_;
  if (progress_) {
    if (info.step == 0)
      std::fprintf(progress_, "reference state written\n");
    else
      std::fprintf(progress_, "step %d '%s' increment %d (fraction %.4g) converged in %d iteration(s)\n", info.step,
                   info.step_name.c_str(), info.increment, info.fraction, info.iterations);
    std::fflush(progress_);
  }
}

}  // namespace tunica
