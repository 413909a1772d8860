#pragma once
// Second-order forward-mode differentiation for small kernels. A jet carries a
// value v, its gradient g = ∂v/∂y and its Hessian h = ∂²v/∂y² with respect to N
// independent variables y; the operations below propagate all three exactly by
// the chain rule:
//   (a ± b)'' = a'' ± b''
//   (a b)''   = a b'' + b a'' + a' b'ᵀ + b' a'ᵀ
//   φ(a)''    = φ'(a) a'' + φ''(a) a' a'ᵀ      (φ = 1/·, √·, ·²)
// so a function composed of them yields its exact first and second derivatives
// (up to rounding), with a symmetric Hessian.
#include <Eigen/Dense>
#include <cmath>

namespace tunica {

template <int N>
struct Jet {
  using Vec = Eigen::Matrix<double, N, 1>;
  using Mat = Eigen::Matrix<double, N, N>;
  double v = 0;
  Vec g = Vec::Zero();
  Mat h = Mat::Zero();

  /// A constant: zero gradient and Hessian.
  static Jet constant(double value) {
    Jet j;
    j.v = value;
    return j;
  }
  /// The independent variable y_i at `value`: gradient e_i, zero Hessian.
  static Jet variable(double value, int i) {
    Jet j;
    j.v = value;
    j.g(i) = 1.0;
    return j;
  }
};

/// φ(a) given φ, φ′ and φ″ at a.v.
template <int N>
Jet<N> chain(const Jet<N>& a, double f0, double f1, double f2) {
  Jet<N> r;
  r.v = f0;
  r.g = f1 * a.g;
  r.h = f1 * a.h + f2 * a.g * a.g.transpose();
  return r;
}

template <int N>
Jet<N> operator+(const Jet<N>& a, const Jet<N>& b) {
  Jet<N> r;
  r.v = a.v + b.v;
  r.g = a.g + b.g;
  r.h = a.h + b.h;
  return r;
}

template <int N>
Jet<N> operator-(const Jet<N>& a, const Jet<N>& b) {
  Jet<N> r;
  r.v = a.v - b.v;
  r.g = a.g - b.g;
  r.h = a.h - b.h;
  return r;
}

template <int N>
Jet<N> operator+(const Jet<N>& a, double c) {
  Jet<N> r = a;
  r.v += c;
  return r;
}

template <int N>
Jet<N> operator*(double c, const Jet<N>& a) {
  Jet<N> r;
  r.v = c * a.v;
  r.g = c * a.g;
  r.h = c * a.h;
  return r;
}

template <int N>
Jet<N> operator*(const Jet<N>& a, const Jet<N>& b) {
  Jet<N> r;
  r.v = a.v * b.v;
  r.g = a.v * b.g + b.v * a.g;
  const typename Jet<N>::Mat ab = a.g * b.g.transpose();
  r.h = a.v * b.h + b.v * a.h + ab + ab.transpose();
  return r;
}

template <int N>
Jet<N> operator-(const Jet<N>& a, double c) {
  return a + (-c);
}

/// 1/a:  φ′ = −1/a²,  φ″ = 2/a³.
template <int N>
Jet<N> inverse(const Jet<N>& a) {
  const double i = 1.0 / a.v;
  return chain(a, i, -i * i, 2.0 * i * i * i);
}

/// √a (a > 0):  φ′ = 1/(2√a),  φ″ = −1/(4 a √a).
template <int N>
Jet<N> sqrt(const Jet<N>& a) {
  const double s = std::sqrt(a.v);
  return chain(a, s, 0.5 / s, -0.25 / (a.v * s));
}

/// a²:  φ′ = 2a,  φ″ = 2.
template <int N>
Jet<N> square(const Jet<N>& a) {
  return chain(a, a.v * a.v, 2.0 * a.v, 2.0);
}

/// a/b = a · (1/b).
template <int N>
Jet<N> operator/(const Jet<N>& a, const Jet<N>& b) {
  return a * inverse(b);
}

}  // namespace tunica
