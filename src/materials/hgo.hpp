#pragma once
// Holzapfel–Gasser–Ogden (2000) strain energy in membrane form, with the fibre
// dispersion of Gasser–Ogden–Holzapfel (2006), theory manual (3.5). Incompressible: no
// volumetric part.
//   W = (μ/2)(I1 − 3) + Σ_{i=1,2} k1/(2 k2) [exp(k2 (I*_i − 1)²) − 1],
//   I1 = C11 + C22 + C33,
//   I4_i = a_i·C a_i = C11 cos²β + C22 sin²β ± 2 C12 cosβ sinβ,  a_{1,2} = (cosβ, ±sinβ, 0),
//   I*_i = κ I1 + (1 − 3κ) I4_i.
// A fibre family carries load only in tension: its term is zero unless I*_i > 1.
// Direction 1 is circumferential, 2 axial, 3 through the thickness.
#include <Eigen/Dense>

#include "materials/membrane_material.hpp"

namespace tunica {

class HgoMaterial final : public MembraneMaterial {
public:
  /// mu > 0, k1 >= 0, k2 > 0, beta the fibre angle from direction 1 (rad), kappa in [0, 1/3].
  HgoMaterial(double mu, double k1, double k2, double beta, double kappa);
  std::string type() const override { return "hgo"; }
  EnergyDerivatives energy(const Eigen::Vector4d& v) const override;

  /// I*_i of family i = 0 (+β) or 1 (−β) at v = (C11, C22, C12, C33).
  double fibre_invariant(int i, const Eigen::Vector4d& v) const { return 1.0 + fibre_strain(i, v); }

private:
  /// I*_i − 1 = dI*_i/dv · (v − v_I), v_I = (1, 1, 0, 1) (I*_i is linear in v and 1 at C = I),
  /// evaluated so that it is exactly 0 at C = I and fibres there are never in tension by rounding.
  double fibre_strain(int i, const Eigen::Vector4d& v) const { return dI_[i].dot(v - Eigen::Vector4d(1, 1, 0, 1)); }

  double mu_, k1_, k2_;
  /// dI*_i/dv (constant: I*_i is linear in v).
  Eigen::Vector4d dI_[2];
};

}  // namespace tunica
