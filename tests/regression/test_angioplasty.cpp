// The balloon-angioplasty example (examples/balloon-angioplasty.yaml, THEORY §6, a draft of
// the paper's §4.2): a prestretched Fung artery, a neo-Hookean solid plaque entering stress
// free, a Mooney–Rivlin balloon entering and inflated to 2.05 N/mm², penalty contact
// plaque–artery and balloon–plaque. Checks what the paper's example shows qualitatively:
// every increment converges without cut-backs, the balloon opens the lumen, and the
// balloon–plaque contact pressure is Hertz-like: one contiguous contact zone around the
// stenosis centre, its maximum near the centre, zero beyond its edges.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "../support/capture.hpp"

using namespace tunica;
using namespace tunica::test;

TEST(Angioplasty, TheBalloonOpensTheStenosisWithAHertzLikeContactPressure) {
  const std::string path = std::string(TUNICA_SOURCE_DIR) + "/examples/balloon-angioplasty.yaml";
  const Model m = read_deck_text(read_text(path), path);
  ASSERT_EQ(m.contacts.size(), 2u);
  Analysis a(m);
  Capture c;
  a.run(c);
  ASSERT_EQ(c.rows.back().info.step, 3);
  ASSERT_EQ(c.rows.back().info.fraction, 1.0);
  EXPECT_EQ(c.cutbacks, 0);
  int most = 0;
  for (const auto& row : c.rows) most = std::max(most, row.info.iterations);
  EXPECT_LE(most, 8);

  const int lumen = Capture::column(m, "lumen_min_mm"), pc = Capture::column(m, "pc_balloon_plaque_MPa"),
            pa = Capture::column(m, "pc_plaque_artery_MPa");
  const double lumen_before = 0.39;  // the stenosis' lumen radius at its centre (deck)
  EXPECT_GT(c.rows.back().values[lumen], lumen_before + 0.02) << "the balloon opens the lumen";
  double peak = 0;
  for (const auto& row : c.rows) peak = std::max(peak, row.values[pc]);
  EXPECT_GT(peak, 0.05);
  EXPECT_LT(peak, 2.05) << "the contact pressure stays below the balloon pressure";
  EXPECT_GT(c.rows.back().values[pa], 0.0) << "the plaque is pressed on the artery";

  // The balloon's slave nodes in meridian order (pole to pole) at the end.
  const auto states = a.system().contact_states(a.displacement(), 1, a.loads().step);
  ASSERT_GT(states.size(), 20u);
  std::vector<int> active;
  std::size_t top = 0;
  for (std::size_t k = 0; k < states.size(); ++k) {
    if (states[k].pressure > 0) active.push_back(static_cast<int>(k));
    if (states[k].pressure > states[top].pressure) top = k;
  }
  ASSERT_GE(active.size(), 3u);
  // One contiguous zone, inactive on both sides of it (the poles are held on the catheter).
  EXPECT_EQ(active.back() - active.front() + 1, static_cast<int>(active.size()));
  EXPECT_GT(active.front(), 0);
  EXPECT_LT(active.back(), static_cast<int>(states.size()) - 1);
  // The maximum near the stenosis centre (z = 2 mm after the prestretch to 4 mm), the edges low.
  const auto z = [&](std::size_t k) { return m.X[states[k].node](1) + a.displacement()(2 * states[k].node + 1); };
  EXPECT_NEAR(z(top), 2.0, 0.3);
  EXPECT_LT(states[active.front()].pressure, 0.5 * states[top].pressure);
  EXPECT_LT(states[active.back()].pressure, 0.5 * states[top].pressure);
}
