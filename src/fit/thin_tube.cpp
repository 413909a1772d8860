#include "fit/thin_tube.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "core/errors.hpp"

namespace tunica {

const char* tube_ends_name(TubeEnds ends) { return ends == TubeEnds::open ? "open" : "closed"; }

TubeState tube_state(const MembraneMaterial& material, const TubeGeometry& g, double lambda_theta, double lambda_z) {
  TubeState s;
  s.lambda_theta = lambda_theta;
  s.lambda_z = lambda_z;
  s.E_theta = 0.5 * (lambda_theta * lambda_theta - 1.0);
  s.E_z = 0.5 * (lambda_z * lambda_z - 1.0);
  const MembraneResponse m =
      membrane_response(material, Eigen::Vector3d(lambda_theta * lambda_theta, lambda_z * lambda_z, 0.0));
  s.S_theta = m.S(0);
  s.S_z = m.S(1);
  s.sigma_theta = lambda_theta * lambda_theta * s.S_theta;  // σ = F S Fᵀ, principal: σα = λα² Sα
  s.sigma_z = lambda_z * lambda_z * s.S_z;
  s.r = lambda_theta * g.R;
  s.h = g.H / (lambda_theta * lambda_z);  // λ3 = 1/(λθ λz)
  s.outer_diameter = 2.0 * s.r + s.h;
  s.pressure = s.sigma_theta * s.h / s.r;  // p r = σθ h
  s.membrane_force = 2.0 * std::numbers::pi * s.r * s.h * s.sigma_z;
  s.axial_force =
      g.ends == TubeEnds::open ? s.membrane_force : s.membrane_force - std::numbers::pi * s.r * s.r * s.pressure;
  return s;
}

std::optional<double> mid_radius_from_outer_diameter(const TubeGeometry& g, double outer_diameter, double lambda_z) {
  // r² − (D/2) r + H R/(2 λz) = 0
  const double disc = outer_diameter * outer_diameter / 16.0 - g.H * g.R / (2.0 * lambda_z);
  if (!(disc >= 0) || !(outer_diameter > 0)) return std::nullopt;
  return outer_diameter / 4.0 + std::sqrt(disc);
}

double hoop_stretch_at_pressure(const MembraneMaterial& material, const TubeGeometry& g, double pressure,
                                double lambda_z) {
  const double target = pressure * g.R * lambda_z / g.H;  // S1 at equilibrium
  // f(λθ) = S1(λθ, λz) − target; increasing for a material with D11 > 0. A non-finite
  // S1 (exp overflow at huge stretch) counts as "above".
  auto f = [&](double lt) {
    const double s1 = membrane_response(material, Eigen::Vector3d(lt * lt, lambda_z * lambda_z, 0.0)).S(0);
    return std::isfinite(s1) ? s1 - target : HUGE_VAL;
  };
  constexpr double kMin = 1e-3, kMax = 50.0;
  double lo = 1.0, hi = 1.0;
  double flo = f(lo), fhi = flo;
  if (flo == 0) return 1.0;
  if (flo < 0) {
    while (fhi < 0) {
      lo = hi;
      flo = fhi;
      hi *= 1.25;
      if (hi > kMax)
        throw SolveError(fmt::format("thin tube: no hoop stretch up to {} carries p = {:g} at axial stretch {:g}", kMax,
                                     pressure, lambda_z));
      fhi = f(hi);
    }
  } else {
    while (flo > 0) {
      hi = lo;
      fhi = flo;
      lo *= 0.8;
      if (lo < kMin)
        throw SolveError(fmt::format("thin tube: no hoop stretch down to {} carries p = {:g} at axial stretch {:g}",
                                     kMin, pressure, lambda_z));
      flo = f(lo);
    }
  }
  // Safeguarded Newton on [lo, hi] with f(lo) < 0 < f(hi): dS1/dλθ = D11 dE1/dλθ = D11 λθ.
  double x = 0.5 * (lo + hi);
  for (int it = 0; it < 200; ++it) {
    const MembraneResponse m = membrane_response(material, Eigen::Vector3d(x * x, lambda_z * lambda_z, 0.0));
    const double fx = m.S(0) - target;
    if (!std::isfinite(fx) || fx > 0)
      hi = x;
    else
      lo = x;
    if (fx == 0) return x;
    const double dfx = m.D(0, 0) * x;
    double next = x - fx / dfx;
    if (!std::isfinite(next) || next <= lo || next >= hi) next = 0.5 * (lo + hi);
    if (std::abs(next - x) <= 1e-15 * x || hi - lo <= 1e-15 * hi) return next;
    x = next;
  }
  return x;
}

}  // namespace tunica
