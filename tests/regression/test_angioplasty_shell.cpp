// The angioplasty with the artery and the balloon as Kirchhoff–Love shells
// (examples/balloon-angioplasty-shell.yaml, balloon of 51 elements) against the membrane
// deck (examples/balloon-angioplasty.yaml) on the same meshes (51-element balloon, 5 × 100
// plaque, the shell deck's; the membrane deck has 101 and 5 × 300): the paper's
// shell cross-check (theory manual §12.2), "almost identical results". Checks: both reach
// 2.05 N/mm² without cut-backs; the lumen opens to within 1e-3 mm of the membranes'; the
// peak contact pressure agrees within 2 % and the total balloon–plaque contact force within
// 4 % (3 % lower with shells); the contact zone is one contiguous run of balloon nodes around
// the stenosis centre.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "../support/capture.hpp"
#include "../support/contact_pairs.hpp"

using namespace tunica;
using namespace tunica::test;

namespace {

struct AngioplastyResult {
  double lumen = 0, force = 0, peak = 0, zone_centre = 0;
  int cutbacks = 0, zone_nodes = 0;
  bool contiguous = false, complete = false;
};

AngioplastyResult run(const std::string& name, int balloon_elements) {
  const std::string path = std::string(TUNICA_SOURCE_DIR) + "/examples/" + name;
  std::string deck = read_text(path);
  const std::string n = std::to_string(balloon_elements);
  if (deck.find("end_angle: 90 deg, elements: " + n + "}") == std::string::npos) {  // the membrane deck: 101
    deck = replace(deck, "end_angle: 90 deg, elements: 101}", "end_angle: 90 deg, elements: " + n + "}");
    deck = replace(deck, "balloon_poles: {part: balloon, nodes: [0, 101]}",
                   "balloon_poles: {part: balloon, nodes: [0, " + n + "]}");
    // The shell deck's plaque mesh (5 × 100 instead of 5 × 300), its middle node row held in z.
    deck = replace(deck, "elements_z: 300\n", "elements_z: 100\n");
    deck = replace(deck, "plaque_mid: {part: plaque, nodes: [900, 901, 902, 903, 904, 905]}",
                   "plaque_mid: {part: plaque, nodes: [300, 301, 302, 303, 304, 305]}");
  }
  const Model m = read_deck_text(deck, path);
  Analysis a(m);
  Capture c;
  a.run(c);
  AngioplastyResult r;
  r.complete = c.rows.back().info.step == 3 && c.rows.back().info.fraction == 1.0;
  r.cutbacks = c.cutbacks;
  r.lumen = c.rows.back().values[Capture::column(m, "lumen_min_mm")];
  r.force = c.rows.back().values[Capture::column(m, "force_balloon_plaque_N")];
  const auto states = a.system().contact_states(a.displacement(), contact_pair(m, "balloon_plaque"), a.loads().step);
  std::vector<int> active;
  for (std::size_t k = 0; k < states.size(); ++k)
    if (states[k].pressure > 0) active.push_back(static_cast<int>(k));
  r.zone_nodes = static_cast<int>(active.size());
  r.contiguous = !active.empty() && active.back() - active.front() + 1 == r.zone_nodes;
  for (const auto& s : states) r.peak = std::max(r.peak, s.pressure);
  if (!active.empty()) {
    const int mid = active[active.size() / 2];
    const int node = states[static_cast<std::size_t>(mid)].node;
    r.zone_centre = m.X[node](1) + a.displacement()(2 * node + 1);
  }
  return r;
}

}  // namespace

TEST(AngioplastyShell, ShellsGiveNearlyTheMembraneResult) {
  const AngioplastyResult mem = run("balloon-angioplasty.yaml", 51), shell = run("balloon-angioplasty-shell.yaml", 51);
  ASSERT_TRUE(mem.complete);
  ASSERT_TRUE(shell.complete);
  EXPECT_EQ(mem.cutbacks, 0);
  EXPECT_EQ(shell.cutbacks, 0);
  EXPECT_NEAR(shell.lumen, mem.lumen, 1e-3);
  EXPECT_NEAR(shell.force / mem.force, 1.0, 0.04);  // 3 % lower: the stiffer balloon carries more itself
  EXPECT_TRUE(shell.contiguous);
  EXPECT_GE(shell.zone_nodes, 5);
  EXPECT_NEAR(shell.zone_centre, 2.0, 0.05);
  EXPECT_NEAR(shell.peak / mem.peak, 1.0, 0.02);
  std::printf("membrane vs shell: lumen %.4f / %.4f mm, contact force %.4f / %.4f N, peak %.4f / %.4f N/mm², "
              "zone %d / %d nodes, cut-backs %d / %d\n",
              mem.lumen, shell.lumen, mem.force, shell.force, mem.peak, shell.peak, mem.zone_nodes,
              shell.zone_nodes, mem.cutbacks, shell.cutbacks);
}
