#pragma once
// Incompressible hyperelastic materials for membranes (theory manual §2).
//
// A material is a pure function of strain: it gives its strain energy W and the
// first and second partial derivatives of W with respect to the membrane block
// of the 3-D right Cauchy–Green tensor in the material frame,
//     v = (C11, C22, C12, C33),   C13 = C23 = 0,
// with C12 the off-diagonal entry (standing for both C12 and C21, so that
// dW/dv3 = 2 ∂W/∂C12 as a tensor derivative). Direction 1 is circumferential,
// direction 2 axial (meridional), direction 3 through the thickness.
// Incompressibility and plane stress are not the material's business: the
// reduction in membrane_response() does them for every material alike.
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

/// W and its partial derivatives with respect to v = (C11, C22, C12, C33).
struct EnergyDerivatives {
  double W = 0;
  Eigen::Vector4d dW = Eigen::Vector4d::Zero();
  Eigen::Matrix4d d2W = Eigen::Matrix4d::Zero();
};

/// An incompressible strain energy W(C) for membranes.
class MembraneMaterial {
public:
  virtual ~MembraneMaterial() = default;
  /// The deck name of the model ("fung", ...).
  virtual std::string type() const = 0;
  /// W(v) and its first and second partial derivatives; v = (C11, C22, C12, C33).
  virtual EnergyDerivatives energy(const Eigen::Vector4d& v) const = 0;
  /// True if W depends on C through its invariants only (the material frame does not matter).
  virtual bool isotropic() const { return false; }
};

/// Membrane response at one point: reduced energy, 2nd Piola–Kirchhoff stress and tangent.
struct MembraneResponse {
  double W = 0;                                    ///< Ŵ(C) = W(C, C33(C))
  Eigen::Vector3d S = Eigen::Vector3d::Zero();     ///< (S11, S22, S12)
  Eigen::Matrix3d D = Eigen::Matrix3d::Zero();     ///< dS = D dE, dE = (dE11, dE22, 2 dE12)
  double C33 = 1;                                  ///< λ₃², thickness stretch squared
};

/// Theory manual (2.1)–(2.2): plane stress by the Lagrange multiplier p = 2 C33 ∂W/∂C33 with
/// C33 = 1/det C (orthonormal reference frame, det G = 1):
///   S^{αβ} = 2 ∂W/∂C_αβ − 2 C33 ∂W/∂C33 C^{αβ},  𝒞 = 2 dS/dC,
/// computed as derivatives of the reduced energy Ŵ(C) = W(C, 1/det C), (2.5)–(2.8).
/// `C` = (C11, C22, C12) in the material frame; det C must be positive.
MembraneResponse membrane_response(const MembraneMaterial& material, const Eigen::Vector3d& C);

/// A material type a deck can name: its declared parameters, a factory, and sample parameter
/// sets (at least one) that the tests run through every membrane and shell element.
struct MaterialType {
  ComponentSpec spec;
  std::function<std::unique_ptr<MembraneMaterial>(const Params&)> make;
  std::vector<MaterialSample> samples;
};

/// All registered material types by deck name.
const std::map<std::string, MaterialType>& material_types();

/// Registers a material type by name; used next to each class as a static object.
struct RegisterMaterial {
  explicit RegisterMaterial(MaterialType type);
};

}  // namespace tunica
