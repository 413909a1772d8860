// The balloon-angioplasty example (examples/balloon-angioplasty.yaml, theory manual §12.2, a draft of
// the paper's §4.2): a prestretched Fung artery, a neo-Hookean solid plaque entering stress
// free, a Mooney–Rivlin balloon entering and inflated to 2.05 N/mm², penalty contact
// plaque–artery and balloon–plaque. Checks what the paper's example shows qualitatively:
// every increment converges (one cut-back at the first touch), the balloon opens the lumen, and the
// balloon–plaque contact pressure is Hertz-like: one contiguous contact zone around the
// stenosis centre, its maximum near the centre, zero beyond its edges.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "../support/capture.hpp"
#include "../support/contact_pairs.hpp"

using namespace tunica;
using namespace tunica::test;

TEST(Angioplasty, TheBalloonOpensTheStenosisWithAHertzLikeContactPressure) {
  const std::string path = std::string(TUNICA_SOURCE_DIR) + "/examples/balloon-angioplasty.yaml";
  const Model m = read_deck_text(read_text(path), path);
  // Two deformable pairs, balloon_plaque with two passes (the deck's `passes: 2`).
  ASSERT_EQ(m.contacts.size(), 3u);
  const int balloon_plaque = contact_pair(m, "balloon_plaque");
  ASSERT_GE(balloon_plaque, 0);
  ASSERT_GE(m.contacts[static_cast<std::size_t>(balloon_plaque)].reverse, 0);
  Analysis a(m);
  Capture c;
  a.run(c);
  ASSERT_EQ(c.rows.back().info.step, 3);
  ASSERT_EQ(c.rows.back().info.fraction, 1.0);
  // The first touch of balloon and plaque: with two passes both meshes' nodes
  // enter the active set at once, and the increment where they touch is retried once at half
  // the size (11 iterations); every other increment takes at most 8.
  EXPECT_LE(c.cutbacks, 1);
  int most = 0;
  for (const auto& row : c.rows) most = std::max(most, row.info.iterations);
  EXPECT_LE(most, 11);

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
  const auto states = a.system().contact_states(a.displacement(), balloon_plaque, a.loads().step);
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

namespace {

struct PenaltyRun {
  double peak = 0, force = 0, penetration = 0, lumen = 0;
  int cutbacks = 0;
  bool complete = false;
};

/// The example deck with both contact penalties scaled by `factor`, run to the end.
PenaltyRun run_with_penalty(const std::string& factor_text) {
  const std::string path = std::string(TUNICA_SOURCE_DIR) + "/examples/balloon-angioplasty.yaml";
  std::string deck = read_text(path);
  for (int pair = 0; pair < 2; ++pair)
    deck = replace(deck, "    penalty: 2e3 N/mm^3\n", "    penalty: " + factor_text + " N/mm^3\n");
  const Model m = read_deck_text(deck, path);
  Analysis a(m);
  Capture c;
  a.run(c);
  PenaltyRun r;
  r.complete = c.rows.back().info.step == 3 && c.rows.back().info.fraction == 1.0;
  r.cutbacks = c.cutbacks;
  r.force = c.rows.back().values[Capture::column(m, "force_balloon_plaque_N")];
  r.penetration = c.rows.back().values[Capture::column(m, "pen_balloon_plaque_mm")];
  r.lumen = c.rows.back().values[Capture::column(m, "lumen_min_mm")];
  for (const auto& s : a.system().contact_states(a.displacement(), contact_pair(m, "balloon_plaque"), a.loads().step))
    r.peak = std::max(r.peak, s.pressure);
  return r;
}

}  // namespace

// The penalty study as a regression: ten times both penalties (2e3 → 2e4 N/mm³)
// changes the maximum balloon–plaque contact pressure at 2.05 N/mm² by under 2 %, and the
// penetration falls about tenfold (docs/examples/balloon-angioplasty.md, "Penalty study").
TEST(Angioplasty, TenfoldPenaltyChangesThePeakContactPressureByUnderTwoPercent) {
  const PenaltyRun base = run_with_penalty("2e3"), stiff = run_with_penalty("2e4");
  ASSERT_TRUE(base.complete);
  ASSERT_TRUE(stiff.complete);
  std::printf("penalty x1 / x10: peak %.4f / %.4f N/mm2 (%+.2f %%), penetration %.3g / %.3g mm, force %.5f / %.5f N, "
              "cut-backs %d / %d\n",
              base.peak, stiff.peak, 100 * (stiff.peak / base.peak - 1), base.penetration, stiff.penetration, base.force,
              stiff.force, base.cutbacks, stiff.cutbacks);
  EXPECT_NEAR(stiff.peak / base.peak, 1.0, 0.02);
  EXPECT_GT(base.penetration / stiff.penetration, 8.0);
  EXPECT_LT(base.penetration / stiff.penetration, 12.0);
  EXPECT_NEAR(stiff.force / base.force, 1.0, 0.01);
  EXPECT_NEAR(stiff.lumen, base.lumen, 1e-3);
}
