#include "loads/axisym_pressure.hpp"

#include <numbers>

namespace tunica {

void axisym_pressure(const AxisymNodes& x, double p, Eigen::Vector4d& f, Eigen::Matrix4d* dfdu) {
  const double r1 = x(0, 0), r2 = x(0, 1);
  const Eigen::Vector2d n(x(1, 1) - x(1, 0), -(x(0, 1) - x(0, 0)));
  const double m[2] = {r1 / 3.0 + r2 / 6.0, r1 / 6.0 + r2 / 3.0};
  const double c = 2.0 * std::numbers::pi * p;
  f << c * m[0] * n, c * m[1] * n;
  if (dfdu) {
    // ∂n/∂u for u = (r1, z1, r2, z2); ∂m_a/∂u.
    Eigen::Matrix<double, 2, 4> dn;
    dn << 0, -1, 0, 1,  //
        1, 0, -1, 0;
    const Eigen::RowVector4d dm[2] = {Eigen::RowVector4d(1.0 / 3.0, 0, 1.0 / 6.0, 0),
                                      Eigen::RowVector4d(1.0 / 6.0, 0, 1.0 / 3.0, 0)};
    for (int a = 0; a < 2; ++a) dfdu->middleRows<2>(2 * a) = c * (n * dm[a] + m[a] * dn);
  }
}

}  // namespace tunica
