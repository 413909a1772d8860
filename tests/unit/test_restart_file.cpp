// restart.txt keeps the step's converged states that the hints of a failure read (their
// pressures and volumes, solver/step_trace.hpp), reads them back, refuses a trace that cannot be
// one, and still reads the files of format 4, written before it kept them, and of format 5, written
// before it recorded the reference an inverse step computed (Checkpoint::reference_shift).
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <filesystem>
#include <fstream>

#include "core/errors.hpp"
#include "output/file_manifest.hpp"
#include "output/restart_file.hpp"
#include "../support/capture.hpp"
#include "../support/scratch.hpp"

using namespace tunica;

namespace {

/// A record of one load whose step has converged `count` states along p = V.
RestartRecord record(int count) {
  RestartRecord r;
  r.deck = "d.yaml";
  Checkpoint& c = r.checkpoint;
  c.step = 1;
  c.fraction = 0.5;
  c.u = Eigen::VectorXd::Zero(4);
  c.loads.boundary = c.step_start.boundary = {0.0};
  c.loads.pressure = c.step_start.pressure = {1.0};
  c.loads.volume = c.step_start.volume = {1.0};
  for (int k = 0; k < count; ++k) {
    LoadState s;
    s.pressure = {0.1 * k};
    s.volume = {1.0 + k};
    if (k == 0) c.trace.restart_at(s);
    else c.trace.push(s);
  }
  return r;
}

std::string write(const std::string& name, const std::string& text) {
  const std::string path = (test::scratch("restart-file") / name).string();
  std::ofstream(path) << text;
  return path;
}

}  // namespace

TEST(RestartFile, TheStepTraceIsKeptAndReadBack) {
  const RestartRecord r = read_restart(write("seven.txt", restart_text(record(7))));
  const StepTrace& t = r.checkpoint.trace;
  EXPECT_EQ(t.count(), 7);
  ASSERT_EQ(t.kept().size(), 5u);
  EXPECT_EQ(t.first(0).pressure, std::vector<double>{0.0});
  EXPECT_EQ(t.first(1).volume, std::vector<double>{2.0});
  EXPECT_EQ(t.last(2).pressure, std::vector<double>{0.1 * 4});
  EXPECT_EQ(t.last(0).volume, std::vector<double>{7.0});
}

TEST(RestartFile, ATraceThatCannotBeOneIsRefused) {
  // Seven states keep five: a file claiming three of them kept has been made by hand.
  std::string text = restart_text(record(7));
  text = text.substr(0, text.rfind("checksum "));
  text = test::replace(text, "trace 7 5\n", "trace 3 5\n");
  const std::string path = write("three.txt", text + fmt::format("checksum {:08x}\n", crc32_of(text)));
  try {
    read_restart(path);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("malformed restart file: a step trace of 3 states keeps 3, not 5"),
              std::string::npos)
        << e.what();
  }
}

TEST(RestartFile, AFileOfFormat4IsReadWithoutATrace) {
  // What Tunica wrote before it kept the trace: the run continues, its hints start afresh.
  std::string text = restart_text(record(7));
  text = text.substr(0, text.rfind("checksum "));
  text = test::replace(text, "tunica-restart 8\n", "tunica-restart 4\n");
  const std::size_t from = text.find("trace "), to = text.find("\nu ") + 1;
  text.erase(from, to - from);
  text.erase(text.find("reference_shift "));
  const RestartRecord r = read_restart(write("format4.txt", text + fmt::format("checksum {:08x}\n", crc32_of(text))));
  EXPECT_EQ(r.checkpoint.trace.count(), 0);
  EXPECT_EQ(r.checkpoint.loads.pressure, std::vector<double>{1.0});
}

TEST(RestartFile, AFileOfFormat5IsReadWithoutAReferenceShift) {
  // What Tunica wrote before steps could follow an inverse step: no reference of its own.
  std::string text = restart_text(record(7));
  text = text.substr(0, text.rfind("checksum "));
  text = test::replace(text, "tunica-restart 8\n", "tunica-restart 5\n");
  text.erase(text.find("reference_shift "));
  const RestartRecord r = read_restart(write("format5.txt", text + fmt::format("checksum {:08x}\n", crc32_of(text))));
  EXPECT_EQ(r.checkpoint.reference_shift.size(), 0);
  EXPECT_EQ(r.checkpoint.trace.count(), 7);
}

TEST(RestartFile, AFileOfFormat6IsReadWithoutAPrestress) {
  // What Tunica wrote before the prestress method of inverse steps.
  std::string text = restart_text(record(7));
  text = text.substr(0, text.rfind("checksum "));
  text = test::replace(text, "tunica-restart 8\n", "tunica-restart 6\n");
  text.erase(text.find("prestress "));
  const RestartRecord r = read_restart(write("format6.txt", text + fmt::format("checksum {:08x}\n", crc32_of(text))));
  EXPECT_TRUE(r.checkpoint.prestress.empty());
  EXPECT_EQ(r.checkpoint.trace.count(), 7);
}

TEST(RestartFile, AFileOfFormat7IsReadWithoutAContactSmoothing) {
  // What Tunica wrote before it smoothed a chattering contact by itself.
  std::string text = restart_text(record(7));
  text = text.substr(0, text.rfind("checksum "));
  text = test::replace(text, "tunica-restart 8\n", "tunica-restart 7\n");
  text.erase(text.find("contact_smoothing "));
  const RestartRecord r = read_restart(write("format7.txt", text + fmt::format("checksum {:08x}\n", crc32_of(text))));
  EXPECT_TRUE(r.checkpoint.contact_smoothing.empty());
  EXPECT_EQ(r.checkpoint.trace.count(), 7);
}

TEST(RestartFile, TheContactSmoothingIsReadBack) {
  RestartRecord rec = record(7);
  rec.checkpoint.contact_smoothing = {0.0, 1.8e-4, 2.5e-4};
  const RestartRecord r = read_restart(write("smoothing.txt", restart_text(rec)));
  EXPECT_EQ(r.checkpoint.contact_smoothing, rec.checkpoint.contact_smoothing);
}

TEST(RestartFile, APrestressIsReadBack) {
  RestartRecord rec = record(7);
  rec.checkpoint.prestress = {1.1, 0.01, -0.02, 1.2, 0.3, 1.0, 0.0, 0.0, 1.0, 0.25};
  const RestartRecord r = read_restart(write("prestress.txt", restart_text(rec)));
  EXPECT_EQ(r.checkpoint.prestress, rec.checkpoint.prestress);
}

TEST(RestartFile, TheReferenceShiftOfAnInverseStepIsKeptBitForBit) {
  RestartRecord rec = record(7);
  rec.checkpoint.reference_shift = Eigen::VectorXd::Constant(rec.checkpoint.u.size(), 1.0 / 3.0);
  const RestartRecord r = read_restart(write("shift.txt", restart_text(rec)));
  ASSERT_EQ(r.checkpoint.reference_shift.size(), rec.checkpoint.u.size());
  EXPECT_EQ(r.checkpoint.reference_shift, rec.checkpoint.reference_shift);
}
