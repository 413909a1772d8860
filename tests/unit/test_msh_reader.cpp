// Tunica's own .msh reader (msh_parser, msh_surface) and the containment of Gmsh
// scripts (geo_mesher, --allow-scripts):
// - the four formats Gmsh writes (4.1 and 2.2, ASCII and binary; files written by
//   Gmsh 4.8 in tests/data/meshes/gmsh-written/, with an element-data view) read to
//   the same mesh, and so does a script meshed by Gmsh in each of the four formats;
// - no file runs anything without the flag: a .msh holding a script and a .geo;
// - damaged files: every kind of defect the reader checks gets its own message with
//   the line and the tags as written in the file; truncations and random corruptions
//   of every shipped mesh are read or refused with a one-line InputError;
// - counts far beyond the file's size are refused before anything is allocated.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>

#include "core/bounded_file.hpp"
#include "core/errors.hpp"
#include "core/printable.hpp"
#include "mesh/geo_mesher.hpp"
#include "mesh/gmsh_reader.hpp"
#include "mesh/msh_parser.hpp"
#include "mesh/msh_surface.hpp"
#include "../support/scratch.hpp"

using namespace tunica;
namespace fs = std::filesystem;

namespace {

std::string write(const std::string& name, const std::string& text) {
  const fs::path p = test::scratch("msh-reader") / name;
  std::ofstream(p, std::ios::binary) << text;
  return p.string();
}

std::string data(const std::string& name) { return std::string(TUNICA_SOURCE_DIR) + "/tests/data/meshes/" + name; }

std::string bytes_of(const std::string& path) { return read_file_bounded(path, 1u << 26, "test file"); }

/// The InputError `f` throws (a test failure if none).
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

/// How much slower than Release this build runs (AddressSanitizer: tools/test-sanitizers.sh).
#if defined(__SANITIZE_ADDRESS__)
constexpr double kSlowdown = 10;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr double kSlowdown = 10;
#else
constexpr double kSlowdown = 1;
#endif
#else
constexpr double kSlowdown = 1;
#endif

SurfaceMesh from_text(const std::string& text, const std::string& view = "") {
  return surface_mesh_from_msh(parse_msh(text, "t.msh"), "t.msh", view);
}

void expect_same(const SurfaceMesh& a, const SurfaceMesh& b, const std::string& what) {
  ASSERT_EQ(a.nodes.size(), b.nodes.size()) << what;
  // ASCII files hold 16 significant digits ("%.16g"), binary ones the exact doubles.
  for (std::size_t i = 0; i < a.nodes.size(); ++i)
    EXPECT_LE((a.nodes[i] - b.nodes[i]).norm(), 1e-15 * (1 + a.nodes[i].norm())) << what << " node " << i;
  ASSERT_EQ(a.surfaces.size(), b.surfaces.size()) << what;
  for (std::size_t s = 0; s < a.surfaces.size(); ++s) {
    EXPECT_EQ(a.surfaces[s].name, b.surfaces[s].name) << what;
    EXPECT_EQ(a.surfaces[s].triangles, b.surfaces[s].triangles) << what;
    EXPECT_EQ(a.surfaces[s].quads, b.surfaces[s].quads) << what;
    EXPECT_EQ(a.surfaces[s].triangle_direction, b.surfaces[s].triangle_direction) << what;
  }
  EXPECT_EQ(a.node_sets, b.node_sets) << what;
}

/// A quarter cylinder R = 1, z in [0, 3], with physical surface "wall" and curves "bottom", "top".
const char* kQuarterCylinder =
    "lc = 0.25;\n"
    "Point(1) = {0, 0, 0, lc}; Point(2) = {1, 0, 0, lc}; Point(3) = {0, 1, 0, lc};\n"
    "Circle(1) = {2, 1, 3};\n"
    "out[] = Extrude {0, 0, 3} { Curve{1}; };\n"
    "Physical Surface(\"wall\") = {out[1]};\n"
    "Physical Curve(\"bottom\") = {1};\n"
    "Physical Curve(\"top\") = {out[0]};\n";

/// A Gmsh 2.2 square of two triangles (nodes 1-4), physical surface 1 "wall"; `extra_nodes`
/// and `extra_elements` are appended to the sections, `count` is the element count.
std::string square(const std::string& extra_nodes = "", int node_count = 4, const std::string& extra_elements = "",
                   int element_count = 2) {
  return "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n1\n2 1 \"wall\"\n$EndPhysicalNames\n$Nodes\n" +
         std::to_string(node_count) + "\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n" + extra_nodes + "$EndNodes\n$Elements\n" +
         std::to_string(element_count) + "\n1 2 2 1 1 1 2 3\n2 2 2 1 1 1 3 4\n" + extra_elements + "$EndElements\n";
}

}  // namespace

TEST(MshReader, TheFourFormatsGmshWritesGiveTheSameMesh) {
  const SurfaceMesh ref = read_gmsh(data("gmsh-written/patch-v41-ascii.msh"), "fibre");
  ASSERT_EQ(ref.surfaces.size(), 1u);
  EXPECT_EQ(ref.surfaces[0].name, "patch");
  EXPECT_EQ(ref.surfaces[0].triangles, (std::vector<std::array<int, 3>>{{0, 1, 2}, {0, 2, 3}}));
  EXPECT_EQ(ref.surfaces[0].triangle_direction, (std::vector<Eigen::Vector3d>{{1, 0, 0}, {0, 1, 0}}));
  for (const char* f : {"patch-v41-binary.msh", "patch-v22-ascii.msh", "patch-v22-binary.msh"})
    expect_same(ref, read_gmsh(data(std::string("gmsh-written/") + f), "fibre"), f);
  // Quadrangles with physical curves and a physical point (node sets).
  const SurfaceMesh quads = read_gmsh(data("gmsh-written/quads-v41-ascii.msh"));
  EXPECT_EQ(quads.nodes.size(), 20u);
  EXPECT_EQ(quads.surfaces.at(0).quads.size(), 12u);
  EXPECT_EQ(quads.node_sets.at("bottom").size(), 4u);
  EXPECT_EQ(quads.node_sets.at("top").size(), 4u);
  EXPECT_EQ(quads.node_sets.at("corner").size(), 1u);
  for (int i : quads.node_sets.at("top")) EXPECT_EQ(quads.nodes[i](2), 3.0);
  for (const char* f : {"quads-v41-binary.msh", "quads-v22-ascii.msh", "quads-v22-binary.msh"})
    expect_same(quads, read_gmsh(data(std::string("gmsh-written/") + f)), f);
}

TEST(MshReader, AScriptMeshedInEachFormatReadsToTheSameMesh) {
  const std::string geo = write("quarter.geo", kQuarterCylinder);
  const SurfaceMesh ref = read_gmsh(geo, "", true);
  EXPECT_GT(ref.surfaces.at(0).triangles.size(), 50u);
  EXPECT_EQ(ref.node_sets.size(), 2u);
  for (double version : {4.1, 2.2})
    for (bool binary : {false, true}) {
      const std::string what = std::to_string(version) + (binary ? " binary" : " ASCII");
      const std::string msh = write("quarter-" + what + ".msh", mesh_geo_script(geo, {version, binary}));
      expect_same(ref, read_gmsh(msh), what);
    }
}

TEST(MshReader, ScriptsRunOnlyWithTheFlag) {
  const fs::path marker = test::scratch("msh-reader") / "script-ran";
  fs::remove(marker);
  const std::string command = "System \"touch " + marker.string() + "\";\n";
  // A .msh that is a script: refused as not a mesh, whatever the flag.
  const std::string msh = write("script.msh", command + kQuarterCylinder);
  for (bool allow : {false, true}) {
    const InputError e = input_error([&] { read_gmsh(msh, "", allow); });
    EXPECT_EQ(e.where().file, msh);
    EXPECT_EQ(e.where().line, 1);
    EXPECT_TRUE(contains(e.reason(), "not a Gmsh mesh: a .msh file must begin with $MeshFormat")) << e.what();
  }
  // A .geo without the flag: refused, with the flag named.
  const std::string geo = write("script.geo", command + kQuarterCylinder);
  const InputError e = input_error([&] { read_gmsh(geo); });
  EXPECT_TRUE(contains(e.reason(), "--allow-scripts")) << e.what();
  EXPECT_FALSE(fs::exists(marker)) << "a refused file ran a command";
  // With the flag, the script runs (in the child process).
  EXPECT_NO_THROW(read_gmsh(geo, "", true));
  EXPECT_TRUE(fs::exists(marker));
}

TEST(MshReader, AScriptThatCrashesGmshIsAnInputErrorAndTheNextReadWorks) {
  // Gmsh's parser divides by zero on this (SIGFPE in the child).
  const std::string bad = write("crash.geo", "a = 1 % 0;\n");
  const InputError e = input_error([&] { read_gmsh(bad, "", true); });
  EXPECT_EQ(e.where().file, bad);
  const std::string geo = write("after-crash.geo", kQuarterCylinder);
  EXPECT_EQ(read_gmsh(geo, "", true).surfaces.at(0).name, "wall");
}

TEST(MshReader, MixedOrderElementsAreRefusedNeverDropped) {
  const InputError e = input_error([&] {
    from_text(square("5 0.5 0.5 0\n6 0.5 0 0\n7 1 0.5 0\n", 7, "3 9 2 1 1 2 3 5 6 7 5\n", 3));
  });
  EXPECT_EQ(e.where().line, 22);
  EXPECT_EQ(e.where().key, "wall");
  // Linear and quadratic triangles in one surface: refused (a surface is meshed at one order).
  EXPECT_TRUE(contains(e.reason(), "physical surface 'wall' mixes 3-node (type 2) and 6-node (type 9) triangles "
                                   "(element 3 (line 22))"))
      << e.what();
}

TEST(MshReader, DuplicatedNodeTagsAreReportedWithBothLines) {
  const InputError e = input_error([&] { from_text(square("3 5 5 0\n", 5)); });
  EXPECT_EQ(e.where().line, 14);
  EXPECT_TRUE(contains(e.reason(), "node tag 3 is defined twice (lines 12 and 14)")) << e.what();
}

TEST(MshReader, DuplicatedElementTagsAreReported) {
  const InputError e = input_error([&] { from_text(square("5 2 1 0\n", 5, "2 2 2 1 1 2 5 3\n", 3)); });
  EXPECT_TRUE(contains(e.reason(), "element tag 2 is used twice (lines 19 and 20)")) << e.what();
}

TEST(MshReader, CoincidentNodesAreACrack) {
  // Node 5 sits on node 3: the second triangle uses it instead of 3, so the square is split.
  const std::string text = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n5\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n"
                           "5 1 1 0\n$EndNodes\n$Elements\n3\n1 2 2 1 1 1 2 3\n2 2 2 1 1 1 5 4\n"
                           "3 2 2 1 1 2 5 3\n$EndElements\n";
  const InputError e = input_error([&] { from_text(text); });
  EXPECT_EQ(e.where().line, 10);
  EXPECT_TRUE(contains(e.reason(), "node 3 (line 8) and node 5 (line 10) coincide at (1, 1, 0)")) << e.what();
  EXPECT_TRUE(contains(e.reason(), "Coherence Mesh")) << e.what();
}

TEST(MshReader, AnElementSharingNoEdgeIsReported) {
  // Triangle 3 touches the square at node 3 only.
  const InputError e = input_error([&] { from_text(square("5 2 1 0\n6 2 2 0\n", 6, "3 2 2 1 1 3 5 6\n", 3)); });
  EXPECT_EQ(e.where().line, 21);
  EXPECT_TRUE(contains(e.reason(), "element 3 (line 21) shares no edge with any other element")) << e.what();
}

TEST(MshReader, AnUndefinedNodeIsReported) {
  const InputError e = input_error([&] { from_text(square("", 4, "3 2 2 1 1 2 9 3\n", 3)); });
  EXPECT_TRUE(contains(e.reason(), "element 3 (line 19) names node 9, which the file does not define")) << e.what();
}

TEST(MshReader, SurfaceElementsOutsideAnyPhysicalGroupAreNamedInTheMessage) {
  std::string text = square();
  text = text.replace(text.find("$PhysicalNames"), text.find("$Nodes") - text.find("$PhysicalNames"), "");
  for (auto at = text.find(" 2 1 1 "); at != std::string::npos; at = text.find(" 2 1 1 ")) text.replace(at, 7, " 2 0 1 ");
  const InputError e = input_error([&] { from_text(text); });
  EXPECT_TRUE(contains(e.reason(), "the file defines no physical surface (its 2 surface elements belong to no "
                                   "physical group)"))
      << e.what();
}

TEST(MshReader, UnsupportedVersionsAndByteOrderNameTheFix) {
  InputError e = input_error([&] { from_text("$MeshFormat\n4 0 8\n$EndMeshFormat\n"); });
  EXPECT_TRUE(contains(e.reason(), "save the mesh as version 4.1 or 2.2")) << e.what();
  e = input_error([&] { from_text(std::string("$MeshFormat\n4.1 1 8\n\0\0\0\1\n$EndMeshFormat\n", 33)); });
  EXPECT_TRUE(contains(e.reason(), "another byte order")) << e.what();
  e = input_error([&] { from_text("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$PartitionedEntities\n1\n$EndPartitionedEntities\n"); });
  EXPECT_EQ(e.where().line, 4);
  EXPECT_TRUE(contains(e.reason(), "a partitioned mesh is not read")) << e.what();
}

TEST(MshReader, HugeCountsAreRefusedBeforeAllocating) {
  struct rusage before {};
  getrusage(RUSAGE_SELF, &before);
  const auto t0 = std::chrono::steady_clock::now();
  InputError e = input_error([&] { from_text("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 1000000000 1 1000000000\n"); });
  EXPECT_TRUE(contains(e.reason(), "the file announces 1000000000 nodes; at most 10000000 are allowed")) << e.what();
  e = input_error([&] { from_text("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n9000000\n1 0 0 0\n$EndNodes\n"); });
  EXPECT_TRUE(contains(e.reason(), "the file announces 9000000 nodes, but only")) << e.what();
  e = input_error([&] { from_text("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n0 0 0 0\n$EndNodes\n$Elements\n"
                                  "1 5000000 1 5000000\n2 1 2 5000000\n1 1 2 3\n$EndElements\n"); });
  EXPECT_TRUE(contains(e.reason(), "the file announces 5000000 elements, but only")) << e.what();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  struct rusage after {};
  getrusage(RUSAGE_SELF, &after);
  EXPECT_LT(seconds, 1.0);
  EXPECT_LT(after.ru_maxrss - before.ru_maxrss, 100 * 1024) << "kB";  // ru_maxrss is in kB
}

TEST(MshReader, MissingSectionsAndUnclosedSectionsAreReported) {
  InputError e = input_error([&] { from_text("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"); });
  EXPECT_TRUE(contains(e.reason(), "the file has no $Nodes section")) << e.what();
  e = input_error([&] { from_text("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Comments\nhello\n"); });
  EXPECT_TRUE(contains(e.reason(), "section $Comments is not closed by $EndComments")) << e.what();
  e = input_error([&] { from_text(square() + square()); });
  EXPECT_TRUE(contains(e.reason(), "the file has a second $PhysicalNames section")) << e.what();
  e = input_error([&] { from_text(square() + "7 8 9\n"); });
  EXPECT_TRUE(contains(e.reason(), "expected the start of a section ($Nodes, $Elements, ...), found '7'")) << e.what();
}

TEST(MshReader, TruncatedFilesAreRefusedAtEveryLength) {
  for (const char* f : {"mixed_fibre.msh", "gmsh-written/patch-v41-binary.msh", "gmsh-written/patch-v22-binary.msh"}) {
    const std::string full = bytes_of(data(f));
    int read = 0;
    for (std::size_t n = 0; n < full.size(); ++n) {
      const std::string_view cut = std::string_view(full).substr(0, n);
      try {
        surface_mesh_from_msh(parse_msh(cut, f), f, "fibre");
        // Only a cut at a section's end leaves a valid (shorter) file.
        ++read;
        const std::string_view kept = cut.substr(0, cut.find_last_not_of(" \r\n") + 1);
        const std::size_t last = kept.find_last_of('\n');
        EXPECT_EQ(kept.substr(last + 1, 4), "$End") << f << " cut at " << n;
      } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
      }
    }
    std::printf("  %s: %zu cuts, %d at a section end read\n", f, full.size(), read);
    EXPECT_LE(read, 8) << f;
  }
}

TEST(MshReader, RandomCorruptionsAreReadOrRefusedWithOneLine) {
  // 8 random bytes overwritten, 200 times per file (tools/mesh-corruption.sh runs 1,000
  // per shipped mesh through the command line).
  std::mt19937 rng(20261201);
  for (const char* f : {"mixed_fibre.msh", "gmsh-written/patch-v41-ascii.msh", "gmsh-written/patch-v41-binary.msh",
                        "gmsh-written/patch-v22-ascii.msh", "gmsh-written/patch-v22-binary.msh"}) {
    const std::string full = bytes_of(data(f));
    int refused = 0;
    for (int trial = 0; trial < 200; ++trial) {
      std::string text = full;
      for (int k = 0; k < 8; ++k) text[rng() % text.size()] = static_cast<char>(rng() & 0xff);
      try {
        surface_mesh_from_msh(parse_msh(text, f), f, trial % 2 ? "fibre" : "");
      } catch (const InputError& e) {
        ++refused;
        const std::string m = e.what();
        EXPECT_EQ(m.find('\n'), std::string::npos) << m;
        EXPECT_EQ(m.rfind(f, 0), 0u) << m;
        EXPECT_TRUE(is_printable_line(m)) << m;
      }
    }
    std::printf("  %s: %d of 200 corruptions refused, the rest read\n", f, refused);
  }
}

TEST(BoundedFile, DevicesAndOversizedFilesAreRefusedAtOnce) {
  const auto t0 = std::chrono::steady_clock::now();
  InputError e = input_error([&] { read_file_bounded("/dev/zero", 1u << 20, "deck"); });
  EXPECT_TRUE(contains(e.reason(), "not a regular file")) << e.what();
  const std::string fifo = (test::scratch("msh-reader") / "fifo").string();
  std::filesystem::remove(fifo);  // an earlier process of the same pid may have left one
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  e = input_error([&] { read_file_bounded(fifo, 1u << 20, "deck"); });
  EXPECT_TRUE(contains(e.reason(), "not a regular file")) << e.what();
  e = input_error([&] { read_file_bounded(write("big", std::string(2000, 'x')), 1000, "deck"); });
  EXPECT_TRUE(contains(e.reason(), "the deck is 2000 bytes, more than the 1000 bytes it may have")) << e.what();
  e = input_error([&] { read_file_bounded(test::scratch("msh-reader").string(), 1000, "deck"); });
  EXPECT_TRUE(contains(e.reason(), "it is a directory")) << e.what();
  EXPECT_EQ(read_file_bounded(write("small", "abc"), 3, "deck"), "abc");
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 1.0);
}

TEST(MshReader, TheKindsOfFileThatCrashedGmshAreInputErrors) {
  // Files that crash Gmsh 4.8's reader (fuzz/regressions/msh/): a 4.1 binary element naming a node
  // tag that does not exist (a segfault in GModel::getMeshVertexByTag), a 2.2 binary
  // element block announcing more elements than the section (an assertion in
  // GModelIO_MSH2.cpp), and a .msh that is a script dividing by zero (SIGFPE).
  const std::string dir = std::string(TUNICA_SOURCE_DIR) + "/fuzz/regressions/msh/";
  InputError e = input_error([&] { read_gmsh(dir + "undefined-node-v41-binary.msh"); });
  EXPECT_TRUE(contains(e.reason(), "names node 1000000000, which the file does not define")) << e.what();
  e = input_error([&] { read_gmsh(dir + "block-overflow-v22-binary.msh"); });
  EXPECT_TRUE(contains(e.reason(), "the number of elements that follow is 1001, outside [1, 19]")) << e.what();
  e = input_error([&] { read_gmsh(dir + "script-divide-by-zero.msh", "", true); });
  EXPECT_TRUE(contains(e.reason(), "not a Gmsh mesh")) << e.what();
}

TEST(MshReader, WhatIsNotAMeshGetsAHintForWhatItIs) {
  InputError e = input_error([&] { from_text("solid vessel\n facet normal 0 0 1\n"); });
  EXPECT_TRUE(contains(e.reason(), "it looks like an STL surface: write a .geo with Merge")) << e.what();
  std::string binary_stl(84 + 50, '\0');
  binary_stl[80] = 1;
  e = input_error([&] { from_text(binary_stl); });
  EXPECT_TRUE(contains(e.reason(), "it looks like an STL surface")) << e.what();
  e = input_error([&] { from_text("\xEF\xBB\xBF$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"); });
  EXPECT_TRUE(contains(e.reason(), "begins with '\\xEF\\xBB\\xBF$MeshFormat")) << e.what();
  EXPECT_TRUE(contains(e.reason(), "byte-order mark")) << e.what();
  e = input_error([&] { from_text("\n$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"); });
  EXPECT_TRUE(contains(e.reason(), "remove the blank space before $MeshFormat")) << e.what();
  e = input_error([&] { from_text("Point(1) = {0, 0, 0};\n"); });
  EXPECT_TRUE(contains(e.reason(), "a Gmsh script must be named .geo")) << e.what();
}

TEST(MshReader, SurfaceElementsOutsideThePhysicalSurfacesAreRefused) {
  // A third triangle with no physical tag beside the physical square: a hole nobody sees.
  const InputError e = input_error([&] { from_text(square("5 2 0 0\n", 5, "3 2 2 0 1 2 5 3\n", 3)); });
  EXPECT_EQ(e.where().line, 20);
  EXPECT_TRUE(contains(e.reason(), "1 surface element(s), the first element 3 (line 20), belong to no physical "
                                   "surface"))
      << e.what();
}

TEST(Printable, TerminalSafeEscapesOnlyWhatIsNotPrintable) {
  // A message that already quotes a file through printable() passes unchanged; raw control
  // characters and ill-formed bytes are escaped; line breaks and printable UTF-8 stay.
  EXPECT_EQ(terminal_safe("(it has: wal\\x08)"), "(it has: wal\\x08)");
  EXPECT_EQ(terminal_safe("ed\x1b[31mge\nWand_\xc3\xa4 \xff"), "ed\\x1B[31mge\nWand_\xc3\xa4 \\xFF");
  EXPECT_TRUE(is_printable_line(terminal_safe("a\x01b\xe2\x80\xae" "c")));  // a control and a bidirectional override
}

TEST(Printable, EscapesControlsAndInvalidBytesAndKeepsUtf8) {
  EXPECT_EQ(printable("Wand_\xC3\xA4"), "Wand_\xC3\xA4");  // "Wand_ä" stays
  EXPECT_EQ(printable("a\nb\xFF\xC3"), "a\\nb\\xFF\\xC3");
  EXPECT_EQ(printable("\xE2\x80\xA8"), "\\xE2\\x80\\xA8");  // U+2028, a line separator
  EXPECT_EQ(printable("\xC0\xAF"), "\\xC0\\xAF");  // overlong
  EXPECT_EQ(printable(std::string(50, 'x'), 10), "xxxxxxxxxx...");
  EXPECT_TRUE(is_printable_line("σ × 2"));
  EXPECT_FALSE(is_printable_line("a\nb"));
  EXPECT_FALSE(is_printable_line("\xFF"));
}

TEST(MshReader, NodesCrowdingOnePlaneAreCheckedInLinearithmicTime) {
  // 160,000 nodes on one plane normal to the direction the fast check projects on (a
  // grid in that plane, as a hostile file could make), no two coincident: the check
  // must finish at once and accept them; one more node on top of another is found.
  const Eigen::Vector3d d = Eigen::Vector3d(1.0, std::sqrt(2.0), std::sqrt(3.0)).normalized();
  const Eigen::Vector3d u = d.cross(Eigen::Vector3d::UnitX()).normalized(), v = d.cross(u);
  const int n = 400;
  std::string nodes, elements;
  int tag = 0, etag = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const Eigen::Vector3d x = i * u + j * v;
      nodes += fmt::format("{} {:.17g} {:.17g} {:.17g}\n", ++tag, x(0), x(1), x(2));
    }
  for (int i = 0; i + 1 < n; ++i)
    for (int j = 0; j + 1 < n; ++j) {
      const int a = i * n + j + 1, b = a + n;
      elements += fmt::format("{} 3 2 1 1 {} {} {} {}\n", ++etag, a, b, b + 1, a + 1);
    }
  const auto mesh = [&](const std::string& extra_node, const std::string& extra_element, int more) {
    return "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n" + std::to_string(tag + more) + "\n" + nodes + extra_node +
           "$EndNodes\n$Elements\n" + std::to_string(etag + more) + "\n" + elements + extra_element + "$EndElements\n";
  };
  const auto t0 = std::chrono::steady_clock::now();
  EXPECT_EQ(from_text(mesh("", "", 0)).nodes.size(), static_cast<std::size_t>(n * n));
  // One more node on node 1, in a triangle with nodes 2 and n + 2.
  const InputError e = input_error([&] {
    from_text(mesh(fmt::format("{} 0 0 0\n", tag + 1), fmt::format("{} 2 2 1 1 {} 2 {}\n", etag + 1, tag + 1, n + 2), 1));
  });
  EXPECT_TRUE(contains(e.reason(), fmt::format("node 1 (line 6) and node {} (line {}) coincide", tag + 1, tag + 6)))
      << e.what();
  // The bound is a few times what the linearithmic check takes in a Release build (times
  // kSlowdown under the sanitizers); a check quadratic in the nodes would exceed it by far.
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 5.0 * kSlowdown);
}

TEST(MshReader, AnEntityInHundredsOfThousandsOfGroupsIsRefusedBeforeListing) {
  // One surface entity in 100,000 physical groups, holding 1,700 triangles: listing every
  // membership would take 1.7e8 entries; refused at once instead.
  std::string phys;
  // fmt::format, not " " + std::to_string(p): GCC 12 warns falsely on that (-Wrestrict, GCC bug 105651).
  for (int p = 1; p <= 100000; ++p) phys += fmt::format(" {}", p);
  std::string elements;
  for (int e = 1; e <= 1700; ++e) elements += fmt::format("{} 1 2 3\n", e);
  const std::string text = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Entities\n0 0 1 0\n1 0 0 0 1 1 0 100000" + phys +
                           " 0\n$EndEntities\n$Nodes\n1 3 1 3\n2 1 0 3\n1\n2\n3\n0 0 0\n1 0 0\n0 1 0\n$EndNodes\n"
                           "$Elements\n1 1700 1 1700\n2 1 2 1700\n" + elements + "$EndElements\n";
  const auto t0 = std::chrono::steady_clock::now();
  const InputError e = input_error([&] { from_text(text); });
  EXPECT_TRUE(contains(e.reason(), "physical groups in all, more than the 160000000 Tunica reads")) << e.what();
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 2.0);
}

TEST(MshReader, OneFarAwayNodeDoesNotMakeItsNeighboursCoincide) {
  // Node 6 at x = 1e9 makes the meshed region 1e9 wide; nodes 1 mm apart are not a crack.
  const std::string text = square("5 2 0 0\n6 1e9 0.5 0\n", 6, "3 2 2 1 1 2 5 3\n4 2 2 1 1 5 6 3\n", 4);
  try {
    const SurfaceMesh m = from_text(text);
    EXPECT_EQ(m.nodes.size(), 6u);
  } catch (const InputError& e) {
    EXPECT_FALSE(contains(e.reason(), "coincide")) << e.what();
  }
  // Two nodes at one point beside it still are.
  const std::string crack = square("5 2 0 0\n6 1e9 0.5 0\n7 1 1 0\n", 7, "3 2 2 1 1 2 5 7\n4 2 2 1 1 5 6 7\n", 4);
  const InputError e = input_error([&] { from_text(crack); });
  EXPECT_TRUE(contains(e.reason(), "node 3 (line 12) and node 7 (line 16) coincide at (1, 1, 0)")) << e.what();
}
