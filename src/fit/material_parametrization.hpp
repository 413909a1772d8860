#pragma once
// How `tunica fit` explores the constants of a built-in material: internal
// variables θ, bounded boxes only, that map onto admissible constants alone, so
// that no iterate and no result can be a non-convex (or non-positive) energy.
//   fung2d:        θ = (ln c, L11, L21, L22),  [[a1,a4],[a4,a2]] = L Lᵀ,  L11, L22 ≥ 1e-4
//   fung3d:        θ = (ln c, L11, L21, L22, L31, L32, L33),
//                  [[a1,a4,a6],[a4,a2,a5],[a6,a5,a3]] = L Lᵀ, diagonal of L ≥ 1e-4
//   neo_hookean:   θ = (ln μ)
//   mooney_rivlin: θ = (ln b1, t), b2 = t b1, t ≥ 0
// (theory manual §3: convexity of Fung's law needs c > 0 and a positive definite
// quadratic form; a Cholesky factor with a positive diagonal gives exactly those.)
// θ(0) is always the logarithm of a stress-like factor to which every stress, so
// every predicted pressure and force, is proportional.
// The tube (C12 = 0) cannot see Fung's shear coefficient a7: it stays 0.
#include <Eigen/Dense>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "materials/membrane_material.hpp"

namespace tunica {

/// A material constant a fit reports: its deck key and dimension.
struct FittedConstant {
  std::string name;
  Dimension dim = Dimension::dimensionless;
};

/// One fittable model (see the file comment).
struct MaterialParametrization {
  std::string model;          ///< `--model` name
  std::string material_type;  ///< the deck material type it builds
  std::string doc;
  std::vector<FittedConstant> constants;  ///< in deck order
  std::vector<std::string> theta_names;
  Eigen::VectorXd lower, upper;  ///< box bounds of θ
  /// θ → constants (internal units, N/mm² for stresses).
  std::function<Eigen::VectorXd(const Eigen::VectorXd& theta)> constants_of;
  /// constants → θ. Constants outside the admissible set are first projected onto it
  /// (eigenvalues of Fung's matrix raised to 1e-8, negative b2 to 0); a non-positive
  /// scale gives nullopt. `projected` (if given) tells whether that happened.
  std::function<std::optional<Eigen::VectorXd>(const Eigen::VectorXd& constants, bool* projected)> theta_of;
  /// Starting points (θ with θ(0) = 0, to be scaled to the data).
  std::vector<Eigen::VectorXd> starts;

  /// The material through the registry, from a deck map {type, constants...}: the very
  /// factory and validation a deck uses. Throws InputError if the constants are refused.
  std::unique_ptr<MembraneMaterial> make_material(const Eigen::VectorXd& constants) const;
  /// d constants / d θ (central differences of constants_of).
  Eigen::MatrixXd constants_jacobian(const Eigen::VectorXd& theta) const;
};

/// The fittable models by `--model` name: fung2d, fung3d, neo_hookean, mooney_rivlin.
const std::map<std::string, MaterialParametrization>& material_parametrizations();

/// The model named `name`; throws InputError({"--model"}) listing the known ones.
const MaterialParametrization& material_parametrization(const std::string& name);

}  // namespace tunica
