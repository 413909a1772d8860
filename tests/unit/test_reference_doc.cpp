// The deck reference in docs/ is generated from the parameter declarations
// (`tunica reference`); this test fails when the two drift apart.
// Regenerate with: build/tunica reference > docs/deck-reference.md
#include <gtest/gtest.h>

#include "../support/capture.hpp"
#include "io/reference.hpp"

TEST(ReferenceDoc, DocsDeckReferenceIsTheGeneratedOne) {
  const std::string doc = tunica::test::read_text(std::string(TUNICA_SOURCE_DIR) + "/docs/deck-reference.md");
  EXPECT_EQ(doc, tunica::deck_reference_markdown())
      << "docs/deck-reference.md is stale: run `build/tunica reference > docs/deck-reference.md`";
}

TEST(ReferenceDoc, EveryMaterialAndSectionIsDocumented) {
  const std::string ref = tunica::deck_reference_markdown();
  for (const char* s : {"`type: fung`", "`type: neo_hookean`", "`type: mooney_rivlin`", "`type: line`", "`type: arc`",
                        "## `units`", "## `steps`", "## `output.history`", "`reaction_z`"})
    EXPECT_NE(ref.find(s), std::string::npos) << s;
}
