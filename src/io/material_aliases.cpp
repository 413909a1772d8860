#include "io/material_aliases.hpp"

#include <algorithm>
#include <cctype>

namespace tunica {

std::string foreign_constant_hint(const std::string& type, const std::string& key) {
  std::string k = key;
  std::transform(k.begin(), k.end(), k.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (k == "nu" || k == "v" || k == "poisson" || k == "poissons_ratio" || k == "d1" || k == "d" || k == "kappa_bulk" ||
      k == "bulk_modulus")
    return "Tunica's membrane materials are exactly incompressible (ν = 0.5, no bulk modulus or D1): leave it out";
  const bool c10 = k == "c10" || k == "c1", c01 = k == "c01" || k == "c2";
  const bool young = k == "e" || k == "youngs_modulus" || k == "young";
  const bool shear = k == "g" || k == "shear_modulus";
  if (type == "mooney_rivlin") {
    if (c10 || c01)
      return "W = b1 (I1 − 3) + b2 (I2 − 3) here, Abaqus' and FEBio's Mooney–Rivlin form: C10 is `b1` and C01 is `b2`";
    if (young || shear)
      return "give the I1 and I2 coefficients `b1`, `b2`: the shear modulus at rest is 2 (b1 + b2), and E = 3 × that "
             "for an incompressible material";
  }
  if (type == "neo_hookean") {
    if (c10) return "W = (μ/2)(I1 − 3) here: Abaqus' C10 is μ/2, so write `mu` = 2 × C10";
    if (young) return "write the shear modulus `mu`: for an incompressible material μ = E/3";
    if (shear) return "the shear modulus is `mu` here";
  }
  return "";
}

}  // namespace tunica
