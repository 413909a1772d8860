// Axisymmetric membranes in contact with deformable masters (deck key `master`,
// penalty Π = ½ ε ⟨−g_N⟩² A_s per slave node, node to segment; theory manual §9.1, §9.2):
// (b) cylinder–cylinder closed form: a neo-Hookean tube (slave, R_i = 1 mm) inflated
//     inside a Fung tube (master, R_o = 1.2 mm), both at λ_z = 1 (ends held axially),
//     offset c = half thicknesses: first free inflation, then both deform together.
//     Per unit length (q: contact pressure on the inner tube's current surface):
//       inner: T_θ,i = (p − q) r_i,  S_θ,i = μ(1 − λ_i⁻⁴) = (p − q) R_i/H_i,
//       outer: T_θ,o = q r_i (the force 2π r_i q per length), S_θ,o(λ_o) λ_o = q r_i/H_o,
//       penalty: c − (r_o − r_i) = ⟨−g_N⟩ = q r_i/(ε R_i)  (q is per current area),
//     solved here by nested bisections, independently of the code;
// (c) Newton converges quadratically once the active set settles (soft penalty);
// (d) patch test: an annulus pressed by p onto a deformable flat master (stretched
//     radially under it) carries p_c = p at its interior nodes.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <map>
#include <numbers>

#include "../support/capture.hpp"
#include "../support/contact_tubes.hpp"
#include "../support/system_fd.hpp"

using namespace tunica;
using namespace tunica::test;

namespace {


// The closed form (see the header comment).
constexpr double kMu = 0.1, kHi = 0.1, kRi = 1.0, kC = 0.2, kA1 = 1.0, kHo = 0.1, kRo = 1.2, kOffset = 0.1;

double bisect(const std::function<double(double)>& f, double lo, double hi) {
  const bool up = f(hi) > 0;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    ((f(mid) > 0) == up ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}
/// Inner tube: λ with μ(1 − λ⁻⁴) = p_net R_i/H_i.
double inner_radius(double p_net) { return kRi * std::pow(1.0 - p_net * kRi / (kMu * kHi), -0.25); }
/// Outer tube, Fung at E_z = 0: S_θ = 2c a1 E e^{a1 E²}; λ_o with S_θ λ_o = q r_i/H_o.
double outer_radius(double q, double ri) {
  const auto f = [&](double l) {
    const double E = 0.5 * (l * l - 1);
    return 2 * kC * kA1 * E * std::exp(kA1 * E * E) * l - q * ri / kHo;
  };
  return kRo * bisect(f, 1.0, 3.0);
}
struct TubesState {
  double ri, ro, q;
};
/// The closed form at pressure p and penalty ε (ε = ∞: the exact constraint).
TubesState tubes(double p, double eps) {
  const double free = inner_radius(p);
  if (free <= kRo - kOffset) return {free, kRo, 0};
  const auto gap = [&](double q) {
    const double ri = inner_radius(p - q), ro = outer_radius(q, ri);
    return kOffset - (ro - ri) - (std::isinf(eps) ? 0.0 : q * ri / (eps * kRi));
  };
  const double q = bisect(gap, 0, p);
  const double ri = inner_radius(p - q);
  return {ri, outer_radius(q, ri), q};
}

const std::string kPatch = R"(title: annulus pressed onto a deformable flat master
units: {length: mm, force: N}
materials:
  soft: {type: neo_hookean, mu: 0.1}
  stiff: {type: neo_hookean, mu: 1}
parts:
  sheet:
    element: axisymmetric_membrane
    material: soft
    thickness: 0.1
    mesh: {type: line, from: [1, 0], to: [2, 0], elements: 10}
  base:
    element: axisymmetric_membrane
    material: stiff
    thickness: 0.1
    mesh: {type: line, from: [3, -0.1], to: [0.5, -0.1], elements: 7}
boundary:
  flat: {node_set: base.all, dofs: [z]}
  pull: {node_set: base.start, dofs: [r]}
loads:
  push: {type: pressure, part: sheet}
contact:
  floor: {slave: sheet, master: base, penalty: 1e4 N/mm^3, offset: 0.10000001}
solver: {residual_tolerance: 1e-10}
steps:
  - {name: press, increments: 2, set: {push: 0.01 MPa}}
  - {name: stretch, increments: 2, set: {pull: 0.3}}
output:
  vtk: false
  history:
    - {quantity: contact_pressure, contact: floor, name: p_max}
    - {quantity: contact_force, contact: floor}
    - {quantity: reaction_z, node_set: base.all, name: base_z}
)";

}  // namespace

TEST(DeformableContactDeck, ConcentricTubesMatchTheClosedForm) {
  const double eps = 1e3;  // N/mm³: penetration q r/(ε R) ≈ 4e-6 mm
  const Model m = read_deck_text(contact_tubes_deck("1e3"), "tubes.yaml");
  ASSERT_EQ(m.contacts.size(), 1u);
  ASSERT_TRUE(m.contacts[0].deformable());
  Capture cap;
  Analysis a(m);
  a.run(cap);
  EXPECT_EQ(cap.cutbacks, 0);
  const int cp = Capture::column(m, "pressure_N_per_mm2"), cri = Capture::column(m, "ri_mm"),
            cro = Capture::column(m, "ro_mm"), cmax = Capture::column(m, "pc_max_N_per_mm2"),
            cmin = Capture::column(m, "pc_min_N_per_mm2"), cf = Capture::column(m, "contact_force_N"),
            cpen = Capture::column(m, "contact_penetration_mm");
  int before = 0, after = 0;
  double worst_r = 0, worst_q = 0, worst_uniform = 0, worst_limit = 0, worst_pen = 0;
  for (const auto& row : cap.rows) {
    if (row.info.step == 0) continue;
    const double p = row.values[cp];
    const TubesState s = tubes(p, eps);
    if (s.q == 0) {  // the gap is still open: free inflation, the outer tube untouched
      ++before;
      EXPECT_NEAR(row.values[cri], s.ri, 1e-9 * s.ri) << "p = " << p;
      EXPECT_NEAR(row.values[cro], kRo, 1e-12);
      EXPECT_EQ(row.values[cmax], 0.0);
      worst_r = std::max(worst_r, std::abs(row.values[cri] / s.ri - 1));
      continue;
    }
    ++after;
    const double ri = row.values[cri], ro = row.values[cro], qmax = row.values[cmax], qmin = row.values[cmin];
    EXPECT_NEAR(ri, s.ri, 1e-8 * s.ri) << "p = " << p;
    EXPECT_NEAR(ro, s.ro, 1e-8 * s.ro) << "p = " << p;
    EXPECT_NEAR(qmax, s.q, 1e-6 * s.q) << "p = " << p;
    // Uniform along the tube (end nodes included: half area, half force).
    EXPECT_NEAR(qmin, qmax, 1e-8 * qmax) << "p = " << p;
    // The total normal force is q × the inner tube's current lateral area 2π r_i L.
    EXPECT_NEAR(row.values[cf], qmax * 2 * std::numbers::pi * ri * 1.0, 1e-8 * row.values[cf]);
    // The penetration is the penalty's: c − (r_o − r_i) = q r_i/(ε R_i).
    EXPECT_NEAR(row.values[cpen], s.q * s.ri / (eps * kRi), 1e-6 * s.q / eps);
    worst_r = std::max({worst_r, std::abs(ri / s.ri - 1), std::abs(ro / s.ro - 1)});
    worst_q = std::max(worst_q, std::abs(qmax / s.q - 1));
    worst_uniform = std::max(worst_uniform, (qmax - qmin) / qmax);
    worst_pen = std::max(worst_pen, std::abs(row.values[cpen] / (s.q * s.ri / (eps * kRi)) - 1));
    // The ε → ∞ limit differs by O(1/ε): here q r/ε ≈ 4e-6 mm of radius, ~1e-5 of q.
    const TubesState hard = tubes(p, std::numeric_limits<double>::infinity());
    worst_limit = std::max(worst_limit, std::abs(qmax / hard.q - 1));
  }
  EXPECT_GE(before, 3);
  EXPECT_GE(after, 10);
  EXPECT_LT(worst_limit, 1e-3);
  std::printf("tubes: |r/r_closed − 1| ≤ %.2e, |q/q_closed − 1| ≤ %.2e, (q_max − q_min)/q ≤ %.2e, "
              "|penetration/closed − 1| ≤ %.2e (%d free, %d contact rows); vs the ε → ∞ limit |q/q∞ − 1| ≤ %.2e\n",
              worst_r, worst_q, worst_uniform, worst_pen, before, after, worst_limit);
}

TEST(DeformableContactDeck, NewtonConvergesQuadraticallyOnceTheActiveSetSettles) {
  // A soft penalty (contact stiffness comparable to the membranes'), so that the contact
  // increments need several iterations and the order can be measured.
  const double eps = 0.05;
  // Every iteration factorizes (reuse_factorization: never): the rate measured is Newton's, (7.1).
  std::string deck = contact_tubes_deck("0.05");
  const std::string plain = "solver: {residual_tolerance: 1e-11}";
  ASSERT_NE(deck.find(plain), std::string::npos);
  deck.replace(deck.find(plain), plain.size(), "solver: {residual_tolerance: 1e-11, reuse_factorization: never}");
  const Model m = read_deck_text(deck, "tubes-soft.yaml");
  Capture cap;
  Analysis a(m);
  a.run(cap);
  EXPECT_EQ(cap.cutbacks, 0);
  std::map<std::pair<int, int>, std::vector<IterationRecord>> inc;
  for (const auto& it : cap.iterations) inc[{it.info.step, it.info.increment}].push_back(it.rec);
  int measured = 0, settled = 0;
  double qmin = 10, qmax = 0, cmax = 0;
  for (const auto& [key, recs] : inc) {
    if (key.first != 2) continue;
    bool same = true;
    for (const auto& r : recs) same = same && r.active_contacts == recs.front().active_contacts;
    // newton.csv's active_changes: at least the change of the count, 0 at an increment's first residual.
    EXPECT_EQ(recs.front().active_changes, 0);
    for (std::size_t j = 1; j < recs.size(); ++j)
      EXPECT_GE(recs[j].active_changes, std::abs(recs[j].active_contacts - recs[j - 1].active_contacts));
    if (!same || recs.front().active_contacts == 0) continue;
    ++settled;
    EXPECT_EQ(recs.front().active_contacts, 9);
    for (const auto& r : recs) EXPECT_EQ(r.active_changes, 0) << "a settled increment keeps the same active nodes";
    double floor = recs.front().residual, last_q = 0;
    for (const auto& r : recs) floor = std::min(floor, r.residual);
    for (std::size_t j = 1; j + 1 < recs.size(); ++j) {
      const double r0 = recs[j - 1].relative_residual, r1 = recs[j].relative_residual, r2 = recs[j + 1].relative_residual;
      if (recs[j + 1].residual < 1e3 * floor || r2 < 1e-12 || r1 >= 1.0) continue;
      last_q = std::log(r2 / r1) / std::log(r1 / r0);
    }
    // The quadratic constant r_{k+1}/r_k² (relative residuals) stays bounded while the residual
    // falls by 10 orders (linear convergence would make it grow like 1/r_k).
    for (std::size_t j = 0; j + 1 < recs.size(); ++j)
      if (recs[j + 1].residual >= 1e3 * floor)
        cmax = std::max(cmax, recs[j + 1].relative_residual / std::pow(recs[j].relative_residual, 2));
    if (last_q == 0) continue;
    ++measured;
    qmin = std::min(qmin, last_q);
    qmax = std::max(qmax, last_q);
    // Three residuals per increment only (1 → ~1e-2 → ~1e-7 → round-off): the estimate from the
    // first three carries the spread of the constant, hence ±0.5 (the rigid sleeve's, ±0.3).
    EXPECT_NEAR(last_q, 2.0, 0.5) << "increment " << key.second;
  }
  EXPECT_LT(cmax, 1.0);
  // The soft-penalty state is still the closed form (with its large penetration).
  const auto& last = cap.rows.back().values;
  const TubesState s = tubes(last[Capture::column(m, "pressure_N_per_mm2")], eps);
  EXPECT_NEAR(last[Capture::column(m, "pc_max_N_per_mm2")], s.q, 1e-6 * s.q);
  EXPECT_NEAR(last[Capture::column(m, "ri_mm")], s.ri, 1e-8);
  std::printf("soft-penalty tubes: %d settled contact increments, order estimate in [%.2f, %.2f] over %d, "
              "r_{k+1}/r_k² ≤ %.2e; penetration %.3e mm\n",
              settled, qmin, qmax, measured, cmax, last[Capture::column(m, "contact_penetration_mm")]);
  EXPECT_GE(measured, 4);
}

TEST(DeformableContactDeck, PatchTestAnnulusOnADeformableFlatMaster) {
  const Model m = read_deck_text(kPatch, "patch.yaml");
  Capture cap;
  Analysis a(m);
  a.run(cap);
  ASSERT_EQ(cap.rows.size(), 5u);
  const double p = 0.01, eps = 1e4;
  const double area = std::numbers::pi * (2.0 * 2.0 - 1.0 * 1.0);
  double worst = 0, worst_force = 0, worst_reaction = 0;
  // The master was stretched radially under the sheet (r of its outer edge 3 → 3.3 mm):
  // frictionless, the sheet slides over it and still carries p.
  EXPECT_NEAR(a.displacement()(2 * m.parts[1].nodes.front()), 0.3, 1e-12);
  const auto states = a.system().contact_states(a.displacement(), 0, a.loads().step);
  ASSERT_EQ(states.size(), 11u);
  for (std::size_t k = 1; k + 1 < states.size(); ++k) {  // interior nodes
    EXPECT_TRUE(states[k].point.active);
    EXPECT_NEAR(states[k].pressure, p, 1e-5 * p) << "node " << k;
    EXPECT_NEAR(states[k].point.normal(1), 1.0, 1e-12);
    worst = std::max(worst, std::abs(states[k].pressure / p - 1));
  }
  for (const auto& s : states) EXPECT_NEAR(s.point.gap, -p / eps, 0.1 * p / eps);
  for (const auto& row : cap.rows) {
    if (row.info.step == 0 || row.info.time < 1) continue;  // full pressure
    const double force = row.values[Capture::column(m, "contact_force_N")];
    const double reaction = row.values[Capture::column(m, "base_z_N")];
    EXPECT_NEAR(force / (p * area), 1.0, 1e-6);
    // The master passes the whole force to its supports.
    EXPECT_NEAR(std::abs(reaction), force, 1e-9 * force);
    worst_force = std::max(worst_force, std::abs(force / (p * area) - 1));
    worst_reaction = std::max(worst_reaction, std::abs(std::abs(reaction) / force - 1));
  }
  std::printf("deformable patch test: interior |p_c/p − 1| ≤ %.2e, |force/(p A) − 1| ≤ %.2e, "
              "|reaction/force − 1| ≤ %.2e, p/ε = %.1e\n",
              worst, worst_force, worst_reaction, p / eps);
}

// The smooth master on non-matching tubes (8 slave against 11 master elements): the assembled
// tangent at the final state, every slave node active, matches central differences of the
// residual (the contact elements' windows straddle master nodes and the chain's ends).
TEST(DeformableContactDeck, SmoothMasterTangentOnNonMatchingTubes) {
  std::string deck = contact_tubes_deck("1e3", 11);
  const Model m = read_deck_text(deck, "tubes-8-11.yaml");
  ASSERT_EQ(m.contacts[0].master_surface, ContactPair::MasterSurface::smooth);
  Capture cap;
  Analysis a(m);
  a.run(cap);
  const System& sys = a.system();
  const LoadState loads = a.loads();
  Eigen::VectorXd R;
  SparseMatrix K;
  int active = 0;
  sys.assemble_full(a.displacement(), loads, R, K, nullptr, &active);
  EXPECT_EQ(active, 9);
  const Eigen::MatrixXd Kd(K);
  const double err = fd_tangent_error(sys, loads, a.displacement(), Kd, 1e-7);
  std::printf("smooth master, tubes 8 vs 11: FD of the assembled residual vs K: %.2e (max |K| %.2e), %d active\n", err,
              Kd.cwiseAbs().maxCoeff(), active);
  EXPECT_LT(err, 1e-6 * Kd.cwiseAbs().maxCoeff());
}
