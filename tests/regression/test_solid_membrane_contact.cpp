// Contact between a solid part's boundary and a membrane, with the solid entering in step 2
// (theory manual §12.2: the plaque placed in the prestretched, pressurized artery). The slave is the
// plaque's outer surface (the ordered node set plaque.outer of the solid grid), the master the
// artery's meridian (reversed: the slave is inside). Step 1 inflates the artery while the
// plaque is held: the pair is inactive. Step 2 opens the plaque's lumen radially until its
// outer surface presses on the artery and pushes it out.
#include <gtest/gtest.h>

#include <algorithm>

#include "../support/capture.hpp"
#include "../support/solid_decks.hpp"

using namespace tunica;
using namespace tunica::test;

TEST(SolidMembraneContact, ThePlaqueEntersThenPressesTheArteryOutwards) {
  std::string deck = kArteryWithPlaque;
  deck = replace(deck, "  plaque_push: {node_set: plaque.top, dofs: [z]}\n",
                 "  plaque_top: {node_set: plaque.top, dofs: [z]}\n  plaque_open: {node_set: plaque.inner, dofs: [r]}\n");
  deck = replace(deck, "- {name: squeeze, increments: 2, set: {plaque_push: -0.05}}",
                 "- {name: squeeze, increments: 4, set: {plaque_open: 0.3}}");
  deck = replace(deck, "loads:",
                 "contact:\n  fit: {slave: plaque.outer, master: artery, master_orientation: reversed, penalty: 50, "
                 "offset: 0.05}\nloads:");
  deck = replace(deck, "    - {quantity: sigma_thetatheta, part: artery, name: artery_hoop}\n",
                 "    - {quantity: contact_pressure, contact: fit, name: pc}\n"
                 "    - {quantity: contact_penetration, contact: fit, name: pen}\n"
                 "    - {quantity: radius, part: artery, reduce: min, name: r_artery}\n");
  const Model m = read_deck_text(deck, "plaque-contact.yaml");
  ASSERT_EQ(m.contacts.size(), 1u);
  Analysis a(m);
  Capture c;
  a.run(c);
  ASSERT_EQ(c.rows.back().info.step, 2);
  ASSERT_EQ(c.rows.back().info.fraction, 1.0);
  for (const auto& it : c.iterations)
    if (it.info.step == 1) {
      EXPECT_EQ(it.rec.active_contacts, 0) << "the pair must wait for the plaque";
    }
  EXPECT_GT(c.iterations.back().rec.active_contacts, 0);
  const int pc = Capture::column(m, "pc_N_per_mm2"), pen = Capture::column(m, "pen_mm"), r = Capture::column(m, "r_artery_mm");
  ASSERT_GE(pc, 0);
  ASSERT_GE(pen, 0);
  ASSERT_GE(r, 0);
  double r_step1 = 0;
  for (const auto& row : c.rows)
    if (row.info.step == 1) {
      r_step1 = row.values[r];
      EXPECT_EQ(row.values[pc], 0.0);
    }
  const auto& last = c.rows.back().values;
  EXPECT_GT(last[pc], 1e-3);
  EXPECT_GT(last[r], r_step1 + 0.03) << "the artery is pushed out";
  // Penalty law: the largest penetration is about the largest pressure over ε (the pressure
  // output is per current area, the penetration's force per reference area).
  EXPECT_NEAR(last[pen] * 50.0 / last[pc], 1.0, 0.5);
  // The final, pressed state as step 1 would see it: the pair waits for the plaque, so its
  // nodes report no contact (the outputs follow the assembly, which skips a waiting pair).
  double in_step2 = 0;
  for (const auto& s : a.system().contact_states(a.displacement(), 0, 1)) in_step2 = std::max(in_step2, s.pressure);
  EXPECT_GT(in_step2, 1e-3);
  for (const auto& s : a.system().contact_states(a.displacement(), 0, 0)) {
    EXPECT_FALSE(s.point.active) << s.node;
    EXPECT_EQ(s.pressure, 0.0) << s.node;
    EXPECT_EQ(s.force, 0.0) << s.node;
  }
}
