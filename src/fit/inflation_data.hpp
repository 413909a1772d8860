#pragma once
// Measured data of inflation–extension tests (docs/fit.md, "Data format"): a CSV
// file with a header naming each column's quantity and unit,
//     pressure_<unit>, outer_diameter_<unit> | radius_<unit>, axial_force_<unit>,
//     axial_stretch | lambda_z | E_z   (the last optional if the specimen gives axial_stretch)
// ("pressure [mmHg]" and "pressure (mmHg)" are accepted too; other columns are
// ignored), `#` comment lines, and the specimen as a comment line
//     # specimen: {outer_diameter: 1.648 mm, thickness: 0.122 mm, ends: open}
// Several axial-stretch levels may follow each other in one file.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "fit/specimen.hpp"

namespace tunica {

/// One measured point, in internal units (mm, N, N/mm²).
struct InflationPoint {
  double pressure = 0;       ///< p
  double axial_force = 0;    ///< F, as the transducer reads it (see TubeEnds)
  double lambda_z = 1;       ///< axial stretch λz
  double mid_radius = 0;     ///< current mid-surface radius r (from D: r + h/2 = D/2)
  double lambda_theta = 1;   ///< λθ = r/R
  double measured_size = 0;  ///< the measured radius or outer diameter as given
  int line = 0;              ///< line in the data file
};

/// Whether the data give the mid-surface radius or the outer diameter.
enum class SizeMeasure { mid_radius, outer_diameter };

/// A data set ready to fit.
struct InflationData {
  std::string file;
  Specimen specimen;
  SizeMeasure size = SizeMeasure::outer_diameter;
  /// Units of the columns as written in the header (for reports and plots).
  std::string pressure_unit, force_unit, length_unit;
  int header_line = 0;
  std::vector<InflationPoint> points;
};

/// Options of reading.
struct InflationDataOptions {
  /// Replaces the file's `# specimen:` line when given.
  std::optional<DeckNode> specimen;
  /// Keep only rows where column == value (e.g. {"step", 2} for a Tunica history.csv).
  std::vector<std::pair<std::string, double>> select;
  /// Within one axial-stretch level the size must be monotone along the rows (one loading
  /// or unloading branch); a turn is an error unless this is set.
  bool allow_non_monotone = false;
};

/// Reads and checks a data file. Throws InputError naming file, line and column for:
/// missing or duplicate columns, unknown units, malformed or non-finite cells,
/// non-positive stretches or sizes, a diameter too small for the wall, a hoop
/// stretch that turns back within an axial-stretch level, no specimen, no rows.
InflationData read_inflation_data(const std::string& path, const InflationDataOptions& options = {});
/// Same, from text (`file` names it in messages).
InflationData read_inflation_data_text(const std::string& text, const std::string& file,
                                       const InflationDataOptions& options = {});

/// "COLUMN=VALUE" of `--select` split into its column and number; throws InputError.
std::pair<std::string, double> parse_row_selection(const std::string& text);

}  // namespace tunica
