#include "materials/solid_material.hpp"

#include <cmath>
#include <stdexcept>

namespace tunica {

namespace {
// Voigt pairs in the order (11, 22, 33, 12, 23, 13).
constexpr int kPair[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {0, 2}};
}  // namespace

Voigt6 to_voigt(const Eigen::Matrix3d& A) {
  Voigt6 a;
  for (int I = 0; I < 6; ++I) a(I) = A(kPair[I][0], kPair[I][1]);
  return a;
}

Eigen::Matrix3d from_voigt(const Voigt6& a) {
  Eigen::Matrix3d A;
  for (int I = 0; I < 6; ++I) A(kPair[I][0], kPair[I][1]) = A(kPair[I][1], kPair[I][0]) = a(I);
  return A;
}

Voigt66 voigt_odot(const Eigen::Matrix3d& A) {
  Voigt66 D;
  for (int I = 0; I < 6; ++I)
    for (int J = 0; J < 6; ++J) {
      const int i = kPair[I][0], j = kPair[I][1], k = kPair[J][0], l = kPair[J][1];
      D(I, J) = 0.5 * (A(i, k) * A(j, l) + A(i, l) * A(j, k));
    }
  return D;
}

void add_volumetric_stress(const Eigen::Matrix3d& Cinv, double J, double p, double k, Voigt6& S, Voigt66& D) {
  const Voigt6 ci = to_voigt(Cinv);
  S += p * J * ci;
  D += J * (p + J * k) * ci * ci.transpose() - 2.0 * p * J * voigt_odot(Cinv);
}

SolidResponse solid_response(const SolidMaterial& material, const Eigen::Matrix3d& C) {
  const double det = C.determinant();
  if (!(det > 0)) throw std::domain_error("solid_response: det C must be positive");
  const double J = std::sqrt(det);
  const IsochoricResponse iso = material.isochoric(C);
  const VolumetricResponse vol = material.volumetric(J);
  SolidResponse r;
  r.W = iso.W + vol.U;
  r.S = iso.S;
  r.D = iso.D;
  add_volumetric_stress(C.inverse(), J, vol.dU, vol.d2U, r.S, r.D);
  return r;
}

static std::map<std::string, SolidMaterialType>& registry() {
  static std::map<std::string, SolidMaterialType> r;
  return r;
}

const std::map<std::string, SolidMaterialType>& solid_material_types() { return registry(); }

RegisterSolidMaterial::RegisterSolidMaterial(SolidMaterialType type) {
  const std::string name = type.spec.type;
  registry().emplace(name, std::move(type));
}

}  // namespace tunica
