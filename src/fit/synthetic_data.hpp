#pragma once
// Synthetic inflation–extension data from known constants: the thin tube of
// thin_tube.hpp driven by pressure at fixed axial stretches (hoop equilibrium
// solved for λθ, theory manual (8.1)), with optional Gaussian measurement noise. Used by
// `tunica synthesize` to make examples/fit/ and by the round-trip tests, so that the
// data come from the same material code the fit and the FE solver use.
#include <cstdint>
#include <string>
#include <vector>

#include "fit/inflation_data.hpp"

namespace tunica {

/// Standard deviations of the measurement noise, as fractions of each quantity's
/// full scale (the largest |value| of that quantity in the data set).
struct NoiseLevels {
  double pressure = 0;
  double axial_force = 0;
  double size = 0;  ///< the measured outer diameter or radius (λθ then follows the noisy size)
};

/// Points at every (λz, p) of `axial_stretches` × `pressures` (in that order), in
/// internal units (reported as MPa, N, mm); noise from a seeded Mersenne twister (std::mt19937_64) by Box–Muller,
/// three draws per point (pressure, size, force) whatever the levels.
/// Throws SolveError if a pressure cannot be carried (thin_tube.hpp).
InflationData synthesize_inflation_data(const MembraneMaterial& material, const Specimen& specimen,
                                        const std::vector<double>& axial_stretches,
                                        const std::vector<double>& pressures, SizeMeasure size,
                                        const NoiseLevels& noise, std::uint64_t seed);

/// The data as CSV in the documented format: `comment` lines (prefixed with "# "), the
/// `# specimen:` line, and the columns axial_stretch, pressure_<pu>, outer_diameter_<lu>
/// or radius_<lu>, axial_force_<fu> (10 significant digits) in the given units.
std::string inflation_data_csv(const InflationData& data, const std::string& comment, const std::string& pressure_unit,
                               const std::string& force_unit, const std::string& length_unit);

/// Declared keys of a synthesis plan (docs/fit.md).
const ComponentSpec& synthesis_plan_spec();

/// Reads a plan file (keys of synthesis_plan_spec plus `specimen` and `material` maps)
/// and returns the CSV text. Throws InputError naming file, line and key.
std::string synthesize_from_plan(const std::string& plan_path);

}  // namespace tunica
