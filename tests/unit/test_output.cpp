// What `tunica run` writes: history.csv with the requested columns (units in
// the names), newton.csv, and ParaView series whose frames hold the model's
// points, cells and fields; the revolved surface lies at the radius history.csv reports.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <unistd.h>

#include "../support/capture.hpp"
#include "../support/vtu.hpp"

using namespace tunica::test;
namespace fs = std::filesystem;

namespace {

fs::path run_example() {
  static const fs::path out = [] {
    const fs::path dir = fs::temp_directory_path() / ("tunica-output-test-" + std::to_string(getpid()));
    fs::remove_all(dir);
    const std::string cmd = std::string(TUNICA_BINARY) + " run " + TUNICA_SOURCE_DIR +
                            "/examples/rat-aorta-inflation.yaml -q -o " + dir.string();
    if (std::system(cmd.c_str()) != 0) throw std::runtime_error("run failed");
    return dir;
  }();
  return out;
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (auto p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
  return n;
}

}  // namespace

TEST(Output, HistoryHasTheRequestedColumnsWithUnitsAndOneRowPerIncrement) {
  const auto h = lines(read_text((run_example() / "history.csv").string()));
  EXPECT_EQ(h[0],
            "step,increment,time,pressure_mmHg,lambda_theta,E_theta,E_z,S_theta_kPa,S_z_kPa,thickness_mm,radius_mm,"
            "axial_force_N");
  EXPECT_EQ(h.size(), 1u + 1 + 6 + 20);  // header, reference state, 6 prestretch, 20 inflation increments
  EXPECT_EQ(h.back().substr(0, 11), "2,20,2,200,");
}

TEST(Output, NewtonLogHasOneRowPerIteration) {
  const auto n = lines(read_text((run_example() / "newton.csv").string()));
  EXPECT_EQ(n[0].substr(0, 34), "step,increment,attempt,iteration,t");
  EXPECT_NE(n[0].find(",residual,relative_residual,"), std::string::npos);
  // 26 increments of 3–5 iterations, each with its iteration 0.
  EXPECT_GT(n.size(), 26u * 4);
  EXPECT_LT(n.size(), 26u * 6 + 1);
}

TEST(Output, ParaViewSeriesListEveryFrameWithConsistentGrids) {
  const fs::path out = run_example();
  for (const std::string series : {"meridian", "surface"}) {
    const std::string pvd = read_text((out / (series + ".pvd")).string());
    EXPECT_EQ(count(pvd, "<DataSet "), 27) << series;
    const std::string last = read_text((out / "vtk" / (series + "_000026.vtu")).string());
    const int points = series == "meridian" ? 2 : 2 * 48, cells = series == "meridian" ? 1 : 48;
    EXPECT_NE(last.find("NumberOfPoints=\"" + std::to_string(points) + "\" NumberOfCells=\"" + std::to_string(cells)),
              std::string::npos);
    for (const char* field : {"displacement", "lambda_hoop", "sigma_hoop_N_per_mm2", "thickness_mm"})
      EXPECT_NE(last.find(std::string("Name=\"") + field + "\""), std::string::npos) << series << " " << field;
    // Text arrays close with </DataArray>; appended ones are empty elements pointing into <AppendedData>.
    EXPECT_EQ(count(last, "<DataArray"), count(last, "</DataArray>") + count(last, "format=\"appended\" offset="));
  }
}

TEST(Output, RevolvedSurfaceLiesAtTheReportedRadius) {
  const fs::path out = run_example();
  const std::string vtu = read_text((out / "vtk" / "surface_000026.vtu").string());
  const std::vector<double> pts = decode_float64(vtu, "Points");
  const auto h = lines(read_text((out / "history.csv").string()));
  const double radius = std::stod(h.back().substr(h.back().rfind(',', h.back().rfind(',') - 1) + 1));
  ASSERT_EQ(pts.size(), 3u * 96);
  for (std::size_t i = 0; i < pts.size(); i += 3) EXPECT_NEAR(std::hypot(pts[i], pts[i + 1]), radius, 1e-9);
  // The hoop stretch field holds λθ of history.csv on every one of the 48 cells.
  const std::vector<double> lt = decode_float64(vtu, "lambda_hoop");
  ASSERT_EQ(lt.size(), 48u);
  const double lambda_theta = std::stod(h.back().substr(h.back().find(',', h.back().find(',', h.back().find(',', h.back().find(',') + 1) + 1) + 1) + 1));
  for (double x : lt) EXPECT_NEAR(x, lambda_theta, 1e-9);
}
