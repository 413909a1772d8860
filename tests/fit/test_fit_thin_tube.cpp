// The thin-tube model of `tunica fit` against closed forms (theory manual §8): the
// same material code as the FE solver, reduced to a membrane tube.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/errors.hpp"
#include "fit/thin_tube.hpp"
#include "fit_test_support.hpp"

using namespace tunica;
using namespace tunica::fit_test;

// Theory manual (8.1): at fixed λz any material carries S_θ = p R λz / H; hoop_stretch_at_pressure
// finds that state and tube_state gives back the pressure.
TEST(FitThinTube, HoopEquilibriumClosedFormForAnyMaterial) {
  const TubeGeometry g = rat_aorta().geometry;
  const auto fung = make("fung2d", paper_fung());
  const auto nh = make("neo_hookean", Eigen::VectorXd::Constant(1, 0.5));
  const auto mr = make("mooney_rivlin", Eigen::Vector2d(0.2, 0.05));
  for (const MembraneMaterial* m : {fung.get(), nh.get(), mr.get()})
    for (double lz : {1.0, 1.3, 1.6})
      for (double p_mmHg : {0.0, 10.0, 50.0, 200.0}) {
        const double p = p_mmHg * kMmHg;
        const double lt = hoop_stretch_at_pressure(*m, g, p, lz);
        const TubeState s = tube_state(*m, g, lt, lz);
        EXPECT_NEAR(s.S_theta, p * g.R * lz / g.H, 1e-12 * std::max(1e-3, p * g.R * lz / g.H)) << m->type();
        EXPECT_NEAR(s.pressure, p, 1e-12 * std::max(1e-3, p));
      }
}

// A neo-Hookean tube at fixed λz carries at most p = μ H/(λz R) (S1 → μ): beyond it, no state.
TEST(FitThinTube, NoStateBeyondTheNeoHookeanPressureLimit) {
  const TubeGeometry g = rat_aorta().geometry;
  const auto nh = make("neo_hookean", Eigen::VectorXd::Constant(1, 0.1));
  const double limit = 0.1 * g.H / (1.6 * g.R);
  EXPECT_NO_THROW(hoop_stretch_at_pressure(*nh, g, 0.9 * limit, 1.6));
  EXPECT_THROW(hoop_stretch_at_pressure(*nh, g, 1.1 * limit, 1.6), SolveError);
}

// Paper §4.1 / theory manual (8.2), §12.1: prestretched to λz = 1.6 at p = 0, the tube narrows to λθ = 0.8695.
TEST(FitThinTube, PaperPrestretchHoopStretch) {
  const auto fung = make("fung2d", paper_fung());
  EXPECT_NEAR(hoop_stretch_at_pressure(*fung, rat_aorta().geometry, 0.0, 1.6), 0.8695, 5e-5);
}

// Neo-Hookean tube in closed form: S1 = μ(1 − λθ⁻⁴λz⁻²), S2 = μ(1 − λθ⁻²λz⁻⁴),
// p = μ (H/(λz R)) (1 − λθ⁻⁴λz⁻²), N = 2π R H λz μ (1 − λθ⁻²λz⁻⁴).
TEST(FitThinTube, NeoHookeanClosedForm) {
  const double mu = 0.2;
  const auto nh = make("neo_hookean", Eigen::VectorXd::Constant(1, mu));
  const TubeGeometry g = rat_aorta().geometry;
  for (double lt : {0.9, 1.0, 1.3, 2.0})
    for (double lz : {1.0, 1.2, 1.7}) {
      const TubeState s = tube_state(*nh, g, lt, lz);
      const double p = mu * g.H / (lz * g.R) * (1 - std::pow(lt, -4) * std::pow(lz, -2));
      const double N = 2 * std::numbers::pi * g.R * g.H * lz * mu * (1 - std::pow(lt, -2) * std::pow(lz, -4));
      EXPECT_NEAR(s.pressure, p, 1e-14);
      EXPECT_NEAR(s.membrane_force, N, 1e-14);
      EXPECT_NEAR(s.h, g.H / (lt * lz), 1e-15);
    }
}

// r + h/2 = D/2 with h = H/(λθλz): the outer diameter of a state gives back its mid radius;
// a diameter smaller than the wall allows has no root.
TEST(FitThinTube, OuterDiameterGivesMidRadius) {
  const auto fung = make("fung2d", paper_fung());
  const TubeGeometry g = rat_aorta().geometry;
  for (double lt : {0.8, 1.0, 1.5})
    for (double lz : {1.0, 1.6}) {
      const TubeState s = tube_state(*fung, g, lt, lz);
      const auto r = mid_radius_from_outer_diameter(g, s.outer_diameter, lz);
      ASSERT_TRUE(r.has_value());
      EXPECT_NEAR(*r, s.r, 1e-14);
    }
  EXPECT_FALSE(mid_radius_from_outer_diameter(g, 0.1, 1.0).has_value());
}

// Closed ends: the transducer reads N − π r² p.
TEST(FitThinTube, ClosedEndsSubtractTheCapLoad) {
  const auto fung = make("fung2d", paper_fung());
  TubeGeometry g = rat_aorta().geometry;
  const TubeState open = tube_state(*fung, g, 1.4, 1.6);
  g.ends = TubeEnds::closed;
  const TubeState closed = tube_state(*fung, g, 1.4, 1.6);
  EXPECT_DOUBLE_EQ(closed.membrane_force, open.membrane_force);
  EXPECT_NEAR(closed.axial_force, open.axial_force - std::numbers::pi * open.r * open.r * open.pressure, 1e-15);
}
