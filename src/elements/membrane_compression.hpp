#pragma once
// Where a membrane is in compression: a point whose smaller in-plane principal Cauchy stress is
// negative. A real membrane cannot carry compression, it wrinkles (tension-field theory), which
// Tunica does not model yet; its results there are those of a membrane that carries it. The
// history quantity `compressed_fraction`, the VTU field `compressed` and the run's note show where.
#include <vector>

#include "elements/membrane_point.hpp"

namespace tunica {

/// Green–Lagrange strains at or below this everywhere: an unstrained state, nowhere compressed.
constexpr double kUnstrained = 1e-10;

/// Per point: 1 if σ_min < −10⁻⁶ s, s the largest |principal stress| over `points` (so that
/// round-off is not compression), else 0; all 0 if no point is strained beyond kUnstrained.
std::vector<char> compressed_points(const std::vector<MembranePoint>& points);

/// The fraction of the points' reference volume (Σ weight; for a uniform thickness, of the
/// reference area) in compression; 0 for no points.
double compressed_fraction(const std::vector<MembranePoint>& points);

}  // namespace tunica
