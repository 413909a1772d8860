// Bad 3-D meshes and 3-D deck mistakes get clear errors through the real CLI
// (`tunica check`): exit 2, one line naming the file and the key, no crash.
// Meshes are small hand-written Gmsh 2.2 files: a unit square of two triangles
// in the plane z = 0, broken in one way per test.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>

#include "../support/capture.hpp"
#include "../support/cli.hpp"
#include "../support/scratch.hpp"

using namespace tunica::test;
namespace fs = std::filesystem;

namespace {

/// A Gmsh 2.2 mesh: nodes 1–5 ((0,0), (1,0), (1,1), (0,1), (2,0) in z = 0), the given
/// triangles on physical surface 1 "wall", and physical curve 10 "edge" (line 1–2).
std::string msh(const std::string& triangles, int count) {
  return "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n2\n1 10 \"edge\"\n2 1 \"wall\"\n$EndPhysicalNames\n"
         "$Nodes\n5\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n5 2 0 0\n$EndNodes\n$Elements\n" +
         std::to_string(count + 1) + "\n1 1 2 10 1 1 2\n" + triangles + "$EndElements\n";
}

const std::string kGood = "2 2 2 1 1 1 2 3\n3 2 2 1 1 1 3 4\n";

const char* kDeck = R"(units: {length: mm, force: N}
materials:
  rubber: {type: neo_hookean, mu: 1 MPa}
  fung: {type: fung, c: 0.05, a1: 1, a2: 1, a4: 0}
parts:
  wall:
    element: membrane
    material: rubber
    thickness: 0.1 mm
    mesh: {type: gmsh, file: square.msh, surface: wall}
boundary:
  fixed: {node_set: edge, dofs: [x, y, z]}
loads:
  p: {type: pressure, part: wall}
steps:
  - {increments: 1, set: {p: 0.001}}
)";

/// Writes the mesh and the deck (with `from` replaced by `to`), runs `tunica check`, expects
/// exit 2 and one line holding the key and `what`.
void expect_error(const std::string& name, const std::string& mesh, const std::string& from, const std::string& to,
                  const std::string& key, const std::string& what) {
  const fs::path dir = scratch("bad-meshes", name);
  std::ofstream(dir / "square.msh") << mesh;
  const std::string deck_text = from.empty() ? std::string(kDeck) : replace(kDeck, from, to);
  std::ofstream(dir / "deck.yaml") << deck_text;
  const Outcome o = run_cli("check " + (dir / "deck.yaml").string());
  EXPECT_EQ(o.exit_code, 2) << o.output;
  EXPECT_NE(o.output.find("key '" + key + "'"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find(what), std::string::npos) << o.output;
  EXPECT_EQ(std::count(o.output.begin(), o.output.end(), '\n'), 1) << "one line of message: " << o.output;
  EXPECT_EQ(o.output.find("terminate called"), std::string::npos) << o.output;
}

}  // namespace

TEST(BadMeshes, TheGoodSquareIsValid) {
  const fs::path dir = scratch("bad-meshes", "good");
  std::ofstream(dir / "square.msh") << msh(kGood, 2);
  std::ofstream(dir / "deck.yaml") << kDeck;
  const Outcome o = run_cli("check " + (dir / "deck.yaml").string());
  EXPECT_EQ(o.exit_code, 0) << o.output;
  EXPECT_NE(o.output.find("4 node(s), 2 element(s)"), std::string::npos) << o.output;
}

TEST(BadMeshes, InvertedElementIsNamed) {
  // Named by the mesh file and its own element and node tags.
  expect_error("inverted", msh("2 2 2 1 1 1 2 3\n3 2 2 1 1 1 4 3\n", 2), "", "", "parts.wall.mesh.surface",
               "inverted/square.msh: surface 'wall': element 3 (a triangle, line 21) is inverted");
}

TEST(BadMeshes, DegenerateElementIsNamed) {
  expect_error("degenerate", msh(kGood + "4 2 2 1 1 1 2 5\n", 3), "", "", "parts.wall.mesh.surface",
               "element 4 (a triangle, line 22) is degenerate (area 0, longest edge 2); its nodes are [1, 2, 5]");
}

TEST(BadMeshes, MissingPhysicalSurfaceIsNamed) {
  expect_error("missing-surface", msh(kGood, 2), "surface: wall}", "surface: vessel}", "parts.wall.mesh.surface",
               "no physical surface 'vessel' (it has: wall)");
}

TEST(BadMeshes, MissingMeshFileIsNamed) {
  expect_error("missing-file", msh(kGood, 2), "file: square.msh", "file: nowhere.msh", "parts.wall.mesh.file",
               "nowhere.msh");
}

TEST(BadMeshes, FrameDirectionNormalToTheSurfaceIsRefused) {
  expect_error("normal-frame", msh(kGood, 2), "    mesh: {type: gmsh",
               "    frame: {type: vector, direction: [0, 0, 1]}\n    mesh: {type: gmsh", "parts.wall.frame",
               "normal to the surface");
}

TEST(BadMeshes, AnisotropicMaterialNeedsAFrame) {
  expect_error("no-frame", msh(kGood, 2), "material: rubber", "material: fung", "parts.wall.frame", "anisotropic");
}

TEST(BadMeshes, AxisymmetricDofNamesAreRefusedIn3d) {
  expect_error("dof-r", msh(kGood, 2), "dofs: [x, y, z]", "dofs: [r, z]", "boundary.fixed.dofs[0]", "3-D DOFs are x, y and z");
}

TEST(BadMeshes, AxisymmetricAnd3dPartsDoNotMix) {
  expect_error("mixed", msh(kGood, 2), "boundary:",
               "  tube:\n    element: axisymmetric_membrane\n    material: rubber\n    thickness: 0.1\n"
               "    mesh: {type: line, from: [1, 0], to: [1, 1], elements: 2}\nboundary:",
               "parts.tube.element", "cannot be mixed");
}

TEST(BadMeshes, VolumeControlOfAnUndefinedLoad) {
  expect_error("volume-control", msh(kGood, 2), "{increments: 1, set: {p: 0.001}}",
               "{increments: 1, volume_control: {load: q, volume: 1}}", "steps[0].volume_control.load", "undefined pressure load 'q'");
}

TEST(BadMeshes, ADeckNamingAScriptIsRefusedUnlessScriptsAreAllowed) {
  const fs::path dir = scratch("bad-meshes", "script");
  const fs::path marker = dir / "script-ran";
  // The square as a script that also runs a command.
  std::ofstream(dir / "square.geo") << "System \"touch " << marker.string() << "\";\n"
                                    << "Point(1) = {0, 0, 0, 1}; Point(2) = {1, 0, 0, 1}; Point(3) = {1, 1, 0, 1};\n"
                                       "Point(4) = {0, 1, 0, 1}; Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4};\n"
                                       "Line(4) = {4, 1}; Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};\n"
                                       "Physical Surface(\"wall\") = {1}; Physical Curve(\"edge\") = {1};\n";
  std::ofstream(dir / "deck.yaml") << replace(kDeck, "file: square.msh", "file: square.geo");
  Outcome o = run_cli("check " + (dir / "deck.yaml").string());
  EXPECT_EQ(o.exit_code, 2) << o.output;
  EXPECT_NE(o.output.find("square.geo: this is a Gmsh script (.geo), which can run commands: Tunica meshes one only "
                          "with --allow-scripts"),
            std::string::npos)
      << o.output;
  EXPECT_NE(o.output.find("key 'parts.wall.mesh.file'"), std::string::npos) << o.output;
  EXPECT_EQ(std::count(o.output.begin(), o.output.end(), '\n'), 1) << o.output;
  EXPECT_FALSE(fs::exists(marker)) << "a refused script ran";
  o = run_cli("run " + (dir / "deck.yaml").string() + " -q -o " + (dir / "out").string());
  EXPECT_EQ(o.exit_code, 2) << o.output;
  EXPECT_FALSE(fs::exists(marker)) << "a refused script ran";
  // Allowed: it runs, and the deck is valid.
  o = run_cli("check --allow-scripts " + (dir / "deck.yaml").string());
  EXPECT_EQ(o.exit_code, 0) << o.output;
  EXPECT_TRUE(fs::exists(marker));
  // `tunica mesh` makes a .msh of it that the deck reads as data.
  fs::remove(marker);
  o = run_cli("mesh " + (dir / "square.geo").string() + " -o " + (dir / "square.msh").string() + " --binary");
  EXPECT_EQ(o.exit_code, 0) << o.output;
  EXPECT_TRUE(fs::exists(marker));
  std::ofstream(dir / "deck.yaml") << kDeck;
  o = run_cli("check " + (dir / "deck.yaml").string());
  EXPECT_EQ(o.exit_code, 0) << o.output;
}

TEST(BadMeshes, ADeviceOrAHugeHeaderIsRefusedAtOnce) {
  const auto t0 = std::chrono::steady_clock::now();
  Outcome o = run_cli("check /dev/zero");
  EXPECT_EQ(o.exit_code, 2) << o.output;
  EXPECT_NE(o.output.find("/dev/zero: cannot read the deck: it is not a regular file"), std::string::npos) << o.output;
  // A mesh whose header announces 10^9 nodes.
  const fs::path dir = scratch("bad-meshes", "huge");
  std::ofstream(dir / "square.msh") << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 1000000000 1 1000000000\n";
  std::ofstream(dir / "deck.yaml") << kDeck;
  o = run_cli("check " + (dir / "deck.yaml").string());
  EXPECT_EQ(o.exit_code, 2) << o.output;
  EXPECT_NE(o.output.find("square.msh:5: the file announces 1000000000 nodes; at most 10000000 are allowed"),
            std::string::npos)
      << o.output;
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 2.0);
  // The largest child of this test process (CTest runs each test in a process of its own).
  struct rusage children {};
  getrusage(RUSAGE_CHILDREN, &children);
  EXPECT_LT(children.ru_maxrss, 100 * 1024) << "kB";
}

TEST(BadMeshes, TunicaMeshRefusesWhatIsNotAScriptOrNotAMeshFileAndBadResults) {
  const fs::path dir = scratch("bad-meshes", "mesh-command");
  std::ofstream(dir / "square.msh") << msh(kGood, 2);
  Outcome o = run_cli("mesh " + (dir / "square.msh").string() + " -o " + (dir / "out.msh").string());
  EXPECT_EQ(o.exit_code, 2) << o.output;
  EXPECT_NE(o.output.find("this file is not named .geo"), std::string::npos) << o.output;
  const std::string square = "Point(1) = {0, 0, 0, 1}; Point(2) = {1, 0, 0, 1}; Point(3) = {1, 1, 0, 1};\n"
                             "Point(4) = {0, 1, 0, 1}; Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4};\n"
                             "Line(4) = {4, 1}; Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};\n"
                             "Physical Surface(\"wall\") = {1};\n";
  std::ofstream(dir / "square.geo") << square;
  o = run_cli("mesh " + (dir / "square.geo").string() + " -o " + (dir / "square.geo").string());
  EXPECT_EQ(o.exit_code, 2) << o.output;
  EXPECT_NE(o.output.find("must be named .msh"), std::string::npos) << o.output;
  const fs::path fifo = dir / "fifo.msh";
  fs::remove(fifo);
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  o = run_cli("mesh " + (dir / "square.geo").string() + " -o " + fifo.string());
  EXPECT_EQ(o.exit_code, 2) << o.output;
  EXPECT_NE(o.output.find("not a regular file"), std::string::npos) << o.output;
  // A script whose mesh decks could not use: refused, nothing written.
  std::ofstream(dir / "order3.geo") << "Mesh.ElementOrder = 3;\n" << square;
  o = run_cli("mesh " + (dir / "order3.geo").string() + " -o " + (dir / "order3.msh").string());
  EXPECT_EQ(o.exit_code, 2) << o.output;
  EXPECT_NE(o.output.find("order3.geo: key 'wall': physical surface 'wall': element"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("nothing was written"), std::string::npos) << o.output;
  EXPECT_FALSE(fs::exists(dir / "order3.msh"));
  // A script that exits before Gmsh writes anything: named, not the temporary file.
  std::ofstream(dir / "exits.geo") << square << "Exit;\n";
  o = run_cli("mesh " + (dir / "exits.geo").string() + " -o " + (dir / "exits.msh").string());
  EXPECT_EQ(o.exit_code, 2) << o.output;
  EXPECT_NE(o.output.find("exits.geo: the script ended before Gmsh wrote a mesh"), std::string::npos) << o.output;
}

TEST(BadMeshes, APhysicalSurfaceThatHoldsNoElementsIsNamedWithItsTagAndTheLikelyCause) {
  // `Physical Surface("sac") = {7};` where the geometry has only surface 1 (as after a
  // BooleanFragments renumbered the surfaces): Gmsh writes the name and no element of it.
  const fs::path dir = scratch("bad-meshes", "empty-group");
  const std::string square = "Point(1) = {0, 0, 0, 1}; Point(2) = {1, 0, 0, 1}; Point(3) = {1, 1, 0, 1};\n"
                             "Point(4) = {0, 1, 0, 1}; Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4};\n"
                             "Line(4) = {4, 1}; Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};\n";
  std::ofstream(dir / "sac.geo") << square << "Physical Surface(\"sac\") = {7};\n";
  Outcome o = run_cli("mesh " + (dir / "sac.geo").string() + " -o " + (dir / "sac.msh").string());
  EXPECT_EQ(o.exit_code, 2) << o.output;
  EXPECT_EQ(std::count(o.output.begin(), o.output.end(), '\n'), 1) << o.output;
  EXPECT_NE(o.output.find((dir / "sac.geo").string() +
                          ":4: key 'sac': physical surface 'sac' (tag 1) is defined but holds no elements: none of "
                          "the surfaces it lists exists in the geometry Gmsh meshed"),
            std::string::npos)
      << o.output;
  EXPECT_NE(o.output.find("surface numbers that do not exist after the geometry operations (BooleanFragments"),
            std::string::npos)
      << o.output;
  EXPECT_NE(o.output.find("the geometry's surfaces are numbered 1: check the numbering, e.g. in the Gmsh GUI"),
            std::string::npos)
      << o.output;
  EXPECT_EQ(o.output.find("defines no physical surface"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("nothing was written"), std::string::npos) << o.output;
  // Beside a group that holds elements, the empty one is named all the same, by its own tag and line.
  std::ofstream(dir / "two.geo") << square << "Physical Surface(\"wall\") = {1};\n"
                                 << "Physical Surface( \"sac\" ) = {7, 8};\n";
  o = run_cli("mesh " + (dir / "two.geo").string() + " -o " + (dir / "two.msh").string());
  EXPECT_EQ(o.exit_code, 2) << o.output;
  EXPECT_NE(o.output.find((dir / "two.geo").string() +
                          ":5: key 'sac': physical surface 'sac' (tag 2) is defined but holds no elements"),
            std::string::npos)
      << o.output;
  EXPECT_FALSE(fs::exists(dir / "two.msh"));
  // A mesh file that names a physical surface no element belongs to.
  std::string empty = msh(kGood, 2);
  empty.replace(empty.find("$PhysicalNames\n2\n"), 17, "$PhysicalNames\n3\n2 7 \"sac\"\n");
  std::ofstream(dir / "square.msh") << empty;
  std::ofstream(dir / "deck.yaml") << kDeck;
  o = run_cli("check " + (dir / "deck.yaml").string());
  EXPECT_EQ(o.exit_code, 2) << o.output;
  EXPECT_NE(o.output.find("square.msh: key 'sac': physical surface 'sac' (tag 7) is named in $PhysicalNames but holds "
                          "no elements: no surface of the file belongs to it"),
            std::string::npos)
      << o.output;
}

TEST(BadMeshes, AFailedTunicaMeshSaysTheEarlierMeshIsKeptAndWhyAnEdgeLoopDoesNotClose) {
  // Two strips extruded from lines whose shared end is two points at the same position: with
  // AutoCoherence off they are not merged, and Gmsh stops with "not forming a closed loop",
  // naming no curve.
  const fs::path dir = scratch("bad-meshes", "open-loop");
  std::ofstream(dir / "strip.geo") << "Geometry.AutoCoherence = 0;\n"
                                      "Point(1) = {0, 0, 0, 0.25}; Point(2) = {1, 0, 0, 0.25};\n"
                                      "Point(3) = {1, 0, 0, 0.25}; Point(4) = {2, 0, 0, 0.25};\n"
                                      "Line(1) = {1, 2}; Line(2) = {3, 4};\n"
                                      "a[] = Extrude {0, 1, 0} { Curve{1}; };\n"
                                      "b[] = Extrude {0, 1, 0} { Curve{2}; };\n"
                                      "Physical Surface(\"wall\") = {a[1], b[1]};\n";
  fs::remove(dir / "strip.msh");
  Outcome o = run_cli("mesh " + (dir / "strip.geo").string() + " -o " + (dir / "strip.msh").string());
  EXPECT_EQ(o.exit_code, 2) << o.output;
  EXPECT_NE(o.output.find("closed loop"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("points at the same position that are not merged"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("add `Coherence;` after the geometry"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("curves that do not meet"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("nothing was written (" + (dir / "strip.msh").string() + " was not created)"),
            std::string::npos)
      << o.output;
  EXPECT_FALSE(fs::exists(dir / "strip.msh"));
  // An earlier mesh of that name stays as it was, and the message says so.
  std::ofstream(dir / "strip.msh") << "earlier";
  o = run_cli("mesh " + (dir / "strip.geo").string() + " -o " + (dir / "strip.msh").string());
  EXPECT_EQ(o.exit_code, 2) << o.output;
  EXPECT_NE(o.output.find("the earlier " + (dir / "strip.msh").string() + " is left unchanged"), std::string::npos)
      << o.output;
  EXPECT_EQ(read_text((dir / "strip.msh").string()), "earlier");
}

TEST(BadMeshes, TerminatingTunicaMeshEndsGmshAndLeavesNoTemporaryFolder) {
  const fs::path dir = scratch("bad-meshes", "mesh-sigterm");
  fs::create_directories(dir / "tmp");
  const fs::path marker = dir / "still-running";
  std::ofstream(dir / "slow.geo") << "System \"sleep 3; touch " << marker.string() << "\";\nPoint(1) = {0, 0, 0};\n";
  const std::string cmd = "TMPDIR=" + (dir / "tmp").string() + " " + TUNICA_BINARY + " mesh " +
                          (dir / "slow.geo").string() + " -o " + (dir / "slow.msh").string() + " & pid=$!; sleep 1; "
                          "kill -TERM $pid; wait $pid; echo exit $?";
  FILE* p = popen(cmd.c_str(), "r");
  char buf[256] = {};
  std::string out;
  while (std::fgets(buf, sizeof buf, p)) out += buf;
  pclose(p);
  EXPECT_NE(out.find("exit 143"), std::string::npos) << out;
  EXPECT_TRUE(fs::is_empty(dir / "tmp")) << "the temporary folder was left";
  ::sleep(4);  // the script's command would have finished by now
  EXPECT_FALSE(fs::exists(marker)) << "the script's commands went on after tunica was stopped";
}

TEST(BadMeshes, NodeSetsOfOneNameFromTwoPhysicalGroupsAreRefused) {
  const std::string two = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n3\n1 10 \"edge\"\n1 11 \"edge\"\n"
                          "2 1 \"wall\"\n$EndPhysicalNames\n$Nodes\n5\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n5 2 0 0\n"
                          "$EndNodes\n$Elements\n4\n1 1 2 10 1 1 2\n5 1 2 11 2 3 4\n" + kGood + "$EndElements\n";
  expect_error("two-edges", two, "", "", "edge", "physical groups 10 (dimension 1) and 11 (dimension 1) are both named 'edge'");
}

TEST(BadMeshes, AFoldedQuadrilateralIsNamedByTheMeshFileAndItsTags) {
  // A quadrilateral of the shipped quarter cylinder (4.1 binary) with a node moved by a
  // corrupted byte: it passes the surface checks and is folded at a Gauss point.
  const fs::path dir = scratch("bad-meshes", "folded");
  fs::copy_file(fs::path(TUNICA_SOURCE_DIR) / "tests/data/bad-meshes/folded-quad-v41-binary.msh", dir / "square.msh",
                fs::copy_options::overwrite_existing);
  std::ofstream(dir / "deck.yaml") << kDeck;
  const Outcome o = run_cli("check " + (dir / "deck.yaml").string());
  EXPECT_EQ(o.exit_code, 2) << o.output;
  EXPECT_NE(o.output.find("key 'parts.wall.mesh': part 'wall': " + (dir / "square.msh").string() +
                          ": element 18 (a quadrilateral, nodes 19, 13, 14, 20): folded quadrilateral"),
            std::string::npos)
      << o.output;
}

TEST(BadMeshes, ControlCharactersFromAMeshNeverReachTheTerminal) {
  // A physical curve named with an escape sequence: the deck's node set 'edge' is undefined, and
  // the message listing the node sets there are shows the name escaped, on one printable line.
  std::string mesh = msh(kGood, 2);
  mesh = replace(mesh, "1 10 \"edge\"", "1 10 \"ed\x1b[31mge\"");
  expect_error("control-name", mesh, "", "", "boundary.fixed.node_set", "undefined node set 'edge'");
  const fs::path dir = scratch("bad-meshes") / "control-name";
  const Outcome o = run_cli("check " + (dir / "deck.yaml").string());
  EXPECT_EQ(o.output.find('\x1b'), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("ed\\x1B[31mge"), std::string::npos) << o.output;
}
