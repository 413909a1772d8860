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
