// Gauss–Legendre rules (elements/gauss_legendre.hpp): the n-point rule integrates
// every monomial t^k, k ≤ 2n − 1, exactly over [−1, 1] (∫ t^k = 2/(k + 1) for even
// k, 0 for odd k); abscissae ascending and symmetric; n outside 1..64 rejected.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "elements/gauss_legendre.hpp"

using namespace tunica;

TEST(GaussLegendre, IntegratesPolynomialsOfDegreeTwoNMinusOneExactly) {
  for (int n = 1; n <= 20; ++n) {
    const GaussRule g = gauss_legendre(n);
    ASSERT_EQ(static_cast<int>(g.t.size()), n);
    for (int i = 0; i < n; ++i) {
      EXPECT_NEAR(g.t[i], -g.t[n - 1 - i], 1e-15) << n;
      if (i > 0) {
        EXPECT_LT(g.t[i - 1], g.t[i]) << n;
      }
    }
    for (int k = 0; k <= 2 * n - 1; ++k) {
      double q = 0;
      for (int i = 0; i < n; ++i) q += g.w[i] * std::pow(g.t[i], k);
      EXPECT_NEAR(q, k % 2 ? 0.0 : 2.0 / (k + 1), 1e-14) << "n=" << n << " k=" << k;
    }
  }
  EXPECT_THROW(gauss_legendre(0), std::invalid_argument);
  EXPECT_THROW(gauss_legendre(65), std::invalid_argument);
}
