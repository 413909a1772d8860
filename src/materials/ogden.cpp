#include "materials/ogden.hpp"

#include <fmt/format.h>

#include <cmath>

namespace tunica {

OgdenMaterial::OgdenMaterial(std::vector<double> mu, std::vector<double> alpha)
    : mu_(std::move(mu)), alpha_(std::move(alpha)) {}

double OgdenMaterial::g(int k, double c) const {
  // d^k/dc^k [μ/α c^(α/2)] = μ/α (α/2)(α/2 − 1)…(α/2 − k + 1) c^(α/2 − k).
  double sum = 0;
  for (std::size_t p = 0; p < mu_.size(); ++p) {
    const double e = 0.5 * alpha_[p];
    double falling = 1;
    for (int j = 0; j < k; ++j) falling *= e - j;
    sum += mu_[p] / alpha_[p] * falling * std::pow(c, e - k);
  }
  return sum;
}

EnergyDerivatives OgdenMaterial::energy(const Eigen::Vector4d& v) const {
  // Eigen-decomposition of the in-plane block: c1,2 = m ± r, m = (C11 + C22)/2,
  // r = √(((C11 − C22)/2)² + C12²); n1 = (cos θ, sin θ), n2 = (−sin θ, cos θ),
  // tan 2θ = 2 C12/(C11 − C22). θ = 0 when the eigenvalues are equal (any basis will do).
  const double m = 0.5 * (v(0) + v(1));
  const double d = 0.5 * (v(0) - v(1));
  const double r = std::hypot(d, v(2));
  const double c1 = m + r, c2 = m - r, c3 = v(3);
  const double theta = 0.5 * std::atan2(v(2), d);
  const double cs = std::cos(theta), sn = std::sin(theta);

  // With dC = [[dv1, dv3], [dv3, dv2]] (v3 = C12 stands for C12 and C21):
  //   dc_i = n_iᵀ dC n_i = a_i·dv,     a_i = (n_i1², n_i2², 2 n_i1 n_i2),
  //   n1ᵀ dC n2 = b·dv,                b = (n11 n21, n12 n22, n11 n22 + n12 n21),
  // and for F = g(c1) + g(c2) (second-order eigenvalue perturbation):
  //   dF  = Σ g'(c_i) a_i,
  //   d²F = Σ g''(c_i) a_i a_iᵀ + 2 [(g'(c1) − g'(c2))/(c1 − c2)] b bᵀ.
  const Eigen::Vector3d a1(cs * cs, sn * sn, 2.0 * cs * sn);
  const Eigen::Vector3d a2(sn * sn, cs * cs, -2.0 * cs * sn);
  const Eigen::Vector3d b(-cs * sn, sn * cs, cs * cs - sn * sn);

  // Divided difference of g'; near equal eigenvalues its Taylor series about m,
  //   (g'(m + r) − g'(m − r))/(2r) = g''(m) + g⁽⁴⁾(m) r²/3! + g⁽⁶⁾(m) r⁴/5! + O(r⁶),
  // whose truncation error ~(r/m)⁶ is below the rounding error of the quotient, ~ε m/r, at the switch.
  const double dd = r > kEqualEigenvalueGap * m
                        ? (g(1, c1) - g(1, c2)) / (c1 - c2)
                        : g(2, m) + r * r * (g(4, m) / 6.0 + r * r * g(6, m) / 120.0);

  double w0 = 0;  // Σ_p 3 μ_p/α_p
  for (std::size_t p = 0; p < mu_.size(); ++p) w0 += 3.0 * mu_[p] / alpha_[p];

  EnergyDerivatives out;
  out.W = g(0, c1) + g(0, c2) + g(0, c3) - w0;
  out.dW.head<3>() = g(1, c1) * a1 + g(1, c2) * a2;
  out.dW(3) = g(1, c3);
  out.d2W.topLeftCorner<3, 3>() =
      g(2, c1) * a1 * a1.transpose() + g(2, c2) * a2 * a2.transpose() + 2.0 * dd * b * b.transpose();
  out.d2W(3, 3) = g(2, c3);
  return out;
}

namespace {
const RegisterMaterial reg_ogden(MaterialType{
    ComponentSpec{"materials", "ogden",
                  "Incompressible Ogden law with N = 1…8 terms: W = Σₚ μ_p/α_p (λ1^α_p + λ2^α_p + λ3^α_p − 3), "
                  "λ1², λ2² the eigenvalues of the in-plane block of C, λ3² = C33. `mu` and `alpha` are lists of "
                  "equal length, e.g. `mu: [0.63 MPa, 0.0012 MPa, -0.01 MPa]`, `alpha: [1.3, 5.0, -2.0]`; "
                  "α_p ≠ 0, and the small-strain shear modulus ½ Σ μ_p α_p must be positive "
                  "(μ_p α_p > 0 for every term is advisable). One term with α = 2 is neo-Hookean with μ; "
                  "α = (2, −2) is Mooney–Rivlin with μ = (2 b1, −2 b2).",
                  {required(numbers("mu", Dimension::pressure, 0, "coefficients μ_p, one per term")),
                   required(numbers("alpha", Dimension::dimensionless, 0, "exponents α_p ≠ 0, one per term"))}},
    [](const Params& p) -> std::unique_ptr<MembraneMaterial> {
      const std::vector<double>& mu = p.numbers("mu");
      const std::vector<double>& alpha = p.numbers("alpha");
      if (mu.empty() || mu.size() > 8)
        p.fail("mu", fmt::format("Ogden needs 1 to 8 terms, got {} values of mu", mu.size()));
      if (alpha.size() != mu.size())
        p.fail("alpha", fmt::format("Ogden needs as many alpha as mu values: {} mu, {} alpha", mu.size(),
                                    alpha.size()));
      double shear = 0;
      for (std::size_t k = 0; k < alpha.size(); ++k) {
        if (alpha[k] == 0)
          p.fail("alpha", fmt::format("Ogden exponent alpha #{} is 0 (every alpha must be nonzero)", k + 1));
        shear += mu[k] * alpha[k];
      }
      if (!(shear > 0))
        p.fail("mu", fmt::format("Ogden initial shear modulus ½ Σ mu_p alpha_p = {:g} must be positive",
                                 0.5 * shear));
      return std::make_unique<OgdenMaterial>(mu, alpha);
    },
    // Isotropic: one orientation.
    {MaterialSample{"treloar_rubber",
                    "three terms, Ogden's (1972) fit of Treloar's rubber data (one term with μ_p α_p < 0)",
                    {{"mu", "[0.63 MPa, 0.0012 MPa, -0.01 MPa]"}, {"alpha", "[1.3, 5.0, -2.0]"}}},
     MaterialSample{"stiffening_soft_tissue",
                    "one term with a large exponent, strongly stiffening like soft tissue (illustrative)",
                    {{"mu", "[20 kPa]"}, {"alpha", "[9]"}}}}});
}  // namespace

}  // namespace tunica
