// Parts that enter in a later step (`enter_step`, theory manual §10.1: the plaque is placed stress free in
// the prestretched artery). The deck: an artery prestretched and pressurized in step 1, a solid
// plaque entering in step 2, where its top is pushed down by 0.05 mm.
// (1) During step 1 every plaque node stays exactly at its reference position while the
//     artery moves; the plaque's history stresses are 0.
// (2) At the end of step 1, with the plaque active (the state the first iteration of step 2
//     starts from before the boundary increment), its energy, Gauss-point stresses and its
//     share of the residual vanish to round-off.
// (3) In step 2 it takes load: compressed axially (σ_zz < 0, reaction on its top).
// (4) Restart: a run stopped at the end of step 1 and resumed from the restart file (written
//     and read back) ends bit for bit where the uninterrupted run ends.
#include <gtest/gtest.h>

#include <cmath>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "../support/capture.hpp"
#include "../support/solid_decks.hpp"
#include "output/restart_file.hpp"

using namespace tunica;
using namespace tunica::test;

namespace {

constexpr double kMu = 0.05;  // the plaque's shear modulus in the deck, N/mm²

/// Keeps the state at the end of step 1 and can ask the run to stop there.
class StepOneObserver final : public AnalysisObserver {
public:
  bool stop_after_step_one = false;
  bool stop = false;
  Eigen::VectorXd u1;
  LoadState loads1;
  Checkpoint checkpoint;
  double max_plaque_u_in_step_one = 0;
  std::vector<int> plaque_nodes;
  void on_increment(const Analysis& a, const IncrementInfo& info) override {
    if (info.step == 1) {
      for (int n : plaque_nodes)
        max_plaque_u_in_step_one = std::max(max_plaque_u_in_step_one, a.displacement().segment<2>(2 * n).cwiseAbs().maxCoeff());
      if (info.fraction == 1.0) {
        u1 = a.displacement();
        loads1 = a.loads();
        checkpoint = a.checkpoint();
        stop = stop_after_step_one;
      }
    }
  }
  bool stop_requested() override { return stop; }
};

}  // namespace

TEST(EnterStep, ThePlaqueEntersStressFreeAndTakesLoadAfterwards) {
  const Model m = read_deck_text(kArteryWithPlaque, "artery-plaque.yaml");
  const int plaque = m.find_part("plaque"), artery = m.find_part("artery");
  ASSERT_EQ(m.parts[plaque].enter_step, 1);
  EXPECT_FALSE(m.part_active(plaque, 0));
  EXPECT_TRUE(m.part_active(plaque, 1));
  EXPECT_TRUE(m.part_active(artery, 0));

  Capture cap;
  StepOneObserver obs;
  obs.plaque_nodes = m.parts[plaque].nodes;
  Analysis a(m);
  struct Both final : AnalysisObserver {
    AnalysisObserver *x, *y;
    void on_iteration(const IncrementInfo& i, const IterationRecord& r) override { x->on_iteration(i, r); }
    void on_increment(const Analysis& an, const IncrementInfo& i) override {
      x->on_increment(an, i);
      y->on_increment(an, i);
    }
  } both;
  both.x = &cap;
  both.y = &obs;
  a.run(both);
  EXPECT_EQ(cap.cutbacks, 0);

  // (1) the plaque did not move in step 1; the artery did.
  EXPECT_EQ(obs.max_plaque_u_in_step_one, 0.0);
  double artery_u = 0;
  for (int n : m.parts[artery].nodes) artery_u = std::max(artery_u, std::abs(obs.u1(2 * n)));
  EXPECT_GT(artery_u, 1e-3);
  const int szz_min = Capture::column(m, "szz_min_N_per_mm2"), szz_max = Capture::column(m, "szz_max_N_per_mm2");
  for (const auto& row : cap.rows)
    if (row.info.step <= 1) {
      EXPECT_LT(std::abs(row.values[szz_min]), 1e-12 * kMu);  // round-off of σ at F = I
      EXPECT_LT(std::abs(row.values[szz_max]), 1e-12 * kMu);
    }

  // (2) stress free when it enters: energy, stresses and residual share at round-off.
  const System& sys = a.system();
  LoadState entering = obs.loads1;
  entering.step = 1;
  const double entry_energy = sys.part_energy(obs.u1, plaque), final_energy = sys.part_energy(a.displacement(), plaque);
  EXPECT_LT(std::abs(entry_energy), 1e-12 * final_energy);
  double max_sigma = 0;
  for (const auto& p : sys.solid_points(obs.u1, plaque)) max_sigma = std::max(max_sigma, p.sigma.cwiseAbs().maxCoeff());
  EXPECT_LT(max_sigma, 1e-12 * kMu);
  Eigen::VectorXd R;
  double scale = 0;
  SparseMatrix K;
  sys.assemble_full(obs.u1, entering, R, K, &scale);
  double plaque_R = 0;
  for (int n : m.parts[plaque].nodes) plaque_R = std::max(plaque_R, R.segment<2>(2 * n).cwiseAbs().maxCoeff());
  EXPECT_LT(plaque_R, 1e-14 * scale);
  // The first iteration of step 2 (its residual includes the boundary increment on the plaque top).
  const auto first = std::find_if(cap.iterations.begin(), cap.iterations.end(), [](const Iteration& it) { return it.info.step == 2; });
  ASSERT_NE(first, cap.iterations.end());

  // (3) it takes load in step 2.
  const auto& last = cap.rows.back().values;
  const double F = last[Capture::column(m, "reaction_z_N")];
  EXPECT_LT(last[szz_min], -1e-3);
  EXPECT_LT(F, 0.0);  // the support pushes the top down
  EXPECT_GT(last[Capture::column(m, "p_max_N_per_mm2")], 0.0);
  std::printf("plaque: max |u| in step 1 = %g; at entry: energy %.1e (end of step 2: %.3e), max |σ| %.1e, max |R| %.1e (force scale %.1e); "
              "end of step 2: σ_zz ∈ [%.4f, %.4f] N/mm², σ_rr ≤ %.4f, J ≥ %.5f, top reaction %.5f N; first residual of "
              "step 2 %.3e\n",
              obs.max_plaque_u_in_step_one, entry_energy, final_energy, max_sigma, plaque_R, scale, last[szz_min],
              last[szz_max], last[Capture::column(m, "srr_max_N_per_mm2")], last[Capture::column(m, "J_min")], F,
              first->rec.residual);
}

TEST(EnterStep, ARunStoppedBeforeThePartEntersResumesBitForBit) {
  const Model m = read_deck_text(kArteryWithPlaque, "artery-plaque.yaml");
  Capture full;
  Analysis whole(m);
  whole.run(full);

  // Stopped at the end of step 1; through the restart file: written and read back.
  const auto path = std::filesystem::temp_directory_path() / "tunica-enter-step-restart.txt";
  {
    Analysis again(m);
    StepOneObserver s;
    s.stop_after_step_one = true;
    EXPECT_THROW(again.run(s), Interrupted);
    std::ofstream(path) << restart_text(RestartRecord{again.checkpoint(), 0, 0, 0, "artery-plaque.yaml", {}, {}});
  }
  const RestartRecord r = read_restart(path.string());
  EXPECT_EQ(r.checkpoint.step, 0);
  EXPECT_EQ(r.checkpoint.fraction, 1.0);
  Analysis resumed(m);
  Capture rest;
  resumed.run(rest, &r.checkpoint);
  EXPECT_EQ((resumed.displacement() - whole.displacement()).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(rest.rows.back().values, full.rows.back().values);
  std::filesystem::remove(path);
}
