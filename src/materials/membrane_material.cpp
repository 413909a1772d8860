#include "materials/membrane_material.hpp"

#include <stdexcept>

namespace tunica {

MembraneResponse membrane_response(const MembraneMaterial& material, const Eigen::Vector3d& C) {
  // Theory manual §2.1. det C and its derivatives with respect to x = (C11, C22, C12), (2.6).
  const double det = C(0) * C(1) - C(2) * C(2);
  if (!(det > 0)) throw std::domain_error("membrane_response: det C must be positive");
  const double c33 = 1.0 / det;
  const Eigen::Vector3d ddet(C(1), C(0), -2.0 * C(2));
  Eigen::Matrix3d d2det;
  d2det << 0, 1, 0, 1, 0, 0, 0, 0, -2;
  // C33 = 1/det:  dC33 = -C33² ddet,  d²C33 = 2 C33³ ddet ddetᵀ - C33² d²det.
  const Eigen::Vector3d dc33 = -c33 * c33 * ddet;
  const Eigen::Matrix3d d2c33 = 2.0 * c33 * c33 * c33 * ddet * ddet.transpose() - c33 * c33 * d2det;

  const EnergyDerivatives e = material.energy(Eigen::Vector4d(C(0), C(1), C(2), c33));
  const Eigen::Vector3d Wx = e.dW.head<3>();
  const double W3 = e.dW(3);
  const Eigen::Matrix3d Wxx = e.d2W.topLeftCorner<3, 3>();
  const Eigen::Vector3d Wx3 = e.d2W.block<3, 1>(0, 3);
  const double W33 = e.d2W(3, 3);

  // Reduced energy Ŵ(x) = W(x, C33(x)), (2.5): gradient g and Hessian H (chain rule), (2.7).
  const Eigen::Vector3d g = Wx + W3 * dc33;
  const Eigen::Matrix3d H = Wxx + Wx3 * dc33.transpose() + dc33 * Wx3.transpose() +
                            W33 * dc33 * dc33.transpose() + W3 * d2c33;

  MembraneResponse r;
  r.W = e.W;
  r.C33 = c33;
  // Voigt form (2.8). S = 2 ∂Ŵ/∂C as a tensor: S11 = 2 g1, S22 = 2 g2, S12 = g3 (x3 stands for C12 and C21).
  r.S = Eigen::Vector3d(2.0 * g(0), 2.0 * g(1), g(2));
  // dS/dx = diag(2,2,1) H and dx = diag(2,2,1) dE (engineering shear).
  const Eigen::Vector3d s(2.0, 2.0, 1.0);
  r.D = s.asDiagonal() * H * s.asDiagonal();
  return r;
}

static std::map<std::string, MaterialType>& registry() {
  static std::map<std::string, MaterialType> r;
  return r;
}

const std::map<std::string, MaterialType>& material_types() { return registry(); }

RegisterMaterial::RegisterMaterial(MaterialType type) {
  const std::string name = type.spec.type;
  registry().emplace(name, std::move(type));
}

}  // namespace tunica
