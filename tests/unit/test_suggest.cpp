// core/suggest.hpp: which names are offered as "did you mean": a likely typo only.
#include <gtest/gtest.h>

#include "core/suggest.hpp"

using namespace tunica;

TEST(Suggest, AFileNameIsOfferedOnlyWhenReallyClose) {
  const std::vector<std::string> files = {"b.msh", "square.msh", "tube_2mm.msh", "wall.geo", "aneurysm.msh"};
  EXPECT_EQ(nearest_file_name("sqare.msh", files), "square.msh");     // a letter dropped
  EXPECT_EQ(nearest_file_name("Square.msh", files), "square.msh");    // letter case
  EXPECT_EQ(nearest_file_name("aneurysn.msh", files), "aneurysm.msh");
  EXPECT_EQ(nearest_file_name("anuerysm.msh", files), "aneurysm.msh");  // two letters swapped
  // A one-letter stem has no typo of another: a.msh is not b.msh.
  EXPECT_EQ(nearest_file_name("a.msh", files), "");
  // Another number is another mesh, not a typo.
  EXPECT_EQ(nearest_file_name("tube_1mm.msh", files), "");
  // Too many edits for the length: `cube` is not `tube_2mm`, `sphere` not `square`.
  EXPECT_EQ(nearest_file_name("sphere.msh", files), "");
  // The same name with another extension: the script of that mesh.
  EXPECT_EQ(nearest_file_name("wall.msh", files), "wall.geo");
  // The same extension first.
  EXPECT_EQ(nearest_file_name("wall.geo", {"wall.msh", "wal.geo"}), "wal.geo");
  EXPECT_EQ(nearest_file_name("wall.msh", {}), "");
}

TEST(Suggest, TheSetsOfAPartAreOfferedOnlyForATypoOfTheSetsName) {
  // `wall.x0` and `wall.y0` share the part's prefix and differ in the set's own name, `x0`:
  // another set, not a typo (a tube without `x0` proposed `y0`); compared by the part's rest as
  // file names by their stems.
  const std::vector<std::string> sets = {"wall.bottom", "wall.top", "wall.y0", "wall.start", "wall.ring2", "wall.all"};
  EXPECT_EQ(nearest_name("wall.x0", sets), "");
  EXPECT_EQ(nearest_name("wall.ring1", sets), "");      // another number is another set
  EXPECT_EQ(nearest_name("wall.strat", sets), "wall.start");  // letters swapped
  EXPECT_EQ(nearest_name("wall.botom", sets), "wall.bottom");
  EXPECT_EQ(nearest_name("wall.Y0", sets), "wall.y0");        // letter case
  EXPECT_EQ(nearest_name("wal.top", sets), "wall.top");       // a typo in the part's name
  // A set's name without its part: the one set that ends in it, and none where two parts have it.
  EXPECT_EQ(nearest_name("start", sets), "wall.start");
  EXPECT_EQ(nearest_name("START", sets), "wall.start");
  EXPECT_EQ(nearest_name("start", {"wall.start", "cap.start"}), "");
  EXPECT_EQ(nearest_name("art", sets), "");  // not after a dot
  // Names without a dot keep their rule.
  EXPECT_EQ(nearest_name("lumne", {"lumen"}), "lumen");
  EXPECT_EQ(nearest_name("mn", {"mm", "cm"}), "mm");
}
