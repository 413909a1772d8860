// Two-pass contact of a deformable pair (`passes: 2`, theory manual §9.1, (9.9)): a neo-Hookean
// tube (slave) inflated inside a Fung tube (master), both at λ_z = 1, as in
// test_deformable_contact.cpp (the closed form there):
// - the deck reader forms the reverse pass (slave and master exchanged, the balloon's chain
//   oriented to face the artery, half the penalty on each pass);
// - the assembled tangent matches central differences of the residual with both passes active,
//   on non-matching meshes, for the smooth and the faceted master;
// - the pair's outputs: per slave node its own pass's normal force plus the reverse pass's force on
//   it, their sum the total of both passes; on matching meshes the same total force and contact
//   pressure as one pass with the full penalty.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "../support/capture.hpp"
#include "../support/contact_tubes.hpp"
#include "../support/system_fd.hpp"
#include "../support/vtu.hpp"
#include "output/vtk_writer.hpp"

using namespace tunica;
using namespace tunica::test;

namespace {


std::string tubes(int artery, const std::string& more) {
  return contact_tubes_deck("1e3", artery, 6, more);
}

}  // namespace

TEST(TwoPassContact, TheReversePassIsFormedWithHalfThePenalty) {
  const Model m = read_deck_text(tubes(11, ", passes: 2"), "two-pass.yaml");
  ASSERT_EQ(m.contacts.size(), 2u);
  const ContactPair& first = m.contacts[0];
  const ContactPair& rev = m.contacts[1];
  EXPECT_EQ(first.reverse, 1);
  EXPECT_EQ(first.reverse_of, -1);
  EXPECT_EQ(rev.reverse_of, 0);
  EXPECT_EQ(rev.name, "press");
  EXPECT_DOUBLE_EQ(first.law.penalty, 500.0);
  EXPECT_DOUBLE_EQ(rev.law.penalty, 500.0);
  EXPECT_DOUBLE_EQ(rev.law.offset, first.law.offset);
  EXPECT_EQ(rev.master_surface, first.master_surface);
  // The artery's chain (reversed, as the pair's master) is the slave; the balloon's the master,
  // running in +z so that its normal (t_z, −t_r) = +e_r faces the artery.
  EXPECT_EQ(rev.nodes, first.master);
  EXPECT_EQ(rev.master, m.parts[static_cast<std::size_t>(m.find_part("balloon"))].nodes);
  ASSERT_EQ(rev.areas.size(), 12u);
  // The artery's own tributary areas: 2π R L, R = 1.2 mm, L = 1/11 mm (half at the ends).
  EXPECT_NEAR(rev.areas[1], 2 * std::numbers::pi * 1.2 / 11, 1e-12);
  EXPECT_NEAR(rev.areas[0], std::numbers::pi * 1.2 / 11, 1e-12);
  // One pass (the default): a single pair with the full penalty.
  const Model one = read_deck_text(tubes(11, ""), "one-pass.yaml");
  ASSERT_EQ(one.contacts.size(), 1u);
  EXPECT_EQ(one.contacts[0].reverse, -1);
  EXPECT_DOUBLE_EQ(one.contacts[0].law.penalty, 1e3);
}

TEST(TwoPassContact, TangentMatchesFiniteDifferencesWithBothPassesActive) {
  for (const std::string surface : {"smooth", "faceted"}) {
    SCOPED_TRACE("master_surface: " + surface);
    const Model m = read_deck_text(tubes(11, ", passes: 2, master_surface: " + surface), "two-pass-fd.yaml");
    Capture cap;
    Analysis a(m);
    a.run(cap);
    ASSERT_EQ(cap.cutbacks, 0);
    const System& sys = a.system();
    const LoadState loads = a.loads();
    Eigen::VectorXd R;
    SparseMatrix K;
    int active = 0;
    sys.assemble_full(a.displacement(), loads, R, K, nullptr, &active);
    // Both passes active: every artery node on the balloon (12), and most balloon nodes on the artery
    // (the balloon's surface between the artery's nodes may lift off by a fraction of a micrometre).
    EXPECT_GE(active, 12 + 7);
    const Eigen::MatrixXd Kd(K);
    ActiveRange perturbed;
    const double err = fd_tangent_error(sys, loads, a.displacement(), Kd, 1e-7, &perturbed);
    EXPECT_EQ(perturbed.fewest, active);
    EXPECT_EQ(perturbed.most, active);
    std::printf("two-pass (%s), tubes 8 vs 11: FD of the assembled residual vs K: %.2e (max |K| %.2e), %d active\n",
                surface.c_str(), err, Kd.cwiseAbs().maxCoeff(), active);
    EXPECT_LT(err, 1e-6 * Kd.cwiseAbs().maxCoeff());

    // The pair's nodal forces hold both passes: Σ_s F_s = Σ_s ε/2 ⟨−g_N⟩ A_s + Σ_m ε/2 ⟨−g_N⟩ A_m.
    const auto states = sys.contact_states(a.displacement(), 0, loads.step);
    const auto reverse = sys.contact_states(a.displacement(), 1, loads.step);
    double total = 0, own = 0, back = 0;
    for (std::size_t k = 0; k < states.size(); ++k) {
      total += states[k].force;
      own += states[k].point.pressure * m.contacts[0].areas[k];
    }
    for (const auto& s : reverse) back += s.force;
    EXPECT_GT(own, 0.1 * total);
    EXPECT_GT(back, 0.1 * total);
    EXPECT_NEAR(total, own + back, 1e-12 * total);
    // The pair's contact pressure on the non-matching meshes: the interior nodes' (a lifted-off
    // node carries the reverse pass's force) lie within a few per cent of each other.
    double lo = states[1].pressure, hi = lo;
    for (std::size_t k = 1; k + 1 < states.size(); ++k) {
      lo = std::min(lo, states[k].pressure);
      hi = std::max(hi, states[k].pressure);
    }
    std::printf("two-pass (%s), tubes 8 vs 11: interior nodal contact pressure %.6g … %.6g (spread %.2f %%)\n",
                surface.c_str(), lo, hi, 100 * (hi - lo) / hi);
    EXPECT_LT(hi - lo, 0.05 * hi);
    const double force = cap.rows.back().values[Capture::column(m, "contact_force_N")];
    EXPECT_NEAR(force, total, 1e-12 * total);
  }
}

TEST(TwoPassContact, MatchingMeshesGiveTheOnePassForceAndPressure) {
  for (const std::string surface : {"smooth", "faceted"}) {
    SCOPED_TRACE("master_surface: " + surface);
    const std::string more = ", master_surface: " + surface;
    const Model one = read_deck_text(tubes(8, more), "one-pass.yaml");
    const Model two = read_deck_text(tubes(8, more + ", passes: 2"), "two-pass.yaml");
    Capture c1, c2;
    Analysis a1(one), a2(two);
    a1.run(c1);
    a2.run(c2);
    ASSERT_EQ(c1.rows.size(), c2.rows.size());
    const auto& r1 = c1.rows.back().values;
    const auto& r2 = c2.rows.back().values;
    const auto col = [&](const std::string& name) { return Capture::column(one, name); };
    const double f1 = r1[col("contact_force_N")], f2 = r2[col("contact_force_N")];
    const double max1 = r1[col("pc_max_N_per_mm2")], max2 = r2[col("pc_max_N_per_mm2")];
    const double min1 = r1[col("pc_min_N_per_mm2")], min2 = r2[col("pc_min_N_per_mm2")];
    std::printf("matching tubes (%s): force %.8g (one pass) %.8g (two); p_c max %.8g / %.8g, min %.8g / %.8g; "
                "penetration %.3g / %.3g mm\n",
                surface.c_str(), f1, f2, max1, max2, min1, min2, r1[col("contact_penetration_mm")],
                r2[col("contact_penetration_mm")]);
    EXPECT_GT(f1, 0);
    EXPECT_NEAR(f2, f1, 1e-4 * f1);
    EXPECT_NEAR(max2, max1, 0.02 * max1);
    EXPECT_NEAR(min2, min1, 0.02 * min1);
    // The VTU point field is the pair's nodal pressure on the slave's nodes, 0 on the master's.
    const auto states = a2.system().contact_states(a2.displacement(), 0, a2.loads().step);
    const auto field = decode_float64(meridian_vtu(a2), "contact_pressure_N_per_mm2");
    ASSERT_EQ(field.size(), static_cast<std::size_t>(two.num_nodes()));
    for (const auto& s : states) EXPECT_DOUBLE_EQ(field[static_cast<std::size_t>(s.node)], s.pressure);
    for (int n : two.contacts[0].master) EXPECT_EQ(field[static_cast<std::size_t>(n)], 0.0);
  }
}
