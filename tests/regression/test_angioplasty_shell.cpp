// The angioplasty with the artery and the balloon as Kirchhoff–Love shells
// (examples/balloon-angioplasty-shell.yaml) against the membrane deck
// (examples/balloon-angioplasty.yaml): the paper's shell cross-check (THEORY §6),
// "almost identical results". Checks: the shell run reaches 2.05 N/mm² (automatic
// cut-backs allowed: the stiffer balloon makes the contact active set harder to
// settle), the lumen opens to within 1e-3 mm of the membranes', the total balloon–plaque
// contact force is within 5 %, the contact zone is one contiguous run of balloon nodes
// around the stenosis centre, and the contact pressure smoothed over 3 neighbouring nodes
// (the node-to-segment pressure oscillates from node to node, 0.04 … 0.28 N/mm², in both
// models) peaks within 10 % of the membranes'.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "../support/capture.hpp"

using namespace tunica;
using namespace tunica::test;

namespace {

struct AngioplastyResult {
  double lumen = 0, force = 0, smoothed_peak = 0, zone_centre = 0;
  int cutbacks = 0, zone_nodes = 0;
  bool contiguous = false, complete = false;
};

AngioplastyResult run(const std::string& name) {
  const std::string path = std::string(TUNICA_SOURCE_DIR) + "/examples/" + name;
  const Model m = read_deck_text(read_text(path), path);
  Analysis a(m);
  Capture c;
  a.run(c);
  AngioplastyResult r;
  r.complete = c.rows.back().info.step == 3 && c.rows.back().info.fraction == 1.0;
  r.cutbacks = c.cutbacks;
  r.lumen = c.rows.back().values[Capture::column(m, "lumen_min_mm")];
  r.force = c.rows.back().values[Capture::column(m, "force_balloon_plaque_N")];
  const auto states = a.system().contact_states(a.displacement(), 1, a.loads().step);
  std::vector<int> active;
  for (std::size_t k = 0; k < states.size(); ++k)
    if (states[k].pressure > 0) active.push_back(static_cast<int>(k));
  r.zone_nodes = static_cast<int>(active.size());
  r.contiguous = !active.empty() && active.back() - active.front() + 1 == r.zone_nodes;
  for (std::size_t k = 1; k + 1 < states.size(); ++k)
    r.smoothed_peak =
        std::max(r.smoothed_peak, (states[k - 1].pressure + states[k].pressure + states[k + 1].pressure) / 3.0);
  if (!active.empty()) {
    const int mid = active[active.size() / 2];
    const int node = states[static_cast<std::size_t>(mid)].node;
    r.zone_centre = m.X[node](1) + a.displacement()(2 * node + 1);
  }
  return r;
}

}  // namespace

TEST(AngioplastyShell, ShellsGiveNearlyTheMembraneResult) {
  const AngioplastyResult mem = run("balloon-angioplasty.yaml"), shell = run("balloon-angioplasty-shell.yaml");
  ASSERT_TRUE(mem.complete);
  ASSERT_TRUE(shell.complete);
  EXPECT_LE(shell.cutbacks, 12);
  EXPECT_NEAR(shell.lumen, mem.lumen, 1e-3);
  EXPECT_NEAR(shell.force / mem.force, 1.0, 0.05);
  EXPECT_TRUE(shell.contiguous);
  EXPECT_GE(shell.zone_nodes, 5);
  EXPECT_NEAR(shell.zone_centre, 2.0, 0.05);
  EXPECT_NEAR(shell.smoothed_peak / mem.smoothed_peak, 1.0, 0.1);
  std::printf("membrane vs shell: lumen %.4f / %.4f mm, contact force %.4f / %.4f N, 3-node peak %.4f / %.4f N/mm², "
              "zone %d / %d nodes, cut-backs %d / %d\n",
              mem.lumen, shell.lumen, mem.force, shell.force, mem.smoothed_peak, shell.smoothed_peak, mem.zone_nodes,
              shell.zone_nodes, mem.cutbacks, shell.cutbacks);
}
