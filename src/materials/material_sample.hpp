#pragma once
// Sample parameter sets that a material type declares next to its registration
// (membrane_material.hpp, solid_material.hpp): physically sensible constants, as a deck
// would write them, and the orientations of the material frame that exercise the
// material's anisotropy. The finite-difference tests (tests/support/material_registry.hpp)
// run every element kernel over every registered type × sample, so a material registered
// with its samples is checked by every element without touching a test file.
#include <string>
#include <utility>
#include <vector>

namespace tunica {

struct MaterialSample {
  /// Identifier, unique within the material type: letters, digits and '_' only (it becomes
  /// part of a test name, "<type>_<name>").
  std::string name;
  /// Where the values come from (a paper, an example deck, the theory manual).
  std::string doc;
  /// The parameters as deck text, key and value, e.g. {"c", "61.163 kPa"} or
  /// {"alpha", "[1.3, 5.0, -2.0]"}; read through the type's declaration like any deck, so a
  /// sample outside the declared ranges is an error. Omitted keys take their defaults.
  std::vector<std::pair<std::string, std::string>> values;
  /// Angles (rad) of the material direction 1 in the tangent plane, measured from a direction
  /// the test chooses (3-D membranes: a fixed skew direction of the element; material tests:
  /// the principal axes of the deformation). An isotropic material needs only {0}; a material
  /// with fibres or orthotropy lists angles that put its preferred directions off the axes of
  /// the deformation and of the element. Axisymmetric elements fix the frame (1 = hoop,
  /// 2 = meridian); there the orientation of fibres is the parameters' (e.g. HGO's β).
  std::vector<double> orientations = {0.0};
};

}  // namespace tunica
