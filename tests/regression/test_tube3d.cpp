// The rat aorta as a 3-D Fung membrane tube (examples/rat-aorta-3d.yaml) against
// the thin-tube closed form (theory manual (8.1)) and the axisymmetric model. The quarter
// circumference is a regular polygon of n facets, φ = π/2n each. Inflated
// uniformly, a node takes p·chord·cos(φ/2) from the pressure on its two facets and
// 2T sin(φ/2) from the hoop tension: T = p r cos(φ/2), the Laplace law of a circle
// through the facet midpoints, R_eff = R cos(φ/2). So the 3-D tube must equal the
// closed form (and the axisymmetric model) of radius R_eff to solver round-off,
// its axial force that of the polygon's perimeter 2nR sin(φ/2), and its error
// against the circle of radius R falls as 1 − cos(φ/2) ≈ φ²/8: O(h²).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <tuple>
#include <numbers>

#include <fmt/format.h>

#include "../support/capture.hpp"
#include "../support/fung_tube.hpp"

using namespace tunica;
using namespace tunica::test;

namespace {

const std::string kDeck = std::string(TUNICA_SOURCE_DIR) + "/examples/rat-aorta-3d.yaml";

// Independent closed form (theory manual (3.2), (8.1)): tests/support/fung_tube.hpp.
using namespace fung_tube;

struct Errors {
  double hoop = 0;       ///< largest relative error of λθ, Sθ, Sz, h against the closed form of radius R
  double hoop_eff = 0;   ///< the same against the closed form of radius R_eff = R cos(φ/2)
  double force = 0;      ///< largest relative error of the axial force against the circle of radius R
  int increments = 0;
  int max_iterations = 0;
};

Errors run(const std::string& text, int around, double tol = 1e-9) {
  const Model m = read_deck_text(text, kDeck);
  Capture cap;
  Analysis a(m);
  a.run(cap);
  EXPECT_EQ(cap.cutbacks, 0);
  const int p = Capture::column(m, "pressure_mmHg"), lt = Capture::column(m, "lambda_theta"),
            lzc = Capture::column(m, "lambda_z"), st = Capture::column(m, "S_theta_kPa"),
            sz = Capture::column(m, "S_z_kPa"), sh = Capture::column(m, "S_theta_z_kPa"),
            h = Capture::column(m, "thickness_mm"), F = Capture::column(m, "axial_force_quarter_N");
  Errors e;
  const double phi = std::numbers::pi / (2 * around), R_eff = R * std::cos(phi / 2);
  const double Ez = 0.5 * (lz * lz - 1);
  for (const Row& row : cap.rows) {
    if (row.info.step != 2) continue;
    const double pk = row.values[p] * mmHg_kPa;
    EXPECT_NEAR(row.values[lzc], lz, tol);
    double F_exact = 0;
    for (const double Rc : {R, R_eff}) {
      const double St = pk * Rc * lz / H;  // theory manual (8.1): Sθ = p R λz / H
      const double Et = solve_E_theta(St, Ez);
      const double lt_exact = std::sqrt(2 * Et + 1);
      const double Sz = S2(Et, Ez);
      const double h_exact = H / (lt_exact * lz);
      EXPECT_LT(std::abs(row.values[sh]), 1e-9 * St);
      double worst = 0;
      for (double err : {std::abs(row.values[lt] / lt_exact - 1), std::abs(row.values[st] / St - 1),
                         std::abs(row.values[sz] / Sz - 1), std::abs(row.values[h] / h_exact - 1)})
        worst = std::max(worst, err);
      if (Rc == R) {
        e.hoop = std::max(e.hoop, worst);
        F_exact = Sz * 1e-3 * lz * H * (std::numbers::pi * R / 2);  // circle of radius R; kPa·mm² → N
      } else {
        e.hoop_eff = std::max(e.hoop_eff, worst);
        // Polygon: Sz(R_eff) λz H × reference perimeter 2nR sin(φ/2).
        const double F_polygon = Sz * 1e-3 * lz * H * 2 * around * R * std::sin(phi / 2);
        EXPECT_NEAR(row.values[F] / F_polygon, 1.0, tol);
      }
    }
    e.force = std::max(e.force, std::abs(row.values[F] / F_exact - 1));
    ++e.increments;
  }
  for (const auto& it : cap.iterations)
    if (it.info.step == 2) e.max_iterations = std::max(e.max_iterations, it.rec.iteration);
  return e;
}

std::string with_mesh(int around, const std::string& shape, int along) {
  return replace(read_text(kDeck), "around: 8, along: 2}",
                 "around: " + std::to_string(around) + ", along: " + std::to_string(along) + ", shape: " + shape + "}");
}

}  // namespace

TEST(Tube3d, FungTubeMatchesTheClosedFormInEveryInflationIncrement) {
  // Quads only: a union-jack triangulated tube with free end rings has near-mechanisms at
  // zero stress, too soft for the first Newton step of the prestretch from the stress-free
  // state (not resolved here); triangles are checked on the sphere,
  // the clamped tube (RotationInvariance) and the patch tests.
  for (const auto& [shape, along, tol] : {std::tuple{"quad", 2, 1e-9}}) {
    const Errors e = run(with_mesh(8, shape, along), 8, tol);
    std::printf("%s: max relative error vs R_eff closed form %.2e, vs R closed form %.3e, axial force %.3e, "
                "iterations ≤ %d\n", shape, e.hoop_eff, e.hoop, e.force, e.max_iterations);
    EXPECT_EQ(e.increments, 19);
    EXPECT_LT(e.hoop_eff, tol);
    EXPECT_LT(e.hoop, 5e-3);
    EXPECT_LE(e.max_iterations, 6);
  }
}

TEST(Tube3d, ErrorAgainstTheCircularTubeFallsAtSecondOrder) {
  const Errors e4 = run(with_mesh(4, "quad", 2), 4), e8 = run(with_mesh(8, "quad", 2), 8),
               e16 = run(with_mesh(16, "quad", 2), 16);
  const double r1 = std::log2(e4.hoop / e8.hoop), r2 = std::log2(e8.hoop / e16.hoop);
  const double f1 = std::log2(e4.force / e8.force), f2 = std::log2(e8.force / e16.force);
  std::printf("stress/stretch error vs the circle: 4 %.3e, 8 %.3e, 16 %.3e facets per quarter; rates %.3f, %.3f\n",
              e4.hoop, e8.hoop, e16.hoop, r1, r2);
  std::printf("axial force error: 4 %.3e, 8 %.3e, 16 %.3e; rates %.3f, %.3f\n", e4.force, e8.force, e16.force, f1, f2);
  for (double r : {r1, r2, f1, f2}) EXPECT_NEAR(r, 2.0, 0.05);
}

TEST(Tube3d, ReproducesTheAxisymmetricModelAtEveryPressure) {
  const std::string axi_deck = std::string(TUNICA_SOURCE_DIR) + "/examples/rat-aorta-inflation.yaml";
  std::map<long, std::vector<double>> axi;  // pressure in 0.1 mmHg → (λθ, Sθ, Sz, h)
  {
    // The axisymmetric tube of radius R_eff = R cos(φ/2), φ = π/16 (8 facets per quarter).
    const double R_eff = R * std::cos(std::numbers::pi / 32);
    const std::string r = fmt::format("{:.17g} mm", R_eff);
    const std::string text = replace(read_text(axi_deck), "from: [0.763 mm, 0 mm], to: [0.763 mm, 1 mm]",
                                     "from: [" + r + ", 0 mm], to: [" + r + ", 1 mm]");
    const Model m = read_deck_text(text, axi_deck);
    Capture cap;
    Analysis a(m);
    a.run(cap);
    for (const Row& r : cap.rows)
      if (r.info.step == 2)
        axi[std::lround(10 * r.values[Capture::column(m, "pressure_mmHg")])] = {
            r.values[Capture::column(m, "lambda_theta")], r.values[Capture::column(m, "S_theta_kPa")],
            r.values[Capture::column(m, "S_z_kPa")], r.values[Capture::column(m, "thickness_mm")]};
  }
  const Model m = read_deck_text(read_text(kDeck), kDeck);
  Capture cap;
  Analysis a(m);
  a.run(cap);
  int compared = 0;
  double worst = 0;
  for (const Row& r : cap.rows) {
    auto it = axi.find(std::lround(10 * r.values[Capture::column(m, "pressure_mmHg")]));
    if (r.info.step == 0 || it == axi.end()) continue;
    const double v[4] = {r.values[Capture::column(m, "lambda_theta")], r.values[Capture::column(m, "S_theta_kPa")],
                         r.values[Capture::column(m, "S_z_kPa")], r.values[Capture::column(m, "thickness_mm")]};
    for (int k = 0; k < 4; ++k) worst = std::max(worst, std::abs(v[k] / it->second[k] - 1));
    ++compared;
  }
  std::printf("3-D tube vs axisymmetric model: %d pressures, max relative difference %.2e\n", compared, worst);
  EXPECT_EQ(compared, 20);
  EXPECT_LT(worst, 1e-8);
}
