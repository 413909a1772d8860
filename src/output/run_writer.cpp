#include "output/run_writer.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <map>
#include <sstream>
#include <stdexcept>

#include "core/bounded_file.hpp"
#include "assembly/contact_penetration.hpp"
#include "core/printable.hpp"
#include "elements/membrane_compression.hpp"
#include "output/jump_notes.hpp"
#include "linalg/compute_threads.hpp"
#include "output/atomic_file.hpp"
#include "output/history.hpp"
#include "output/output_folder.hpp"
#include "output/reference_mesh.hpp"
#include "output/stop_signal.hpp"

namespace tunica {

namespace {

constexpr const char* kFramesHeader = "series,frame,time,file,size_bytes,crc32\n";
constexpr std::size_t kMaxFramesCsvBytes = std::size_t{1} << 30;

std::string frame_file(const char* series, long frame) { return fmt::format("vtk/{}_{:06d}.vtu", series, frame); }

/// Errors unless the first line of `path` is `header` (the columns this deck writes).
void check_header(const std::string& path, const std::string& header) {
  const std::string head = read_file_bounded(path, 1 << 20, "file of the run to resume").substr(0, header.size() + 1);
  const std::string line = head.substr(0, head.find('\n'));
  if (line + "\n" != header)
    throw InputError({path, 1, 0, ""}, "its columns differ from what this deck writes:\n  file: " + line.substr(0, 400) +
                                           "\n  deck: " + header.substr(0, header.size() - 1));
}

const FileRecord* find_record(const RestartRecord& r, const std::string& name) {
  for (const auto& f : r.files)
    if (f.name == name) return &f;
  return nullptr;
}

}  // namespace

RunWriter::RunWriter(const Model& model, std::string directory, std::FILE* progress, const RestartRecord* resume)
    : model_(model), dir_(std::move(directory)), progress_(progress), resumed_(resume != nullptr) {
  std::error_code ec;
  const bool had_vtk = std::filesystem::exists(dir_ + "/vtk", ec);
  std::filesystem::create_directories(model.output.vtk ? dir_ + "/vtk" : dir_, ec);  // vtk/ only for frames
  if (ec) throw std::runtime_error("cannot create the output directory '" + dir_ + "': " + ec.message());
  history_header_ = "step,increment,time";
  for (const auto& r : model.output.history) history_header_ += "," + r.column;
  history_header_ += "\n";
  newton_header_ = "step,increment,attempt,iteration,time,residual,relative_residual,energy,relative_energy,"
                   "backtracks,active_contacts,active_changes,solver,threads,assembly_s,factor_s,solve_s\n";
  if (resume) {
    resume_from(*resume);
    return;
  }
  const int removed = remove_earlier_run(dir_);
  if (const std::string other = foreign_file(dir_); !other.empty()) {
    if (!had_vtk) std::filesystem::remove(dir_ + "/vtk", ec);  // the run leaves the folder as it found it
    throw std::runtime_error("'" + other + "' is not a file Tunica wrote (it does not start as Tunica's file of that "
                             "name does), and this run would write over it: move it away, or write the run into "
                             "another folder (-o)");
  }
  if (removed > 0 && progress_)
    std::fprintf(progress_, "removed the %d file(s) of an earlier Tunica run in %s\n", removed, dir_.c_str());
  history_.create(dir_, "history.csv", history_header_);
  newton_.create(dir_, "newton.csv", newton_header_);
}

void RunWriter::resume_from(const RestartRecord& r) {
  const std::string restart_file = dir_ + "/restart.txt";
  const FileRecord* history = find_record(r, "history.csv");
  const FileRecord* newton = find_record(r, "newton.csv");
  if (!history || !newton) throw InputError({restart_file, 0, 0, ""}, "records no history.csv or newton.csv");
  // The appended files: their recorded bytes unchanged; a tail written after the checkpoint is cut.
  for (const auto& f : r.files) verify_file(dir_, f, Tail::cut);
  check_header(dir_ + "/history.csv", history_header_);
  check_header(dir_ + "/newton.csv", newton_header_);
  history_.resume(dir_, *history);
  newton_.resume(dir_, *newton);
  history_rows_ = r.history_rows;
  newton_rows_ = r.newton_rows;
  frames_ = r.frames;
  if (frames_ > 0) {
    // Every frame the series list, exactly as frames.csv records it.
    const std::vector<std::string> series = model_.geometry == Geometry::axisymmetric
                                                ? std::vector<std::string>{"meridian", "surface"}
                                                : std::vector<std::string>{"surface"};
    const FileRecord* frames = find_record(r, "frames.csv");
    if (!frames) throw InputError({restart_file, 0, 0, ""}, "records frames but no frames.csv");
    std::istringstream in(read_file_bounded(dir_ + "/frames.csv", kMaxFramesCsvBytes, "frames.csv"));
    std::string line;
    std::getline(in, line);
    std::map<std::string, long> count;
    for (int row = 2; std::getline(in, line); ++row) {
      std::vector<std::string> w;
      std::istringstream fields(line);
      for (std::string x; std::getline(fields, x, ',');) w.push_back(x);
      if (w.size() != 6 || w[3].rfind("vtk/", 0) != 0 || w[3].find("..") != std::string::npos)
        throw InputError({dir_ + "/frames.csv", row, 0, ""}, "not a frame row of Tunica");
      std::uint64_t bytes = 0;
      std::uint32_t crc = 0;
      try {
        bytes = std::stoull(w[4]);
        crc = static_cast<std::uint32_t>(std::stoul(w[5], nullptr, 16));
      } catch (const std::exception&) {
        throw InputError({dir_ + "/frames.csv", row, 0, ""}, "not a frame row of Tunica");
      }
      verify_file(dir_, {w[3], bytes, crc}, Tail::refuse);
      ++count[w[0]];
    }
    for (const auto& name : series) {
      if (count[name] != frames_)
        throw InputError({dir_ + "/frames.csv", 0, 0, ""},
                         fmt::format("lists {} {} frame(s); the restart file records {}", count[name], name, frames_));
      const FileRecord* pvd = find_record(r, name + ".pvd");
      if (!pvd) throw InputError({restart_file, 0, 0, ""}, "records frames but no " + name + ".pvd");
      (name == "meridian" ? meridian_pvd_ : surface_pvd_).resume(dir_, *pvd, pvd_tail());
    }
    frames_csv_.resume(dir_, *frames);
  }
  remove_after_checkpoint(dir_, frames_);
}

void RunWriter::on_iteration(const IncrementInfo& info, const IterationRecord& r) {
  // The thread count on every row, not once above the columns: a restart may continue the rows with
  // another -j, and the timings beside it are what that count gave.
  newton_pending_ += fmt::format("{},{},{},{},{:.12g},{:.6e},{:.6e},{:.6e},{:.6e},{},{},{},{},{},{:.3e},{:.3e},{:.3e}\n", info.step,
                                 info.increment, info.attempt, r.iteration, info.time, r.residual, r.relative_residual,
                                 r.energy, r.relative_energy, r.backtracks, r.active_contacts, r.active_changes, r.solver,
                                 compute_threads(), r.assembly_seconds, r.factor_seconds, r.solve_seconds);
  ++newton_rows_;
  if (progress_)
    std::fprintf(progress_, "  step %d increment %d iteration %d  residual %.3e  relative %.3e\n", info.step,
                 info.increment, r.iteration, r.residual, r.relative_residual);
}

void RunWriter::on_fixed_point(const FixedPointRecord& rec) {
  const std::string unit = model_.units.display_unit(Dimension::length);
  const auto len = [&](double v) { return model_.units.from_internal(v, unit, Dimension::length); };
  if (fixed_point_rows_.empty())
    fixed_point_rows_ = fmt::format("step,iteration,max_distance_{0},rms_distance_{0},goal_{0},relaxation,increments,"
                                    "newton_iterations,cutbacks,seconds\n",
                                    unit);
  fixed_point_rows_ += fmt::format("{},{},{:.6e},{:.6e},{:.6e},{:.6g},{},{},{},{:.3f}\n", rec.step, rec.iteration,
                                   len(rec.max_distance), len(rec.rms_distance), len(rec.goal), rec.relaxation,
                                   rec.increments, rec.newton_iterations, rec.cutbacks, rec.seconds);
  write_file_atomically(dir_ + "/fixed_point.csv", fixed_point_rows_);
  if (progress_) {
    std::fprintf(progress_,
                 "step %d '%s' fixed-point iteration %d: max |x - x^| = %.3e %s (rms %.3e, goal %.3e) after %d "
                 "increment(s), %d Newton iteration(s), %.2f s\n",
                 rec.step, rec.step_name.c_str(), rec.iteration, len(rec.max_distance), unit.c_str(),
                 len(rec.rms_distance), len(rec.goal), rec.increments, rec.newton_iterations, rec.seconds);
    std::fflush(progress_);
  }
}

void RunWriter::on_cutback(const IncrementInfo& info, const std::string& why) {
  if (progress_)
    std::fprintf(progress_, "  step %d increment %d: %s; cutting the increment back\n", info.step, info.increment,
                 why.c_str());
}

void RunWriter::on_retry(const IncrementInfo& info, const std::string& why, const std::string& how) {
  if (progress_) std::fprintf(progress_, "  step %d increment %d: %s; %s\n", info.step, info.increment, why.c_str(), how.c_str());
}

bool RunWriter::wants_frame(const IncrementInfo& info) const {
  if (!model_.output.vtk) return false;
  // The reference state, every vtk_every-th increment of a step, and the end of each step.
  return info.step == 0 || info.increment % model_.output.vtk_every == 0 || info.fraction >= 1.0 - 1e-12;
}

void RunWriter::write_frame(const Analysis& analysis, const IncrementInfo& info) {
  std::string rows;
  const auto put = [&](const char* series, const std::string& text, AppendFile& pvd) {
    const std::string file = frame_file(series, frames_);
    write_file_atomically(dir_ + "/" + file, text, Durability::synced);
    rows += fmt::format("{},{},{:.12g},{},{},{:08x}\n", series, frames_, info.time, file, text.size(), crc32_of(text));
    if (!pvd.is_open()) pvd.create(dir_, std::string(series) + ".pvd", pvd_head(), pvd_tail());
    pvd.append(pvd_entry(info.time, file));
  };
  const VtkFormat format = model_.output.vtk_format;
  if (model_.geometry == Geometry::axisymmetric) {
    put("meridian", meridian_vtu(analysis, format), meridian_pvd_);
    put("surface", surface_vtu(analysis, model_.output.vtk_segments, format), surface_pvd_);
  } else {
    put("surface", surface3d_vtu(analysis, format), surface_pvd_);
  }
  if (!frames_csv_.is_open()) frames_csv_.create(dir_, "frames.csv", kFramesHeader);
  frames_csv_.append(rows);
  ++frames_;
}

void RunWriter::on_increment(const Analysis& analysis, const IncrementInfo& info) {
  const std::vector<double> values = history_values(analysis, info);
  std::string row = fmt::format("{},{},{:.12g}", info.step, info.increment, info.time);
  for (double v : values) row += fmt::format(",{:.12g}", v);
  history_.append(row + "\n");
  ++history_rows_;
  newton_.append(newton_pending_);
  newton_pending_.clear();
  // A run about to stop on request gets a frame of its last state too.
  last_info_ = info;
  last_framed_ = wants_frame(info) || (model_.output.vtk && stop_requested());
  if (last_framed_) write_frame(analysis, info);
  note_membrane_states(analysis, info);
  note_penetration(analysis, info);
  note_jumps(analysis, info);
  // The end of an inverse step: its zero-pressure geometry (reference_mesh.hpp), written before the
  // steps after it continue on it as their reference (Analysis): the deck's positions and its unknowns.
  if (info.step > 0 && info.fraction >= 1.0 - 1e-12 && model_.steps[info.step - 1].moves_reference())
    write_file_atomically(dir_ + "/" + reference_mesh_name(model_, info.step - 1),
                          reference_mesh_text(model_, analysis.displacement()));
  last_ = RestartRecord{analysis.checkpoint(), history_rows_, newton_rows_, frames_, model_.deck_file, {}, model_.fingerprint};
  for (AppendFile* f : {&history_, &newton_, &frames_csv_, &meridian_pvd_, &surface_pvd_})
    if (f->is_open()) last_->files.push_back(f->record());
  committed_ = false;
  // A checkpoint at the reference state, at the end of each step, when a stop was asked for,
  // and otherwise at most every output.checkpoint_every_s of wall-clock time; in between the
  // record waits (finish() commits it if the run ends there).
  const double since = std::chrono::duration<double>(std::chrono::steady_clock::now() - last_checkpoint_).count();
  if (info.step == 0 || info.fraction >= 1.0 - 1e-12 || stop_requested() || since >= model_.output.checkpoint_every_s)
    commit_checkpoint();
  if (progress_) {
    if (info.step == 0)
      std::fprintf(progress_, "reference state written\n");
    else
      std::fprintf(progress_, "step %d '%s' increment %d (fraction %.4g) converged in %d iteration(s)\n", info.step,
                   info.step_name.c_str(), info.increment, info.fraction, info.iterations);
    std::fflush(progress_);
  }
}

void RunWriter::note_membrane_states(const Analysis& analysis, const IncrementInfo& info) {
  if (info.step == 0) return;  // the reference state is unstressed and unstretched
  compression_noted_.resize(model_.parts.size(), 0);
  stretch_noted_.resize(model_.parts.size(), 0);
  const std::string when = fmt::format("at step {} '{}', increment {}", info.step, info.step_name, info.increment);
  // Every membrane part noted both ways: nothing to evaluate.
  bool pending = false;
  for (std::size_t p = 0; p < model_.parts.size(); ++p)
    pending = pending || (!model_.parts[p].is_solid() && !model_.parts[p].is_shell() &&
                          !(compression_noted_[p] && stretch_noted_[p]));
  if (!pending) return;
  // One evaluation of each part's points serves both notes (and every part's, the scale of load).
  std::vector<std::vector<MembranePoint>> points(model_.parts.size());
  double loaded = 0;  // the largest |principal stress| of any membrane part
  for (std::size_t p = 0; p < model_.parts.size(); ++p) {
    const Part& part = model_.parts[p];
    if (part.is_solid() || part.is_shell()) continue;
    points[p] = analysis.system().points(analysis.displacement(), static_cast<int>(p), analysis.loads().step);
    const CompressionSize size = compression_size(points[p]);
    loaded = std::max({loaded, size.tension, -size.compression});
  }
  for (std::size_t p = 0; p < model_.parts.size(); ++p) {
    if (points[p].empty() || (compression_noted_[p] && stretch_noted_[p])) continue;
    // A part whose stresses are all below kUnloadedShare of the most loaded part's is not loaded
    // yet: its signs are round-off and the way the load reaches it, not compression to note.
    const CompressionSize size = compression_size(points[p]);
    const bool unloaded = std::max(size.tension, -size.compression) < kUnloadedShare * loaded;
    if (!compression_noted_[p] && !unloaded) note_compression(p, points[p], info);
    if (!stretch_noted_[p]) {
      const std::string note = extreme_stretch_note(analysis.model(), static_cast<int>(p), points[p], when);
      if (note.empty()) continue;
      stretch_noted_[p] = 1;
      std::fprintf(stderr, "tunica: note: %s.\n", terminal_safe(note).c_str());
    }
  }
}

void RunWriter::note_compression(std::size_t p, const std::vector<MembranePoint>& points, const IncrementInfo& info) {
  const Part& part = model_.parts[p];
  const double f = compressed_fraction(points);
  if (f <= 0.01) return;
  compression_noted_[p] = 1;
  // How strong: the largest compression against the largest tension (or all compression).
  const CompressionSize size = compression_size(points);
  const auto kpa = [&](double s) { return model_.units.from_internal(s, "kPa", Dimension::pressure); };
  const std::string strength =
      size.tension > 0 && -size.compression > size.tension
          ? fmt::format("the largest compressive principal stress, {:.4g} kPa, exceeds the largest tension, {:.4g} kPa",
                        kpa(size.compression), kpa(size.tension))
      : size.tension > 0
          ? fmt::format("the largest compressive principal stress is {:.3g} % of the largest tension ({:.4g} kPa "
                        "against {:.4g} kPa)",
                        -100 * size.compression / size.tension, kpa(size.compression), kpa(size.tension))
          : fmt::format("no point is in tension; the largest compressive principal stress is {:.4g} kPa",
                        kpa(size.compression));
  std::fprintf(stderr,
               "tunica: note: part '%s' is in compression over %.1f %% of its area at step %d '%s', increment %d "
               "(a negative principal stress below -1 %% of the part's largest; %s): a real membrane wrinkles "
               "there, which Tunica does not model yet; its results there are those of a membrane that carries "
               "compression. The history quantity `compressed_fraction` and the ParaView field `compressed` show "
               "where.\n",
               terminal_safe(part.name).c_str(), 100 * f, info.step, terminal_safe(info.step_name).c_str(),
               info.increment, terminal_safe(strength).c_str());
}

void RunWriter::note_jumps(const Analysis& analysis, const IncrementInfo& info) {
  if (info.step == 0) return;
  const std::string when = fmt::format("at step {} '{}', increment {}", info.step, info.step_name, info.increment);
  jump_noted_.resize(model_.loads.size(), 0);
  for (std::size_t l = 0; l < model_.loads.size(); ++l) {
    if (jump_noted_[l]) continue;
    const std::string note =
        volume_jump_note(analysis.model(), static_cast<int>(l), info.step - 1, analysis.checkpoint().trace, when);
    if (note.empty()) continue;
    jump_noted_[l] = 1;
    std::fprintf(stderr, "tunica: note: %s.\n", terminal_safe(note).c_str());
  }
}

void RunWriter::note_penetration(const Analysis& analysis, const IncrementInfo& info) {
  if (info.step == 0) return;  // the reference state: the deck reader checks the sides
  penetration_noted_.resize(model_.contacts.size(), 0);
  touched_.resize(model_.contacts.size(), 0);
  for (std::size_t c = 0; c < model_.contacts.size(); ++c)
    if (!touched_[c])
      for (const ContactNodeState& s :
           analysis.system().contact_states(analysis.displacement(), static_cast<int>(c), info.step - 1))
        touched_[c] = touched_[c] || s.point.active;
  for (std::size_t c = 0; c < model_.contacts.size(); ++c) {
    if (penetration_noted_[c]) continue;
    const std::string w =
        far_penetration_warning(analysis.system(), analysis.displacement(), info.step - 1, static_cast<int>(c),
                                fmt::format("at step {} '{}', increment {}", info.step, info.step_name, info.increment));
    if (w.empty()) continue;
    penetration_noted_[c] = 1;
    std::fprintf(stderr, "tunica: warning: %s\n", terminal_safe(w).c_str());
  }
}

void RunWriter::commit_checkpoint() {
  if (!last_ || committed_) return;
  // Every file the restart file records is on disk before it is written: it never claims more.
  for (AppendFile* f : {&history_, &newton_, &frames_csv_, &meridian_pvd_, &surface_pvd_})
    if (f->is_open()) f->sync();
  write_file_atomically(dir_ + "/restart.txt", restart_text(*last_), Durability::synced);
  committed_ = true;
  last_checkpoint_ = std::chrono::steady_clock::now();
}

void RunWriter::finish(const Analysis& analysis) {
  if (last_ && !last_framed_ && model_.output.vtk) {
    // The last converged state (the analysis is still at it) as a ParaView frame, recorded in
    // its checkpoint; the appended history and Newton records stay those of the increment.
    write_frame(analysis, last_info_);
    last_framed_ = true;
    last_->frames = frames_;
    std::erase_if(last_->files, [](const FileRecord& f) {
      return f.name == "frames.csv" || f.name == "meridian.pvd" || f.name == "surface.pvd";
    });
    for (AppendFile* f : {&frames_csv_, &meridian_pvd_, &surface_pvd_})
      if (f->is_open()) last_->files.push_back(f->record());
    committed_ = false;
  }
  commit_checkpoint();
}

void RunWriter::note_untouched_contacts() const {
  if (resumed_ || touched_.size() != model_.contacts.size()) return;
  for (std::size_t c = 0; c < model_.contacts.size(); ++c) {
    const ContactPair& pair = model_.contacts[c];
    // A two-pass pair touched when either pass did.
    if (pair.is_reverse_pass() || touched_[c] || (pair.reverse >= 0 && touched_[pair.reverse])) continue;
    const std::string surface = pair.deformable() ? fmt::format("its master '{}'", pair.master_name)
                                                  : fmt::format("the rigid surface '{}'", model_.rigid_surfaces[pair.rigid].name);
    const std::string slave = pair.part >= 0 ? fmt::format("part '{}'", model_.parts[pair.part].name) : "its slave";
    // No load on the slave, one on the master's part: a load on the wrong part.
    std::string loads_on_slave, loads_elsewhere;
    for (const PressureLoad& l : model_.loads)
      (l.part == pair.part ? loads_on_slave : loads_elsewhere) +=
          fmt::format("'{}' on part '{}'; ", l.name, l.part >= 0 ? model_.parts[l.part].name : "?");
    std::string why;
    if (loads_on_slave.empty() && !loads_elsewhere.empty())
      why = fmt::format(" No load acts on {} (the loads: {}): if it was to be pressed onto {}, check the loads' `part`.",
                        slave, loads_elsewhere.substr(0, loads_elsewhere.size() - 2), surface);
    std::fprintf(stderr,
                 "tunica: note: contact pair '%s' never touched: no node of %s came within its offset of %s at any "
                 "converged increment, so the pair had no effect on the results.%s\n",
                 terminal_safe(pair.name).c_str(), terminal_safe(slave).c_str(), terminal_safe(surface).c_str(),
                 terminal_safe(why).c_str());
  }
}

RunWriter::~RunWriter() {
  try {
    commit_checkpoint();
  } catch (...) {  // the run is ending on another error already; the last committed checkpoint stands
  }
}

bool RunWriter::stop_requested() { return stop_signal() != 0; }

void RunWriter::write_newton_log() {
  newton_.append(newton_pending_);
  newton_pending_.clear();
}

}  // namespace tunica
