// Gauss–Legendre rule (gauss_legendre.hpp): Newton's method on P_n from the
// estimate t ≈ cos(π (i + ¾) / (n + ½)), P_n and P_n′ by the three-term
// recurrence  k P_k = (2k − 1) t P_{k−1} − (k − 1) P_{k−2},
//             P_n′ = n (t P_n − P_{n−1}) / (t² − 1).
#include "elements/gauss_legendre.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace tunica {

GaussRule gauss_legendre(int n) {
  if (n < 1 || n > 64) throw std::invalid_argument("gauss_legendre: the number of points must be in 1..64");
  GaussRule rule;
  rule.t.resize(n);
  rule.w.resize(n);
  for (int i = 0; i < (n + 1) / 2; ++i) {
    double t = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5));
    double dp = 0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = t;  // P_0, P_1
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * t * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      const double p = n == 1 ? t : p1;
      const double pm = n == 1 ? 1.0 : p0;  // P_{n−1}
      dp = n * (t * p - pm) / (t * t - 1.0);
      const double dt = p / dp;
      t -= dt;
      if (std::abs(dt) < 1e-16) break;
    }
    const double w = 2.0 / ((1.0 - t * t) * dp * dp);
    rule.t[i] = -t;  // ascending: the estimate above is descending from +1
    rule.t[n - 1 - i] = t;
    rule.w[i] = rule.w[n - 1 - i] = w;
  }
  if (n % 2 == 1) rule.t[n / 2] = 0.0;
  return rule;
}

}  // namespace tunica
