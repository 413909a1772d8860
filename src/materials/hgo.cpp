#include "materials/hgo.hpp"

#include <cmath>
#include <numbers>

namespace tunica {

namespace {
// |I* − 1| below which a fibre family is on its kink (round-off of C at the reference, far below any strain).
constexpr double kKinkBand = 1e-12;
}  // namespace

HgoMaterial::HgoMaterial(double mu, double k1, double k2, double beta, double kappa)
    : mu_(mu), k1_(k1), k2_(k2) {
  // I*_i = κ I1 + (1 − 3κ) I4_i is linear in v = (C11, C22, C12, C33):
  //   dI1/dv = (1, 1, 0, 1),  dI4_i/dv = (cos²β, sin²β, ±2 cosβ sinβ, 0)
  // (v3 = C12 stands for C12 and C21, hence the factor 2 of a_i·C a_i).
  const double c = std::cos(beta), s = std::sin(beta);
  const Eigen::Vector4d dI1(1, 1, 0, 1);
  for (int i = 0; i < 2; ++i) {
    const double sign = i == 0 ? 1.0 : -1.0;
    const Eigen::Vector4d dI4(c * c, s * s, sign * 2.0 * c * s, 0.0);
    dI_[i] = kappa * dI1 + (1.0 - 3.0 * kappa) * dI4;
  }
}

EnergyDerivatives HgoMaterial::energy(const Eigen::Vector4d& v) const {
  EnergyDerivatives out;
  // Ground matrix (μ/2)(I1 − 3): gradient (μ/2)(1, 1, 0, 1), no curvature.
  out.W = 0.5 * mu_ * (v(0) + v(1) + v(3) - 3.0);
  out.dW = Eigen::Vector4d(0.5 * mu_, 0.5 * mu_, 0.0, 0.5 * mu_);
  // Fibre family i, Ψ(I*) = k1/(2 k2)[exp(k2 (I* − 1)²) − 1] for I* > 1:
  //   Ψ'  = k1 (I* − 1) exp(k2 (I* − 1)²),
  //   Ψ'' = k1 [1 + 2 k2 (I* − 1)²] exp(k2 (I* − 1)²),
  //   dW += Ψ' dI*/dv,  d²W += Ψ'' (dI*/dv)(dI*/dv)ᵀ  (I* is linear in v).
  for (int i = 0; i < 2; ++i) {
    const Eigen::Vector4d& a = dI_[i];
    const double e = fibre_strain(i, v);  // I* − 1
    // The tension-only switch is a kink at I* = 1: Ψ' is continuous there, Ψ'' jumps from 0 to k1.
    // The stress-free reference lies on it, where e is a few ulps of either sign from Gauss point
    // to Gauss point; within round-off the tangent is the mean of the two sides, k1/2, at every
    // point alike (theory manual (3.5a)).
    if (std::abs(e) <= kKinkBand) {
      out.d2W += 0.5 * k1_ * (a * a.transpose());
      continue;
    }
    if (!(e > 0.0)) continue;  // tension only
    const double x = std::exp(k2_ * e * e);
    out.W += 0.5 * k1_ / k2_ * (x - 1.0);
    out.dW += k1_ * e * x * a;
    out.d2W += k1_ * (1.0 + 2.0 * k2_ * e * e) * x * (a * a.transpose());
  }
  return out;
}

namespace {
const RegisterMaterial reg_hgo(MaterialType{
    ComponentSpec{
        "materials", "hgo",
        "Holzapfel–Gasser–Ogden (2000) artery law in membrane form, incompressible (no volumetric part): "
        "W = (μ/2)(I1 − 3) + Σᵢ k1/(2 k2) [exp(k2 (Iᵢ* − 1)²) − 1] over two fibre families i = 1, 2, "
        "I1 = C11 + C22 + C33. The families lie in the 1–2 plane at ±β from the circumferential direction 1: "
        "I4ᵢ = C11 cos²β + C22 sin²β ± 2 C12 cosβ sinβ. Fibre dispersion (Gasser–Ogden–Holzapfel 2006): "
        "Iᵢ* = κ I1 + (1 − 3κ) I4ᵢ; κ = 0 is no dispersion, κ = 1/3 isotropic. A family carries load in "
        "tension only (Iᵢ* > 1); otherwise the isotropic ground matrix, μ > 0, carries the load alone. "
        "Small-strain shear modulus μ.",
        {required(positive(number("mu", Dimension::pressure, "shear modulus μ of the ground matrix"))),
         required(at_least(number("k1", Dimension::pressure, "fibre stiffness k1"), 0.0)),
         required(positive(number("k2", Dimension::dimensionless, "fibre exponential coefficient k2"))),
         required(at_most(at_least(number("beta", Dimension::angle,
                                          "fibre angle β from direction 1, between 0 and 90 deg "
                                          "(write the unit, e.g. `39.98 deg`: a plain number is radians)"),
                                   0.0),
                          0.5 * std::numbers::pi * (1.0 + 1e-12))),  // `90 deg` may round above π/2
         with_default(explaining_range(
                          at_most(at_least(number("kappa", Dimension::dimensionless, "fibre dispersion κ"), 0.0),
                                  1.0 / 3.0),
                          "κ runs from 0 (the fibres perfectly aligned along ±β) to 1/3 (isotropic dispersion: the "
                          "fibres spread evenly in every direction, no preferred one), the dispersion of Gasser, "
                          "Ogden & Holzapfel (2006). Some papers use another convention (an in-plane dispersion up "
                          "to 1/2, or the concentration b of the fibres' von Mises distribution, from which κ is "
                          "computed): convert such a value to this κ"),
                      "0")}},
    [](const Params& p) -> std::unique_ptr<MembraneMaterial> {
      return std::make_unique<HgoMaterial>(p.number("mu"), p.number("k1"), p.number("k2"), p.number("beta"),
                                           p.number("kappa"));
    },
    // Two fibre families at ±β. Orientations put them off the principal axes of the deformation
    // and of the element (0: the families symmetric about direction 1 of the test).
    {MaterialSample{"artery_media",
                    "the media of a rabbit carotid artery, Holzapfel, Gasser & Ogden (2000): μ = c = 3 kPa, "
                    "no dispersion",
                    {{"mu", "3 kPa"}, {"k1", "2.3632 kPa"}, {"k2", "0.8393"}, {"beta", "29 deg"}},
                    {0.0, 20.0 * std::numbers::pi / 180.0, -65.0 * std::numbers::pi / 180.0}},
     MaterialSample{"aneurysm_wall",
                    "the stiffened, dispersed wall of examples/aneurysm.yaml (illustrative, not fitted)",
                    {{"mu", "30 kPa"}, {"k1", "100 kPa"}, {"k2", "5"}, {"beta", "40 deg"}, {"kappa", "0.1"}},
                    {0.0, 55.0 * std::numbers::pi / 180.0}}}});
}  // namespace

}  // namespace tunica
