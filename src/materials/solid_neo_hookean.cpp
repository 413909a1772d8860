// Compressible neo-Hookean solid in decoupled form (theory manual (10.2); the plaque, §12.2):
//
//   W_iso(C̄) = (μ/2)(Ī1 − 3),   Ī1 = tr C̄ = J^(−2/3) I1,
//   U(J)     = (κ/4)(J² − 1 − 2 ln J)
//
// U is the volumetric function of Simo & Taylor (CMAME 35 (1982) 107–118), listed
// in Holzapfel, Nonlinear Solid Mechanics (2000) §6.5. It is chosen over
// (κ/2)(J − 1)² because it grows without bound as J → 0 (a compressed element
// cannot be squeezed to zero volume at finite energy) and is convex in J;
// both have U(1) = U'(1) = 0 and U''(1) = κ, so μ and κ are the small-strain
// shear and bulk moduli.
//   U'(J)  = (κ/2)(J − 1/J)         (the hydrostatic stress p)
//   U''(J) = (κ/2)(1 + 1/J²)
//
// Isochoric stress and tangent (Holzapfel 2000 §6.6, neo-Hookean example):
//   S_iso = μ J^(−2/3) (I − (I1/3) C⁻¹),
//   𝒞_iso = (2μ/3) J^(−2/3) [ I1 (C⁻¹⊙C⁻¹ + ⅓ C⁻¹⊗C⁻¹) − I⊗C⁻¹ − C⁻¹⊗I ],
// from ∂I1/∂C = I, ∂J^(−2/3)/∂C = −⅓ J^(−2/3) C⁻¹, ∂C⁻¹/∂C = −C⁻¹⊙C⁻¹.
#include <cmath>
#include <stdexcept>

#include "materials/solid_material.hpp"

namespace tunica {

namespace {

class SolidNeoHookean final : public SolidMaterial {
public:
  SolidNeoHookean(double mu, double kappa) : mu_(mu), kappa_(kappa) {}
  std::string type() const override { return "neo_hookean_solid"; }

  IsochoricResponse isochoric(const Eigen::Matrix3d& C) const override {
    const double det = C.determinant();
    if (!(det > 0)) throw std::domain_error("neo-Hookean solid: det C must be positive");
    const double Jm23 = std::cbrt(1.0 / det);  // J^(−2/3) = (det C)^(−1/3)
    const double I1 = C.trace();
    const Eigen::Matrix3d Cinv = C.inverse();
    const Voigt6 ci = to_voigt(Cinv);
    const Voigt6 id = to_voigt(Eigen::Matrix3d::Identity());
    IsochoricResponse r;
    r.W = 0.5 * mu_ * (Jm23 * I1 - 3.0);
    r.S = mu_ * Jm23 * (id - (I1 / 3.0) * ci);
    r.D = (2.0 * mu_ / 3.0) * Jm23 *
          (I1 * (voigt_odot(Cinv) + ci * ci.transpose() / 3.0) - id * ci.transpose() - ci * id.transpose());
    return r;
  }

  VolumetricResponse volumetric(double J) const override {
    if (!(J > 0)) throw std::domain_error("neo-Hookean solid: J must be positive");
    return {0.25 * kappa_ * (J * J - 1.0 - 2.0 * std::log(J)), 0.5 * kappa_ * (J - 1.0 / J),
            0.5 * kappa_ * (1.0 + 1.0 / (J * J))};
  }

private:
  double mu_, kappa_;
};

const RegisterSolidMaterial reg(SolidMaterialType{
    ComponentSpec{"materials", "neo_hookean_solid",
                  "Solid parts: compressible neo-Hookean solid W = (μ/2)(Ī1 − 3) + (κ/4)(J² − 1 − 2 ln J), Ī1 = J^(−2/3) I1.",
                  {required(positive(number("mu", Dimension::pressure, "shear modulus μ"))),
                   required(positive(number("kappa", Dimension::pressure, "bulk modulus κ")))}},
    [](const Params& p) -> std::unique_ptr<SolidMaterial> {
      return std::make_unique<SolidNeoHookean>(p.number("mu"), p.number("kappa"));
    },
    {MaterialSample{"plaque", "the plaque of the paper's angioplasty example, κ/μ ≈ 1.45 (theory manual §12.2)",
                    {{"mu", "500 kPa"}, {"kappa", "724.6 kPa"}}},
     MaterialSample{"nearly_incompressible",
                    "a soft tissue with Poisson's ratio 0.495 (κ/μ = 100): the volumetric part dominates",
                    {{"mu", "50 kPa"}, {"kappa", "5 MPa"}}}}});

}  // namespace
}  // namespace tunica
