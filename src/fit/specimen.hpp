#pragma once
// The specimen of an inflation–extension test: its load-free geometry, how the
// axial force was measured and, optionally, one axial stretch for every point.
// Given as a `# specimen: {...}` line in the data file or by `tunica fit --specimen`.
#include <optional>
#include <string>

#include "fit/thin_tube.hpp"
#include "io/read_params.hpp"

namespace tunica {

/// A specimen, in internal units (mm, N).
struct Specimen {
  TubeGeometry geometry;                ///< R = (D − H)/2 from the outer diameter D, or R given; H
  std::optional<double> axial_stretch;  ///< λz of every point, if the data have no stretch column
  SourceLocation where;                 ///< where it was given
};

/// Declared specimen keys (for validation and docs/fit.md).
const ComponentSpec& specimen_spec();

/// Reads a specimen map (bare lengths in mm): exactly one of `outer_diameter` and
/// `radius`; R = (D − H)/2 must be positive. Throws InputError naming file, line and key.
Specimen read_specimen(const DeckNode& node);

/// The node of a `--specimen` argument: a YAML file holding the map, or the map
/// itself inline ("{radius: 0.763 mm, thickness: 0.122 mm}"). Throws InputError.
DeckNode specimen_node_from_argument(const std::string& argument);

}  // namespace tunica
