// Follower pressure and enclosed volume of an axisymmetric shell element on its
// Hermite mid-surface (equations in axisym_shell_pressure.hpp).
#include "loads/axisym_shell_pressure.hpp"

#include <numbers>

#include "elements/gauss_legendre.hpp"

namespace tunica {

namespace {

/// r, r_ξ, z_ξ of the Hermite meridian at one point.
struct MeridianPoint {
  double r = 0, rx = 0, zx = 0;
};

/// Positions relative to node 1 (x_ξ from differences of absolute coordinates loses digits on
/// short elements far from the axis; Σ h′ over the position functions is 0, Σ h = 1).
MeridianPoint evaluate(const HermiteBasis& hb, const ShellNodes& x) {
  MeridianPoint q;
  q.r = x(0, 0);
  for (int j = 0; j < 4; ++j) {
    const bool slope = j % 2 == 1;
    const double r = x(hermite_index(j, 0) % 4, hermite_index(j, 0) / 4) - (slope ? 0.0 : x(0, 0));
    const double z = x(hermite_index(j, 1) % 4, hermite_index(j, 1) / 4) - (slope ? 0.0 : x(1, 0));
    q.r += hb.h[j] * r;
    q.rx += hb.dh[j] * r;
    q.zx += hb.dh[j] * z;
  }
  return q;
}

}  // namespace

void axisym_shell_pressure(const ShellNodes& X, const ShellNodes& x, double p, ShellVector& f, ShellMatrix* dfdu) {
  const double L = hermite_length(X);
  const GaussRule g = gauss_legendre(5);
  f.setZero();
  if (dfdu) dfdu->setZero();
  for (std::size_t q = 0; q < g.t.size(); ++q) {
    const double xi = 0.5 * (1.0 + g.t[q]);
    const double w = 0.5 * g.w[q] * 2.0 * std::numbers::pi * p;
    const HermiteBasis hb = hermite_basis(xi, L);
    const MeridianPoint m = evaluate(hb, x);
    for (int j = 0; j < 4; ++j) {
      const int jr = hermite_index(j, 0), jz = hermite_index(j, 1);
      f(jr) += w * m.r * m.zx * hb.h[j];
      f(jz) -= w * m.r * m.rx * hb.h[j];
      if (!dfdu) continue;
      for (int k = 0; k < 4; ++k) {
        const int kr = hermite_index(k, 0), kz = hermite_index(k, 1);
        (*dfdu)(jr, kr) += w * m.zx * hb.h[j] * hb.h[k];
        (*dfdu)(jr, kz) += w * m.r * hb.h[j] * hb.dh[k];
        (*dfdu)(jz, kr) -= w * (m.rx * hb.h[j] * hb.h[k] + m.r * hb.h[j] * hb.dh[k]);
      }
    }
  }
}

double axisym_shell_volume(const ShellNodes& X, const ShellNodes& x, ShellVector* grad) {
  const double L = hermite_length(X);
  const GaussRule g = gauss_legendre(5);
  if (grad) grad->setZero();
  double V = 0;
  for (std::size_t q = 0; q < g.t.size(); ++q) {
    const double xi = 0.5 * (1.0 + g.t[q]);
    const double w = 0.5 * g.w[q] * std::numbers::pi;
    const HermiteBasis hb = hermite_basis(xi, L);
    const MeridianPoint m = evaluate(hb, x);
    V += w * m.r * m.r * m.zx;
    if (grad)
      for (int k = 0; k < 4; ++k) {
        (*grad)(hermite_index(k, 0)) += w * 2.0 * m.r * m.zx * hb.h[k];
        (*grad)(hermite_index(k, 1)) += w * m.r * m.r * hb.dh[k];
      }
  }
  return V;
}

}  // namespace tunica
