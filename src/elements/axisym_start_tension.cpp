#include "elements/axisym_start_tension.hpp"

#include <numbers>

namespace tunica {

void axisym_normal_tension_stiffness(const Eigen::Vector2d& Xa, const Eigen::Vector2d& Xb, double T0,
                                     Eigen::Matrix4d& K) {
  K.setZero();
  const Eigen::Vector2d d = Xb - Xa;
  const double L = d.norm();
  if (!(L > 0)) return;
  const Eigen::Vector2d n(d(1) / L, -d(0) / L);
  const Eigen::Vector4d b(-n(0), -n(1), n(0), n(1));
  const double r_mid = 0.5 * (Xa(0) + Xb(0));
  K = (T0 * 2.0 * std::numbers::pi * r_mid / L) * (b * b.transpose());
}

}  // namespace tunica
