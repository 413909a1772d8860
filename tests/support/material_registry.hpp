#pragma once
// Tests over the material registries. Every registered membrane (solid) material type declares
// sample parameter sets next to its registration (materials/material_sample.hpp); a test suite
// instantiated with
//     INSTANTIATE_TEST_SUITE_P(Registry, Suite, ::testing::ValuesIn(membrane_cases()), case_name);
// runs once per type × sample (× orientation, if asked), so that a material registered with its
// samples is tested by every element without touching a test file. The generator runs when
// GoogleTest registers its tests (in main), after the registries are filled.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <ostream>
#include <string>
#include <vector>

#include "material_from_yaml.hpp"
#include "materials/membrane_material.hpp"
#include "materials/solid_material.hpp"

namespace tunica::test {

/// One registered material type with one of its samples and one of the sample's orientations.
struct MaterialCase {
  std::string type;
  std::string sample;
  int orientation = 0;  ///< index into the sample's orientations
  double angle = 0;     ///< that orientation (rad)
  bool solid = false;   ///< from the solid registry
  bool named_by_orientation = false;  ///< one of several orientations of its sample (the test name says which)
};

/// "hgo artery_media, orientation 20 deg": in GoogleTest's messages about a failing case.
inline void PrintTo(const MaterialCase& c, std::ostream* os) {
  *os << c.type << " " << c.sample << ", orientation " << c.angle * 180 / std::numbers::pi << " deg";
}

/// The sample a case names.
inline const MaterialSample& sample_of(const MaterialCase& c) {
  const std::vector<MaterialSample>& samples =
      c.solid ? solid_material_types().at(c.type).samples : material_types().at(c.type).samples;
  for (const MaterialSample& s : samples)
    if (s.name == c.sample) return s;
  throw std::out_of_range("no sample '" + c.sample + "' of material type '" + c.type + "'");
}

/// The deck text of a sample: "{type: hgo, mu: 3 kPa, ...}".
inline std::string sample_yaml(const std::string& type, const MaterialSample& s) {
  std::string yaml = "{type: " + type;
  for (const auto& [key, value] : s.values) yaml += ", " + key + ": " + value;
  return yaml + "}";
}
inline std::string sample_yaml(const MaterialCase& c) { return sample_yaml(c.type, sample_of(c)); }

/// The material of a case, built from its deck text through the registry (as a deck builds it).
inline std::unique_ptr<MembraneMaterial> make_membrane(const MaterialCase& c) { return material_from_yaml(sample_yaml(c)); }
inline std::unique_ptr<SolidMaterial> make_solid(const MaterialCase& c) { return solid_from_yaml(sample_yaml(c)); }

/// Records a test's largest error in its XML report (`--gtest_output=xml`), e.g. the worst
/// relative finite-difference error over its states, in scientific notation.
inline void record_error(const char* key, double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3e", value);
  ::testing::Test::RecordProperty(key, text);
}

/// A stress scale of a membrane material: the shear modulus μ of the neo-Hookean material whose
/// small-strain tangent, μ [[4, 2, 0], [2, 4, 0], [0, 0, 1]], has the same norm as this one's.
/// Loads in the tests are taken in proportion to it, so that they neither hide the material nor
/// vanish beside it, whatever the sample's units.
inline double sample_scale(const MembraneMaterial& m) {
  return membrane_response(m, Eigen::Vector3d(1, 1, 0)).D.norm() / std::sqrt(41.0);
}

enum class Orientations {
  first,  ///< one case per sample, at its first orientation (axisymmetric elements fix the frame)
  each,   ///< one case per sample and orientation
};

namespace detail {
inline void add_cases(std::vector<MaterialCase>& out, const std::string& type, const std::vector<MaterialSample>& samples,
                      Orientations o, bool solid) {
  for (const MaterialSample& s : samples) {
    const int n = o == Orientations::each ? static_cast<int>(s.orientations.size()) : 1;
    for (int k = 0; k < n; ++k)
      out.push_back({type, s.name, k, s.orientations.empty() ? 0.0 : s.orientations[k], solid, n > 1});
  }
}
}  // namespace detail

/// Every registered membrane material type × its samples (× orientations).
inline std::vector<MaterialCase> membrane_cases(Orientations o = Orientations::first) {
  std::vector<MaterialCase> out;
  for (const auto& [type, t] : material_types()) detail::add_cases(out, type, t.samples, o, false);
  return out;
}

/// Every registered solid material type × its samples (× orientations).
inline std::vector<MaterialCase> solid_cases(Orientations o = Orientations::first) {
  std::vector<MaterialCase> out;
  for (const auto& [type, t] : solid_material_types()) detail::add_cases(out, type, t.samples, o, true);
  return out;
}

/// Test name of a case: "<type>_<sample>", with "_at<angle>deg" ("_atm50deg" for −50°) when the
/// sample has several orientations and cases were made for each.
inline std::string case_name(const ::testing::TestParamInfo<MaterialCase>& info) {
  const MaterialCase& c = info.param;
  std::string name = c.type + "_" + c.sample;
  if (c.named_by_orientation) {
    const long deg = std::lround(c.angle * 180 / std::numbers::pi);
    name += "_at" + std::string(deg < 0 ? "m" : "") + std::to_string(std::labs(deg)) + "deg";
  }
  return name;
}

}  // namespace tunica::test
