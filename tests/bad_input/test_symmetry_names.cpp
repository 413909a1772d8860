// A symmetry boundary that holds one DOF of a node set lying on a coordinate plane normal to
// another axis is likely a swapped name (model/symmetry_plane_check.hpp): a user's Gmsh quarter
// tube named its x = 0 edge "y0" and its y = 0 edge "x0", the deck held x of "x0" and y of "y0",
// and the edges slid along the wrong planes with no word; a neo-Hookean tube then "carried" a
// pressure beyond its largest. The warning stands at the boundary's line, names the plane and
// the DOF a symmetry plane there holds; the right assignment is not warned about.
#include <gtest/gtest.h>

#include "../support/capture.hpp"
#include "../support/cli.hpp"
#include "../support/deck_files.hpp"

using namespace tunica::test;

namespace {

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  return text.replace(text.find(from), from.size(), to);
}

}  // namespace

TEST(SymmetryNames, ASetOnOnePlaneHoldingTheOtherPlanesDofIsWarnedAtItsBoundary) {
  const std::string quarter = read_text(std::string(TUNICA_SOURCE_DIR) + "/examples/rat-aorta-3d.yaml");
  const Outcome right = run_cli("check " + write_deck_file("tunica-symmetry-names", "right", quarter));
  EXPECT_EQ(right.exit_code, 0) << right.output;
  EXPECT_EQ(right.output.find("symmetry plane there"), std::string::npos) << right.output;
  // The two sets swapped, as a mesh with swapped names gives them.
  const std::string swapped =
      replaced(replaced(quarter, "sym_x:   {node_set: wall.x0, dofs: [x]}", "sym_x:   {node_set: wall.y0, dofs: [x]}"),
               "sym_y:   {node_set: wall.y0, dofs: [y]}", "sym_y:   {node_set: wall.x0, dofs: [y]}");
  const std::string path = write_deck_file("tunica-symmetry-names", "swapped", swapped);
  const Outcome o = run_cli("check " + path);
  EXPECT_EQ(o.exit_code, 0) << o.output;
  const int line_x = line_of(swapped, "sym_x:"), line_y = line_of(swapped, "sym_y:");
  EXPECT_NE(o.output.find(path + ":" + std::to_string(line_x) + ":"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find(path + ":" + std::to_string(line_y) + ":"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("boundary 'sym_x' holds x of node set 'wall.y0', whose"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("nodes all lie on the plane y = 0 mm (which the surface crosses there): a symmetry plane "
                          "there holds y"),
            std::string::npos)
      << o.output;
  EXPECT_NE(o.output.find("hold `dofs: [y]`"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("boundary 'sym_y' holds y of node set 'wall.x0'"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("hold `dofs: [x]`"), std::string::npos) << o.output;
  // The end rings hold z on the planes z = const: right, not warned about.
  EXPECT_EQ(o.output.find("boundary 'base'"), std::string::npos) << o.output;
  EXPECT_EQ(o.output.find("boundary 'stretch'"), std::string::npos) << o.output;
}
