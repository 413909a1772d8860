// A thick-walled tube of nearly incompressible neo-Hookean material (κ/μ = 10⁴) as an
// `axisymmetric_solid` deck part, in plane strain (both z faces held in z), its inner
// radius prescribed from R_i = 1 to r_i = 1.5 mm: the inner pressure read from the radial
// reaction, p = F_r/(2π r_i h) (F_r on the whole circumference), against the incompressible
// closed form (theory manual §10.2, (10.9))
//   p = μ [ln(λ_i/λ_o) + ½(λ_o⁻² − λ_i⁻²)],   λ = r/R,   r_o² = R_o² + r_i² − R_i²,
// which is first checked against an independent numerical integral of the equilibrium
// equation, p = μ ∫_{r_i}^{r_o} (λ² − λ⁻²) dr/r. Under refinement through the wall the
// mean-dilatation element converges to it (the compressibility leaves O(μ/κ)); the plain
// displacement element locks.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "../support/capture.hpp"

using namespace tunica;
using namespace tunica::test;

namespace {

constexpr double kRi = 1.0, kRo = 2.0, kH = 0.25, kMu = 1.0, kUi = 0.5;

const std::string kTube = R"(title: thick tube in plane strain, inner radius prescribed
units: {length: mm, force: N}
materials:
  rubber: {type: neo_hookean_solid, mu: 1 MPa, kappa: 1e4 MPa}
parts:
  tube:
    element: axisymmetric_solid
    formulation: FORMULATION
    material: rubber
    mesh: {type: grid, z0: 0, z1: 0.25 mm, inner: 1 mm, outer: 2 mm, elements_r: NR, elements_z: 2}
boundary:
  bottom: {node_set: tube.bottom, dofs: [z]}
  top: {node_set: tube.top, dofs: [z]}
  bore: {node_set: tube.inner, dofs: [r]}
solver: {residual_tolerance: 1e-11}
steps:
  - {name: expand, increments: 5, set: {bore: 0.5 mm}}
output:
  vtk: false
  history:
    - {quantity: reaction_r, node_set: tube.inner, name: F}
    - {quantity: position_r, node_set: tube.outer, name: r_o}
    - {quantity: displacement_z, node_set: tube.all, reduce: max, name: uz_max}
    - {quantity: sigma_rr, part: tube, reduce: min, name: srr_min}
)";

/// Closed form p(r_i) of the incompressible plane-strain tube.
double closed_form(double ri) {
  const double c = ri * ri - kRi * kRi, ro = std::sqrt(kRo * kRo + c);
  const double li = ri / kRi, lo = ro / kRo;
  return kMu * (std::log(li / lo) + 0.5 * (1 / (lo * lo) - 1 / (li * li)));
}

/// The same by composite Simpson quadrature of μ ∫ (λ² − λ⁻²) dr/r, λ² = r²/(r² − c).
double integral(double ri, int n) {
  const double c = ri * ri - kRi * kRi, ro = std::sqrt(kRo * kRo + c), h = (ro - ri) / n;
  const auto g = [&](double r) {
    const double l2 = r * r / (r * r - c);
    return kMu * (l2 - 1 / l2) / r;
  };
  double s = g(ri) + g(ro);
  for (int k = 1; k < n; ++k) s += (k % 2 ? 4 : 2) * g(ri + k * h);
  return s * h / 3;
}

struct TubeResult {
  double p = 0, ro = 0, uz = 0, srr_min = 0;
};

TubeResult run_tube(int nr, const std::string& formulation) {
  const Model m = read_deck_text(replace(replace(kTube, "NR", std::to_string(nr)), "FORMULATION", formulation), "tube.yaml");
  Capture cap;
  Analysis a(m);
  a.run(cap);
  const auto& last = cap.rows.back().values;
  TubeResult r;
  const double ri = kRi + kUi;
  r.p = last[Capture::column(m, "F_N")] / (2 * std::numbers::pi * ri * kH);
  r.ro = last[Capture::column(m, "r_o_mm")];
  r.uz = last[Capture::column(m, "uz_max_mm")];
  r.srr_min = last[Capture::column(m, "srr_min_N_per_mm2")];
  return r;
}

}  // namespace

TEST(SolidTubeDeck, ClosedFormAgreesWithTheEquilibriumIntegral) {
  for (double ri : {1.01, 1.2, 1.5, 2.5}) {
    const double p = closed_form(ri), q = integral(ri, 2000);
    EXPECT_NEAR(q, p, 1e-10 * p) << "r_i = " << ri;
  }
  std::printf("closed form p(1.5) = %.12f, Simpson (2000) = %.12f\n", closed_form(1.5), integral(1.5, 2000));
}

TEST(SolidTubeDeck, MeanDilatationConvergesToTheIncompressibleClosedForm) {
  const double exact = closed_form(kRi + kUi);
  const double ro_exact = std::sqrt(kRo * kRo + (kRi + kUi) * (kRi + kUi) - kRi * kRi);
  double previous = 1e300;
  std::printf("inner pressure, exact %.6f N/mm²; r_o exact %.6f mm\n", exact, ro_exact);
  for (int nr : {2, 4, 8, 16}) {
    const TubeResult r = run_tube(nr, "mean_dilatation");
    const double err = std::abs(r.p / exact - 1);
    std::printf("  nr = %2d: p = %.6f, rel. error %.3e, r_o = %.6f (rel. error %.2e), max u_z %.1e, min σ_rr %.4f\n",
                nr, r.p, err, r.ro, std::abs(r.ro / ro_exact - 1), r.uz, r.srr_min);
    EXPECT_LT(err, previous) << "nr = " << nr;  // error falls with refinement
    EXPECT_NEAR(r.ro, ro_exact, 2e-3 * ro_exact);
    EXPECT_LT(std::abs(r.uz), 1e-12);             // plane strain: no node moves in z
    previous = err;
  }
  EXPECT_LT(previous, 2e-3);
}

TEST(SolidTubeDeck, TheDisplacementFormulationLocks) {
  const double exact = closed_form(kRi + kUi);
  const TubeResult q1 = run_tube(8, "displacement"), q1p0 = run_tube(8, "mean_dilatation");
  std::printf("nr = 8: displacement p = %.4f (error %.2e), mean dilatation p = %.4f (error %.2e)\n", q1.p,
              q1.p / exact - 1, q1p0.p, q1p0.p / exact - 1);
  EXPECT_GT(std::abs(q1.p / exact - 1), 10 * std::abs(q1p0.p / exact - 1));
}
