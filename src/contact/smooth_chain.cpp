// The chord-weighted Catmull–Rom master curve and its penalty contact; formulas in the header.
#include "contact/smooth_chain.hpp"

#include <cmath>
#include <stdexcept>

#include "core/jet.hpp"

namespace tunica {

namespace {

inline double value(double x) { return x; }
template <int N>
double value(const Jet<N>& x) {
  return x.v;
}

/// c, c′ and c″ (r and z components) of a segment at ξ, for a scalar type T (double, or a jet).
template <class T>
struct Curve {
  T c[2], d[2], dd[2];
};

/// The header's curve of segment k on the window Q (slots 0–3, components r, z); `ghost_first` /
/// `ghost_last`: slot 0 / 3 is the reflected ghost (its given value is ignored).
template <class T>
Curve<T> eval_curve(const T& xi, T Q[4][2], bool ghost_first, bool ghost_last) {
  using std::sqrt;
  for (int a = 0; a < 2; ++a) {
    if (ghost_first) Q[0][a] = 2.0 * Q[1][a] - Q[2][a];
    if (ghost_last) Q[3][a] = 2.0 * Q[2][a] - Q[1][a];
  }
  const auto length = [&](int i, int j) {
    const T dr = Q[j][0] - Q[i][0], dz = Q[j][1] - Q[i][1];
    const T l2 = dr * dr + dz * dz;
    if (!(value(l2) > 0)) throw std::domain_error("contact: master segment of zero length");
    return sqrt(l2);
  };
  const T la = length(0, 1), lb = length(1, 2), lc = length(2, 3);
  const T wa = lb / (la + lb), wc = lb / (lb + lc);
  const T x2 = xi * xi, x3 = x2 * xi;
  // Hermite functions (row 0), first (row 1) and second (row 2) derivatives.
  const T h00[3] = {2.0 * x3 - 3.0 * x2 + 1.0, 6.0 * x2 - 6.0 * xi, 12.0 * xi - 6.0};
  const T h10[3] = {x3 - 2.0 * x2 + xi, 3.0 * x2 - 4.0 * xi + 1.0, 6.0 * xi - 4.0};
  const T h01[3] = {-2.0 * x3 + 3.0 * x2, -6.0 * x2 + 6.0 * xi, -12.0 * xi + 6.0};
  const T h11[3] = {x3 - x2, 3.0 * x2 - 2.0 * xi, 6.0 * xi - 2.0};
  Curve<T> out;
  T* targets[3] = {out.c, out.d, out.dd};
  for (int a = 0; a < 2; ++a) {
    const T d1 = (Q[2][a] - Q[0][a]) * wa, d2 = (Q[3][a] - Q[1][a]) * wc;
    for (int o = 0; o < 3; ++o) targets[o][a] = h00[o] * Q[1][a] + h10[o] * d1 + h01[o] * Q[2][a] + h11[o] * d2;
  }
  return out;
}

/// The window's positions as doubles (ghost slots zero, filled by eval_curve).
void window_values(const Eigen::Ref<const Eigen::Matrix2Xd>& chain, const std::array<int, 4>& w, double Q[4][2]) {
  for (int j = 0; j < 4; ++j)
    for (int a = 0; a < 2; ++a) Q[j][a] = w[j] >= 0 ? chain(a, w[j]) : 0.0;
}

Curve<double> curve(const Eigen::Ref<const Eigen::Matrix2Xd>& chain, int k, double xi) {
  const std::array<int, 4> w = smooth_window(k, static_cast<int>(chain.cols()));
  double Q[4][2];
  window_values(chain, w, Q);
  return eval_curve(xi, Q, w[0] < 0, w[3] < 0);
}

using J = Jet<10>;

}  // namespace

std::array<int, 4> smooth_window(int k, int m) {
  if (m < 2 || k < 0 || k > m - 2) throw std::invalid_argument("contact: smooth master segment out of range");
  return {k - 1, k, k + 1, k + 2 <= m - 1 ? k + 2 : -1};
}

Eigen::Vector2d smooth_point(const Eigen::Ref<const Eigen::Matrix2Xd>& chain, int k, double xi) {
  const Curve<double> c = curve(chain, k, xi);
  return {c.c[0], c.c[1]};
}

SmoothProjection project_on_smooth_chain(const Eigen::Vector2d& x, const Eigen::Ref<const Eigen::Matrix2Xd>& chain,
                                         const ChainProjection& start, double end_tolerance) {
  SmoothProjection p;
  const int m = static_cast<int>(chain.cols());
  if (start.feature == ChainFeature::none) return p;
  int k = start.segment;
  double xi = start.feature == ChainFeature::segment ? start.xi : 1.0;
  int switches = 0;
  bool converged = false;
  // Newton on F(ξ) = (x − c)·c′ (F′ = −c′·c′ + (x − c)·c″; where that is not negative, the
  // Gauss–Newton −c′·c′, a descent step), steps capped at half a segment, hopping to a neighbour
  // when ξ leaves [0, 1] by more than round-off. Converged when the step moves the foot by less
  // than 1e-13 of the coordinates' size (round-off in ξ is ~1e-16 |x|/ℓ).
  for (int it = 0; it < 60 && !converged; ++it) {
    const Curve<double> c = curve(chain, k, xi);
    const double r0 = x(0) - c.c[0], r1 = x(1) - c.c[1];
    const double dd = c.d[0] * c.d[0] + c.d[1] * c.d[1];
    const double F = r0 * c.d[0] + r1 * c.d[1];
    double Fp = -dd + r0 * c.dd[0] + r1 * c.dd[1];
    if (!(Fp < 0)) Fp = -dd;
    if (!(Fp < 0)) throw std::domain_error("contact: smooth master curve with a zero tangent");
    const double step = std::max(-0.5, std::min(0.5, -F / Fp));
    xi += step;
    const double size = x.norm() + std::hypot(c.c[0], c.c[1]);
    converged = std::abs(step) * std::sqrt(dd) <= 1e-13 * size;
    constexpr double kHop = 1e-12;  // beyond [0, 1] by more than round-off
    if (xi > 1 + kHop && k < m - 2 && switches < 8) {
      ++k;
      xi -= 1;
      ++switches;
      converged = false;
    } else if (xi < -kHop && k > 0 && switches < 8) {
      --k;
      xi += 1;
      ++switches;
      converged = false;
    }
  }
  const Curve<double> c = curve(chain, k, xi);
  const double l = std::hypot(c.d[0], c.d[1]);
  if (!(l > 0)) throw std::domain_error("contact: smooth master curve with a zero tangent");
  const Eigen::Vector2d normal(c.d[1] / l, -c.d[0] / l);
  const double s = (x - Eigen::Vector2d(c.c[0], c.c[1])).dot(normal);
  // Beyond an end of the chain: no side there, except within the end tolerance τ (of the end
  // segment, measured on the cubic's continuation) when the foot's shift along the tangent is at
  // most half the distance |s| (the end tangent tilted by up to ~27°) and the node is not more
  // than τ end segments behind the surface itself (s ≥ −τℓ, whatever the offset).
  const double beyond = k == 0 && xi < 0 ? -xi : k == m - 2 && xi > 1 ? xi - 1 : 0.0;
  if (beyond > 0) {
    const double shift = beyond * l;
    if (beyond > end_tolerance || shift > 0.5 * std::abs(s) || s < -end_tolerance * l) return p;
  }
  p.found = true;
  p.segment = k;
  p.xi = xi;
  p.normal = normal;
  p.signed_distance = s;
  return p;
}

ContactPoint smooth_contact(const Eigen::Vector2d& xs, const Eigen::Ref<const Eigen::Matrix2Xd>& chain, int k,
                            double xi, double area, const ContactLaw& law, ContactVector10& f, ContactMatrix10* K) {
  f.setZero();
  if (K) K->setZero();
  const std::array<int, 4> w = smooth_window(k, static_cast<int>(chain.cols()));
  const Curve<double> c0 = curve(chain, k, xi);
  const double l0 = std::hypot(c0.d[0], c0.d[1]);
  if (!(l0 > 0)) throw std::domain_error("contact: smooth master curve with a zero tangent");
  ContactPoint p;
  p.xi = xi;
  p.normal = Eigen::Vector2d(c0.d[1], -c0.d[0]) / l0;
  p.gap = (xs - Eigen::Vector2d(c0.c[0], c0.c[1])).dot(p.normal) - law.offset;
  // Open at ξ (the common case): no jets. Else the state is taken from the jet below.
  if (!law.touching(p.gap)) return p;

  // Independent variables y = (x_s, window slots 0–3); a ghost slot's variables stay unused.
  double Qv[4][2];
  window_values(chain, w, Qv);
  const J x[2] = {J::variable(xs(0), 0), J::variable(xs(1), 1)};
  J Q[4][2];
  for (int j = 0; j < 4; ++j)
    for (int a = 0; a < 2; ++a) Q[j][a] = J::variable(Qv[j][a], 2 + 2 * j + a);
  const bool g0 = w[0] < 0, g3 = w[3] < 0;
  // One Newton step of F = (x − c)·c′ = 0 in jet arithmetic from the converged ξ*: it gives ξ*'s
  // value and gradient exactly, which is all the Hessian of g_N needs, since ∂g_N/∂ξ = 0 at the
  // foot point (x − c ∥ n ⊥ n′). (A second step, exact to the Hessian of ξ*, changes nothing.)
  J s = J::constant(xi);
  {
    const Curve<J> c = eval_curve(s, Q, g0, g3);
    const J r0 = x[0] - c.c[0], r1 = x[1] - c.c[1];
    const J F = r0 * c.d[0] + r1 * c.d[1];
    const J Fp = r0 * c.dd[0] + r1 * c.dd[1] - (c.d[0] * c.d[0] + c.d[1] * c.d[1]);
    s = s - F / Fp;
  }
  const Curve<J> c = eval_curve(s, Q, g0, g3);
  // g_N = (x − c)·n − offset, n = (c′_z, −c′_r)/|c′|.
  const J g = ((x[0] - c.c[0]) * c.d[1] - (x[1] - c.c[1]) * c.d[0]) / sqrt(c.d[0] * c.d[0] + c.d[1] * c.d[1]) -
              law.offset;
  // State, force and tangent all from this g_N, so the energy and its derivatives agree even if
  // the given ξ was not converged to the last bit.
  p.gap = g.v;
  p.active = law.touching(g.v);
  p.normal = Eigen::Vector2d(c.d[1].v, -c.d[0].v).normalized();
  if (!p.active) return p;
  p.pressure = law.pressure(g.v);
  p.energy = law.energy(g.v) * area;
  // f = −A_s p ∂g_N/∂y, K = A_s (p′ ∂g_N/∂y ⊗ ∂g_N/∂y − p ∂²g_N/∂y²), theory manual (9.3).
  const double pA = p.pressure * area, kA = law.stiffness(g.v) * area;
  f = -pA * g.g;
  if (K) *K = kA * g.g * g.g.transpose() - pA * g.h;
  return p;
}

}  // namespace tunica
