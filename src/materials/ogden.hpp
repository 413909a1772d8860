#pragma once
// Ogden's incompressible strain energy, N terms (theory manual (3.6)):
//   W = Σ_p μ_p/α_p (λ1^α_p + λ2^α_p + λ3^α_p − 3),
// λ1², λ2² the eigenvalues of the in-plane block [[C11, C12], [C12, C22]] and
// λ3² = C33. Written as W = g(c1) + g(c2) + g(c3) − Σ_p 3 μ_p/α_p with
// g(c) = Σ_p μ_p/α_p c^(α_p/2) and c_i = λ_i². The in-plane part is an isotropic
// spectral function of the 2×2 block, differentiated in spectral form so that it
// stays exact at equal in-plane stretches (equibiaxial states, the undeformed state).
#include <Eigen/Dense>
#include <vector>

#include "materials/membrane_material.hpp"

namespace tunica {

class OgdenMaterial final : public MembraneMaterial {
public:
  /// Equal lengths 1…8, every α_p ≠ 0, Σ μ_p α_p > 0 (checked by the deck reader).
  OgdenMaterial(std::vector<double> mu, std::vector<double> alpha);
  std::string type() const override { return "ogden"; }
  EnergyDerivatives energy(const Eigen::Vector4d& v) const override;
  bool isotropic() const override { return true; }

  /// Below this relative eigenvalue gap (c1 − c2)/(c1 + c2) the divided difference
  /// (g'(c1) − g'(c2))/(c1 − c2) is replaced by its Taylor series about the mean.
  static constexpr double kEqualEigenvalueGap = 1e-3;

  /// g^(k)(c), the k-th derivative of g(c) = Σ_p μ_p/α_p c^(α_p/2), k >= 0.
  double g(int k, double c) const;

private:
  std::vector<double> mu_, alpha_;
};

}  // namespace tunica
