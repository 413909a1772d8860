#include "materials/membrane_material.hpp"

#include <stdexcept>

namespace tunica {

MembraneResponse membrane_response(const MembraneMaterial& material, const Eigen::Vector3d& C) {
  // Theory manual §2.1. det C and its derivatives with respect to x = (C11, C22, C12), (2.6).
  const double det = C(0) * C(1) - C(2) * C(2);
  if (!(det > 0)) throw std::domain_error("membrane_response: det C must be positive");
  const double c33 = 1.0 / det;
  const Eigen::Vector3d ddet(C(1), C(0), -2.0 * C(2));
  // C33 = 1/det:  dC33 = −C33² ddet,  d²C33 = 2 C33³ ddet ddetᵀ − C33² d²det.
  const double c33_2 = c33 * c33, c33_3 = 2.0 * c33_2 * c33;
  const Eigen::Vector3d dc33 = -c33_2 * ddet;

  const EnergyDerivatives e = material.energy(Eigen::Vector4d(C(0), C(1), C(2), c33));
  const Eigen::Vector3d Wx = e.dW.head<3>();
  const double W3 = e.dW(3);
  const Eigen::Matrix3d Wxx = e.d2W.topLeftCorner<3, 3>();
  const Eigen::Vector3d Wx3 = e.d2W.block<3, 1>(0, 3);
  const double W33 = e.d2W(3, 3);

  // Reduced energy Ŵ(x) = W(x, C33(x)), (2.5): gradient g and Hessian H (chain rule), (2.7):
  //   H = W_xx + W_x3 dC33ᵀ + dC33 W_x3ᵀ + W33 dC33 dC33ᵀ + W3 d²C33,  d²det = [[0,1,0],[1,0,0],[0,0,−2]],
  // symmetric: its upper triangle, each entry once.
  // Where W does not depend on C33 (W3, W_x3 and W33 zero: Fung's two-dimensional approach, (3.2)),
  // every term but W_x and W_xx is zero: g = W_x, H = W_xx.
  const bool plane = W3 == 0 && W33 == 0 && (Wx3.array() == 0).all();
  const Eigen::Vector3d g = plane ? Wx : Eigen::Vector3d(Wx + W3 * dc33);
  const auto H = [&](int i, int j, double d2det) {
    if (plane) return Wxx(i, j);
    return Wxx(i, j) + (Wx3(i) * dc33(j) + dc33(i) * Wx3(j)) + W33 * (dc33(i) * dc33(j)) +
           W3 * (c33_3 * (ddet(i) * ddet(j)) - c33_2 * d2det);
  };
  // Voigt form (2.8). S = 2 ∂Ŵ/∂C as a tensor: S11 = 2 g1, S22 = 2 g2, S12 = g3 (x3 stands for C12 and C21);
  // dS/dx = diag(2,2,1) H and dx = diag(2,2,1) dE (engineering shear): D = diag(2,2,1) H diag(2,2,1).
  Eigen::Matrix3d D;
  D(0, 0) = 4.0 * H(0, 0, 0.0);
  D(1, 1) = 4.0 * H(1, 1, 0.0);
  D(2, 2) = H(2, 2, -2.0);
  D(0, 1) = D(1, 0) = 4.0 * H(0, 1, 1.0);
  D(0, 2) = D(2, 0) = 2.0 * H(0, 2, 0.0);
  D(1, 2) = D(2, 1) = 2.0 * H(1, 2, 0.0);
  return {.W = e.W, .S = Eigen::Vector3d(2.0 * g(0), 2.0 * g(1), g(2)), .D = D, .C33 = c33};
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
