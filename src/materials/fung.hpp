#pragma once
// Fung's exponential strain energy (theory manual (3.1)–(3.2); paper eqs. 22–26, the rat aorta):
//   W = c (exp Q − 1),
//   Q = a1 E1² + a2 E2² + a3 E3² + 2 a4 E1 E2 + 2 a5 E2 E3 + 2 a6 E1 E3 + a7 E12²,
// E_i = ½(C_ii − 1), E12 = ½ C12. a3 = a5 = a6 = 0 is the paper's
// "two-dimensional approach"; a7 is the in-plane shear term of Chuong & Fung.
#include <Eigen/Dense>

#include "materials/membrane_material.hpp"

namespace tunica {

class FungMaterial final : public MembraneMaterial {
public:
  /// A = [[a1,a4,a6],[a4,a2,a5],[a6,a5,a3]]; requires c > 0 and a positive definite quadratic form.
  FungMaterial(double c, const Eigen::Matrix3d& A, double a7);
  std::string type() const override { return "fung"; }
  EnergyDerivatives energy(const Eigen::Vector4d& v) const override;

  /// Whether the quadratic form is convex: A positive definite, or, in the two-dimensional
  /// approach (a3 = a5 = a6 = 0), its in-plane block positive definite; and a7 >= 0.
  static bool is_convex(const Eigen::Matrix3d& A, double a7);

private:
  double c_;
  Eigen::Matrix3d A_;
  double a7_;
  Eigen::Matrix4d d2Q_;  ///< d²Q/dv², constant
};

}  // namespace tunica
