// read_gmsh: a .geo meshed on reading (quarter cylinder, scripts allowed), a hand-written
// .msh 4.1 with triangles, quadrangles and an element-data direction view, the errors
// (missing file, garbage, no physical surface, second-order elements, missing or wrong
// view), and the idealized aneurysm of examples/meshes/aneurysm.geo. The .msh reader's
// own cases (formats, damaged files, scripts refused) are in test_msh_reader.cpp.
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <thread>
#include <atomic>
#include <stdexcept>

#include "core/errors.hpp"
#include "mesh/gmsh_reader.hpp"
#include "mesh/mesh_checks.hpp"
#include "../support/scratch.hpp"

using namespace tunica;
using Eigen::Vector3d;
namespace fs = std::filesystem;

namespace {

std::string write(const std::string& name, const std::string& text) {
  const fs::path p = test::scratch("gmsh-reader") / name;
  std::ofstream(p) << text;
  return p.string();
}

/// A quarter cylinder R = 1 from z = 0 to z = 3 (built-in kernel), with physical groups.
std::string quarter_cylinder_geo(const std::string& extra = "", bool physical = true) {
  std::string s = extra +
                  "lc = 0.25;\n"
                  "Point(1) = {0, 0, 0, lc}; Point(2) = {1, 0, 0, lc}; Point(3) = {0, 1, 0, lc};\n"
                  "Circle(1) = {2, 1, 3};\n"
                  "out[] = Extrude {0, 0, 3} { Curve{1}; };\n";
  if (physical)
    s += "Physical Surface(\"wall\") = {out[1]};\n"
         "Physical Curve(\"bottom\") = {1};\n"
         "Physical Curve(\"top\") = {out[0]};\n";
  return s;
}

/// Runs f and returns the InputError it throws (fails the test if it throws none).
InputError input_error(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    std::printf("  %s\n", e.what());
    return e;
  }
  ADD_FAILURE() << "no InputError";
  return InputError({}, "");
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

/// A Gmsh script, meshed with scripts allowed.
SurfaceMesh read_script(const std::string& path, const std::string& view = "") { return read_gmsh(path, view, true); }

Vector3d normal(const SurfaceMesh& m, const std::array<int, 3>& t) {
  return (m.nodes[t[1]] - m.nodes[t[0]]).cross(m.nodes[t[2]] - m.nodes[t[0]]);
}

}  // namespace

TEST(GmshReader, GeoIsMeshedOnReading) {
  const std::string path = write("quarter.geo", quarter_cylinder_geo());
  const SurfaceMesh m = read_script(path);
  ASSERT_EQ(m.surfaces.size(), 1u);
  const auto& wall = m.surfaces[0];
  EXPECT_EQ(wall.name, "wall");
  EXPECT_GT(wall.triangles.size(), 50u);
  EXPECT_EQ(wall.quads.size(), 0u);
  EXPECT_TRUE(wall.triangle_direction.empty());
  std::printf("  quarter cylinder: %zu nodes, %zu triangles\n", m.nodes.size(), wall.triangles.size());
  // Every node is used (compact numbering) and lies on the cylinder.
  std::vector<int> used(m.nodes.size(), 0);
  for (const auto& t : wall.triangles)
    for (int k : t) used.at(k) = 1;
  EXPECT_EQ(std::count(used.begin(), used.end(), 0), 0);
  for (const auto& x : m.nodes) {
    EXPECT_NEAR(std::hypot(x(0), x(1)), 1.0, 1e-12);
    EXPECT_GE(x(0), -1e-15);
    EXPECT_GE(x(1), -1e-15);
  }
  EXPECT_EQ(check_surface(m, wall), "");
  ASSERT_EQ(m.node_sets.size(), 2u);
  const auto& bottom = m.node_sets.at("bottom");
  const auto& top = m.node_sets.at("top");
  EXPECT_EQ(bottom.size(), top.size());
  EXPECT_GE(bottom.size(), 7u);  // arc of length π/2 with lc = 0.25, ends included
  int on_bottom = 0, on_top = 0;
  for (const auto& x : m.nodes) {
    on_bottom += std::abs(x(2)) < 1e-12;
    on_top += std::abs(x(2) - 3) < 1e-12;
  }
  EXPECT_EQ(static_cast<int>(bottom.size()), on_bottom);  // all the nodes on the curve, ends included
  EXPECT_EQ(static_cast<int>(top.size()), on_top);
  for (int i : bottom) EXPECT_NEAR(m.nodes[i](2), 0.0, 1e-12);
  for (int i : top) EXPECT_NEAR(m.nodes[i](2), 3.0, 1e-12);
  // Orientation: the arc runs counterclockwise about +z and is extruded along +z, so
  // Gmsh's normals point away from the axis.
  for (const auto& t : wall.triangles) {
    const Vector3d c = (m.nodes[t[0]] + m.nodes[t[1]] + m.nodes[t[2]]) / 3;
    EXPECT_GT(normal(m, t).dot(Vector3d(c(0), c(1), 0)), 0);
  }
}

TEST(GmshReader, MshWithTrianglesQuadsAndDirectionView) {
  const std::string path = std::string(TUNICA_SOURCE_DIR) + "/tests/data/meshes/mixed_fibre.msh";
  const SurfaceMesh m = read_gmsh(path, "fibre");
  // Node tags 10…70 are renumbered 0…5 in tag order; node 70 belongs to no element: dropped.
  ASSERT_EQ(m.nodes.size(), 6u);
  EXPECT_EQ(m.nodes[0], Vector3d(0, 0, 0));   // tag 10
  EXPECT_EQ(m.nodes[1], Vector3d(1, 0, 0));   // tag 20
  EXPECT_EQ(m.nodes[3], Vector3d(0, 1, 0));   // tag 40
  EXPECT_EQ(m.nodes[5], Vector3d(2, 1, 0));   // tag 60
  ASSERT_EQ(m.surfaces.size(), 1u);
  const auto& s = m.surfaces[0];
  EXPECT_EQ(s.name, "patch");
  ASSERT_EQ(s.quads.size(), 1u);
  ASSERT_EQ(s.triangles.size(), 2u);
  EXPECT_EQ(s.quads[0], (std::array<int, 4>{0, 1, 4, 3}));
  EXPECT_EQ(s.triangles[0], (std::array<int, 3>{1, 2, 5}));
  EXPECT_EQ(s.triangles[1], (std::array<int, 3>{1, 5, 4}));
  ASSERT_EQ(s.quad_direction.size(), 1u);
  ASSERT_EQ(s.triangle_direction.size(), 2u);
  EXPECT_EQ(s.quad_direction[0], Vector3d(1, 0, 0));       // element 5
  EXPECT_EQ(s.triangle_direction[0], Vector3d(0.6, 0.8, 0));  // element 6
  EXPECT_EQ(s.triangle_direction[1], Vector3d(0, 1, 0));      // element 7
  EXPECT_EQ(m.node_sets.at("edge"), (std::vector<int>{0, 3}));
  EXPECT_EQ(check_surface(m, s), "");
  // Without a view name no directions are read.
  const SurfaceMesh plain = read_gmsh(path);
  EXPECT_TRUE(plain.surfaces[0].quad_direction.empty());
}

TEST(GmshReader, MissingFile) {
  const std::string path = (test::scratch("gmsh-reader") / "no-such-mesh.msh").string();
  const InputError e = input_error([&] { read_gmsh(path); });
  EXPECT_EQ(e.where().file, path);
  EXPECT_EQ(e.where().line, 0);
  EXPECT_TRUE(contains(e.reason(), "cannot read the mesh file: no such file")) << e.what();
}

TEST(GmshReader, GarbageIsReportedWithItsLineAndLaterReadsStillWork) {
  const std::string path = write("garbage.msh", "this is not a mesh\n}{ 1 2 3\n");
  const InputError e = input_error([&] { read_gmsh(path); });
  EXPECT_EQ(e.where().file, path);
  EXPECT_EQ(e.where().line, 1);
  EXPECT_TRUE(contains(e.reason(), "not a Gmsh mesh: a .msh file must begin with $MeshFormat")) << e.what();
  // A script with a syntax error: Gmsh's message and line; Gmsh runs in a child process,
  // so later scripts are meshed as if nothing had happened.
  const SurfaceMesh m = read_script(write("after-garbage.geo", quarter_cylinder_geo()));
  EXPECT_EQ(m.surfaces.at(0).name, "wall");
  const InputError e2 = input_error([&] { read_script(write("garbage2.geo", "Point(1) = {0, 0, 0};\nCircle(1 = ;\n")); });
  EXPECT_EQ(e2.where().line, 2);
}

TEST(GmshReader, NoPhysicalSurface) {
  const std::string path = write("nophysical.geo", quarter_cylinder_geo("", false));
  const InputError e = input_error([&] { read_script(path); });
  EXPECT_EQ(e.where().file, path);
  EXPECT_TRUE(contains(e.reason(), "the file defines no physical surface")) << e.what();
}

TEST(GmshReader, SecondOrderTrianglesAreReadWithTheirMidEdgeNodesOnTheSurface) {
  // Mesh.ElementOrder = 2: 6-node triangles (type 9), corners in `triangles`, mid-edge nodes alongside,
  // placed by Gmsh on the curved surface.
  const SurfaceMesh m = read_script(write("order2.geo", quarter_cylinder_geo("Mesh.ElementOrder = 2;\n")));
  ASSERT_EQ(m.surfaces.size(), 1u);
  const auto& s = m.surfaces[0];
  ASSERT_FALSE(s.triangles.empty());
  ASSERT_EQ(s.triangle_midsides.size(), s.triangles.size());
  EXPECT_EQ(s.triangle_tags.size(), s.triangles.size());
  double worst = 0;
  for (std::size_t e = 0; e < s.triangles.size(); ++e)
    for (int a = 0; a < 3; ++a) {
      const Vector3d& mid = m.nodes[s.triangle_midsides[e][a]];
      const Vector3d chord = 0.5 * (m.nodes[s.triangles[e][a]] + m.nodes[s.triangles[e][(a + 1) % 3]]);
      worst = std::max(worst, std::abs(std::hypot(mid(0), mid(1)) - 1.0));
      EXPECT_LT((mid - chord).norm(), 0.1);  // near the edge's chord midpoint, pushed out onto the cylinder
    }
  EXPECT_LT(worst, 1e-9);  // R = 1
  // The physical curves' node sets hold the mid-edge nodes of their 3-node lines too.
  EXPECT_EQ(m.node_sets.at("bottom").size() % 2, 1u);
}

TEST(GmshReader, AGroupOfAReversedCurveKeepsItsName) {
  // Extrude returns signed tags: the lateral curves come back reversed (−5), and Gmsh writes the
  // entity's physical tag as −(group tag). The node set still has the group's name.
  const SurfaceMesh m = read_script(write("signed.geo", quarter_cylinder_geo() + "Physical Curve(\"y0\") = {out[2]};\n"
                                                                               "Physical Curve(\"x0\") = {out[3]};\n"));
  EXPECT_EQ(m.node_sets.count("x0"), 1u);
  EXPECT_EQ(m.node_sets.count("y0"), 1u);
  for (const auto& [name, set] : m.node_sets) EXPECT_EQ(name.find("curve_"), std::string::npos) << name;
  EXPECT_GT(m.node_sets.at("x0").size(), 2u);
}

TEST(GmshReader, ThirdOrderElementsAreRefused) {
  const std::string path = write("order3.geo", quarter_cylinder_geo("Mesh.ElementOrder = 3;\n"));
  const InputError e = input_error([&] { read_script(path); });
  EXPECT_EQ(e.where().file, path);
  EXPECT_EQ(e.where().key, "wall");
  EXPECT_TRUE(contains(e.reason(), "is a 10-node third-order triangle (type 21); Tunica reads 3-node and 6-node "
                                   "triangles (types 2 and 9) and 4-node quadrangles (type 3): mesh with "
                                   "Mesh.ElementOrder = 1, or 2 with triangles only"))
      << e.what();
}

TEST(GmshReader, MissingOrWrongDirectionView) {
  const std::string path = std::string(TUNICA_SOURCE_DIR) + "/tests/data/meshes/mixed_fibre.msh";
  InputError e = input_error([&] { read_gmsh(path, "fiber"); });
  EXPECT_EQ(e.where().file, path);
  EXPECT_EQ(e.where().key, "fiber");
  EXPECT_TRUE(contains(e.reason(), "no $ElementData view named 'fiber' for the element directions (views in the file: "
                                   "'fibre', 'thickness')"))
      << e.what();
  e = input_error([&] { read_gmsh(path, "thickness"); });
  EXPECT_TRUE(contains(e.reason(), "view 'thickness' must hold 3 components per element")) << e.what();
  // A view that misses an element of the surface.
  std::ifstream in(path);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto at = text.find("7 0 1 0\n");
  ASSERT_NE(at, std::string::npos);
  text.erase(at, 8);
  const auto count = text.find("3\n5 1 0 0");  // the number of elements in the view: 3 → 2
  ASSERT_NE(count, std::string::npos);
  text[count] = '2';
  const std::string partial = write("partial-view.msh", text);
  e = input_error([&] { read_gmsh(partial, "fibre"); });
  EXPECT_EQ(e.where().file, partial);
  EXPECT_TRUE(contains(e.reason(), "view 'fibre' has no direction for element 7 of physical surface 'patch'"))
      << e.what();
  // A geometry without views.
  e = input_error([&] { read_script(write("noview.geo", quarter_cylinder_geo()), "fibre"); });
  EXPECT_TRUE(contains(e.reason(), "(views in the file: none)")) << e.what();
}

TEST(GmshReader, IdealizedFusiformAneurysm) {
  const std::string path = std::string(TUNICA_SOURCE_DIR) + "/examples/meshes/aneurysm.geo";
  const SurfaceMesh m = read_script(path);
  ASSERT_EQ(m.surfaces.size(), 1u);
  const auto& wall = m.surfaces[0];
  EXPECT_EQ(wall.name, "wall");
  EXPECT_EQ(wall.quads.size(), 0u);
  std::printf("  aneurysm.geo: %zu nodes, %zu triangles, inlet %zu nodes, outlet %zu nodes\n", m.nodes.size(),
              wall.triangles.size(), m.node_sets.at("inlet").size(), m.node_sets.at("outlet").size());
  EXPECT_GT(wall.triangles.size(), 2000u);
  EXPECT_LT(wall.triangles.size(), 10000u);
  EXPECT_EQ(check_surface(m, wall), "");
  // The four quarter turns share their seam nodes (no duplicate positions), so the wall
  // is one closed tube: its only boundary edges are on the inlet and outlet circles.
  std::set<std::array<long long, 3>> distinct;
  for (const auto& x : m.nodes) distinct.insert({std::llround(x(0) * 1e8), std::llround(x(1) * 1e8), std::llround(x(2) * 1e8)});
  EXPECT_EQ(distinct.size(), m.nodes.size());
  std::map<std::pair<int, int>, int> edge_uses;
  for (const auto& t : wall.triangles)
    for (int k = 0; k < 3; ++k) ++edge_uses[std::minmax(t[k], t[(k + 1) % 3])];
  std::size_t boundary_edges = 0;
  for (const auto& [edge, uses] : edge_uses) boundary_edges += uses == 1;
  EXPECT_EQ(boundary_edges, m.node_sets.at("inlet").size() + m.node_sets.at("outlet").size());
  const double R0 = 2.0, L = 40.0, k = 2.5;
  ASSERT_EQ(m.node_sets.size(), 2u);
  for (const auto& [name, z] : {std::pair<std::string, double>{"inlet", -L / 2}, {"outlet", L / 2}}) {
    const auto& set = m.node_sets.at(name);
    int on_end = 0;
    for (const auto& x : m.nodes) on_end += std::abs(x(2) - z) < 1e-9;
    EXPECT_EQ(static_cast<int>(set.size()), on_end) << name;  // the whole end circle
    EXPECT_GE(set.size(), 20u) << name;
    for (int i : set) {
      EXPECT_NEAR(m.nodes[i](2), z, 1e-9) << name;
      EXPECT_NEAR(std::hypot(m.nodes[i](0), m.nodes[i](1)), R0, 1e-9) << name;
    }
  }
  double rmax = 0;
  for (const auto& x : m.nodes) {
    EXPECT_GE(x(2), -L / 2 - 1e-9);
    EXPECT_LE(x(2), L / 2 + 1e-9);
    const double r = std::hypot(x(0), x(1));
    EXPECT_GE(r, R0 - 1e-6);
    EXPECT_LE(r, k * R0 + 0.05);  // the spline through the profile may overshoot slightly
    rmax = std::max(rmax, r);
  }
  EXPECT_NEAR(rmax, k * R0, 0.02 * k * R0);
  // Outward orientation: every element normal points away from the axis.
  int inward = 0;
  for (const auto& t : wall.triangles) {
    const Vector3d c = (m.nodes[t[0]] + m.nodes[t[1]] + m.nodes[t[2]]) / 3;
    inward += normal(m, t).dot(Vector3d(c(0), c(1), 0)) <= 0;
  }
  EXPECT_EQ(inward, 0) << "of " << wall.triangles.size() << " elements";
  std::printf("  aneurysm.geo: max radius %.4f mm (k R0 = %.1f mm), %d inward elements\n", rmax, k * R0, inward);
}

TEST(GmshReader, ConcurrentReadsAreSerialized) {
  // Reads from several threads (scripts meshed one child process at a time) give the
  // same meshes as one after the other.
  const std::string geo = write("threads.geo", quarter_cylinder_geo());
  const std::string msh = std::string(TUNICA_SOURCE_DIR) + "/tests/data/meshes/mixed_fibre.msh";
  std::vector<std::size_t> counts(4);
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([&, t] {
      const SurfaceMesh m = t % 2 ? read_gmsh(msh, "fibre") : read_script(geo);
      counts[t] = m.nodes.size();
    });
  for (auto& th : threads) th.join();
  EXPECT_EQ(counts[0], 121u);
  EXPECT_EQ(counts[2], 121u);
  EXPECT_EQ(counts[1], 6u);
  EXPECT_EQ(counts[3], 6u);
}

TEST(GmshReader, ScriptsAreMeshedWhileOtherThreadsThrowAndAllocate) {
  // Gmsh runs in a process started by fork and exec (geo_mesher.cpp): whatever the
  // other threads hold at the fork (the unwinder's lock of a thread throwing, the
  // allocator's), the new process image inherits none of it.
  const std::string geo = write("busy.geo", quarter_cylinder_geo());
  std::atomic<bool> stop{false};
  std::atomic<long> thrown{0};
  std::vector<std::thread> noise;
  for (int t = 0; t < 2; ++t)
    noise.emplace_back([&] {
      while (!stop) {
        try {
          throw std::runtime_error(std::string(200, 'x'));
        } catch (const std::exception&) {
          ++thrown;
        }
      }
    });
  std::vector<std::size_t> counts;
  for (int k = 0; k < 8; ++k) counts.push_back(read_script(geo).nodes.size());
  stop = true;
  for (auto& th : noise) th.join();
  EXPECT_GT(thrown.load(), 0);
  for (std::size_t c : counts) EXPECT_EQ(c, 121u);
}

TEST(GmshReader, ACommandTheScriptLeavesRunningNeitherBlocksNorOutlivesTheRead) {
  // A background command started by the script's System holds the report pipe open;
  // the read ends when Gmsh has, and the command is ended with it.
  const fs::path pidfile = test::scratch("gmsh-reader") / "background.pid";
  const std::string geo =
      write("background.geo", quarter_cylinder_geo("System \"sleep 30 & echo $! > " + pidfile.string() + "\";\n"));
  const auto t0 = std::chrono::steady_clock::now();
  EXPECT_EQ(read_script(geo).nodes.size(), 121u);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 10.0);
  std::ifstream in(pidfile);
  pid_t pid = 0;
  ASSERT_TRUE(in >> pid) << "the script's command did not run";
  // Ended (and reaped by init once orphaned): give the kernel a moment.
  bool gone = false;
  for (int i = 0; i < 50 && !gone; ++i) {
    gone = ::kill(pid, 0) != 0 || std::ifstream("/proc/" + std::to_string(pid) + "/stat").peek() == EOF;
    if (!gone) {
      std::string stat;
      std::getline(std::ifstream("/proc/" + std::to_string(pid) + "/stat"), stat);
      gone = stat.find(") Z") != std::string::npos;  // a zombie: ended, not yet reaped
    }
    if (!gone) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  EXPECT_TRUE(gone) << "sleep " << pid << " outlived the read";
}
