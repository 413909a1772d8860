#pragma once
// Shared helpers of the tests of `tunica fit`: materials through the registry and
// synthetic inflation–extension data in memory (full precision).
#include <Eigen/Dense>
#include <memory>
#include <vector>

#include "fit/material_parametrization.hpp"
#include "fit/synthetic_data.hpp"

namespace tunica::fit_test {

constexpr double kMmHg = 133.322387415e-6;  // N/mm² per mmHg (UDUNITS-2)
constexpr double kKPa = 1e-3;               // N/mm² per kPa

/// Fung constants (c [N/mm²], a1, a2, a4) of the paper (theory manual §12.1).
inline Eigen::VectorXd paper_fung() { return Eigen::Vector4d(61.163 * kKPa, 0.68238, 0.60558, 0.1067); }

inline std::unique_ptr<MembraneMaterial> make(const std::string& model, const Eigen::VectorXd& k) {
  return material_parametrization(model).make_material(k);
}

/// The rat aorta of theory manual §12.1: D = 1.648 mm, H = 0.122 mm.
inline Specimen rat_aorta(TubeEnds ends = TubeEnds::open) {
  Specimen s;
  s.geometry.H = 0.122;
  s.geometry.R = 0.5 * (1.648 - 0.122);
  s.geometry.ends = ends;
  return s;
}

/// 0, 10, ..., 200 mmHg.
inline std::vector<double> pressures_to_200_mmHg() {
  std::vector<double> p;
  for (int i = 0; i <= 20; ++i) p.push_back(10.0 * i * kMmHg);
  return p;
}

/// Data at λz = 1.5, 1.6, 1.7, 0 → 200 mmHg, outer diameter, with `noise` on pressure and force.
inline InflationData three_levels(const MembraneMaterial& m, double noise = 0, std::uint64_t seed = 1,
                                  TubeEnds ends = TubeEnds::open) {
  return synthesize_inflation_data(m, rat_aorta(ends), {1.5, 1.6, 1.7}, pressures_to_200_mmHg(),
                                   SizeMeasure::outer_diameter, NoiseLevels{noise, noise, 0.0}, seed);
}

}  // namespace tunica::fit_test
