#pragma once
// (Nearly) incompressible hyperelastic materials for solid elements (theory manual §10,
// (10.2); the plaque of the angioplasty model, §12.2).
//
// The strain energy is written in the decoupled (volumetric–isochoric) form
//     W(C) = W_iso(C̄) + U(J),   C̄ = J^(−2/3) C,   J = det F = √(det C)
// (Flory 1961; Simo, Taylor & Pister, CMAME 51 (1985) 177–208; Holzapfel,
// Nonlinear Solid Mechanics (2000) §6.4). A material gives the two parts
// separately, because the mixed (Q1/P0, mean-dilatation) element evaluates
// W_iso with the pointwise J and U with the element volume ratio θ:
//   - isochoric(C): W_iso(C̄(C)), S_iso = 2 ∂W_iso/∂C and 𝒞_iso = 4 ∂²W_iso/∂C∂C
//     (both as functions of the full C, i.e. already projected:
//      S_iso = J^(−2/3) Dev S̄, Holzapfel (6.91));
//   - volumetric(J): U(J), U'(J), U''(J).
//
// Tensors are 3-D and symmetric, in Voigt order (11, 22, 33, 12, 23, 13) of
// tensor components (no factor 2 on the shear entries of S). A tangent D is the
// 6×6 matrix of 𝒞_ijkl over the same pairs, so that dS = D dE with the
// engineering shear dE = (dE11, dE22, dE33, 2dE12, 2dE23, 2dE13).
// Axisymmetric elements use directions (1, 2, 3) = (r, z, θ): the components
// (rr, zz, θθ, rz) are then the first four Voigt entries.
#include <Eigen/Dense>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "materials/material_sample.hpp"
#include "params/param_spec.hpp"
#include "params/params.hpp"

namespace tunica {

using Voigt6 = Eigen::Matrix<double, 6, 1>;
using Voigt66 = Eigen::Matrix<double, 6, 6>;

/// Voigt vector (11, 22, 33, 12, 23, 13) of a symmetric 3×3 tensor (tensor components).
Voigt6 to_voigt(const Eigen::Matrix3d& A);
/// The symmetric 3×3 tensor of a Voigt vector.
Eigen::Matrix3d from_voigt(const Voigt6& a);
/// (A ⊙ A)_ijkl = ½(A_ik A_jl + A_il A_jk) as a 6×6 Voigt matrix (A symmetric).
Voigt66 voigt_odot(const Eigen::Matrix3d& A);

/// The isochoric part: W_iso(C̄(C)) and its derivatives with respect to C.
struct IsochoricResponse {
  double W = 0;
  Voigt6 S = Voigt6::Zero();    ///< S_iso = 2 ∂W_iso/∂C
  Voigt66 D = Voigt66::Zero();  ///< 𝒞_iso = 4 ∂²W_iso/∂C∂C
};

/// The volumetric part U(J) and its first two derivatives.
struct VolumetricResponse {
  double U = 0;
  double dU = 0;   ///< U'(J): the hydrostatic (mean Cauchy) stress, positive in tension
  double d2U = 0;  ///< U''(J)
};

/// A decoupled strain energy W(C) = W_iso(C̄) + U(J) for solids.
class SolidMaterial {
public:
  virtual ~SolidMaterial() = default;
  /// The deck name of the model ("neo_hookean", ...).
  virtual std::string type() const = 0;
  /// W_iso(C̄(C)), S_iso, 𝒞_iso at the 3-D right Cauchy–Green tensor C (det C > 0).
  virtual IsochoricResponse isochoric(const Eigen::Matrix3d& C) const = 0;
  /// U(J), U'(J), U''(J) for J > 0.
  virtual VolumetricResponse volumetric(double J) const = 0;
};

/// The volumetric stress of a pressure p acting through J = √det C, and its tangent
/// when p varies with J at the rate k = dp/dJ (Holzapfel 2000 §6.5):
///   S_vol = p J C⁻¹,
///   𝒞_vol = 2 ∂S_vol/∂C = J (p + J k) C⁻¹⊗C⁻¹ − 2 p J C⁻¹⊙C⁻¹.
/// With p = U'(J), k = U''(J) these are the derivatives of U(J); with k = 0 they
/// are p times the derivatives of J (dJ/dE = J C⁻¹), as the mixed element needs.
void add_volumetric_stress(const Eigen::Matrix3d& Cinv, double J, double p, double k, Voigt6& S, Voigt66& D);

/// The full (compressible) response W(C) = W_iso + U(J), S = S_iso + J U'(J) C⁻¹, 𝒞 = 𝒞_iso + 𝒞_vol.
struct SolidResponse {
  double W = 0;
  Voigt6 S = Voigt6::Zero();
  Voigt66 D = Voigt66::Zero();
};
SolidResponse solid_response(const SolidMaterial& material, const Eigen::Matrix3d& C);

/// A solid material type a deck can name: its declared parameters, a factory, and sample
/// parameter sets (at least one) that the tests run through the solid element.
struct SolidMaterialType {
  ComponentSpec spec;
  std::function<std::unique_ptr<SolidMaterial>(const Params&)> make;
  std::vector<MaterialSample> samples;
};

/// All registered solid material types by deck name (separate from the membrane materials).
const std::map<std::string, SolidMaterialType>& solid_material_types();

/// Registers a solid material type by name; used next to each class as a static object.
struct RegisterSolidMaterial {
  explicit RegisterSolidMaterial(SolidMaterialType type);
};

}  // namespace tunica
