#pragma once
// Gauss–Legendre quadrature on [−1, 1]: n points t_i (roots of the Legendre
// polynomial P_n) and weights w_i = 2 / ((1 − t_i²) P_n′(t_i)²), exact for
// polynomials of degree ≤ 2n − 1.
#include <vector>

namespace tunica {

struct GaussRule {
  std::vector<double> t;  ///< abscissae in [−1, 1], ascending
  std::vector<double> w;  ///< weights, summing to 2
};

/// The n-point rule, 1 ≤ n ≤ 64 (std::invalid_argument otherwise).
GaussRule gauss_legendre(int n);

}  // namespace tunica
