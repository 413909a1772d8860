#pragma once
// Where a membrane is in compression: a point whose smaller in-plane principal Cauchy stress is
// negative. A real membrane cannot carry compression, it wrinkles (tension-field theory), which
// Tunica does not model yet; its results there are those of a membrane that carries it. The
// history quantity `compressed_fraction`, the VTU field `compressed` and the run's note show where.
#include <vector>

#include "elements/membrane_point.hpp"

namespace tunica {

/// Green–Lagrange strains at or below this everywhere: an unstrained state, nowhere compressed.
/// A state this close to the reference (a step back to zero load, converged to the residual
/// tolerance, leaves strains of 10⁻⁹ and stresses of 10⁻⁸ kPa of either sign) is no evidence of
/// wrinkling: a membrane strained by a millionth carries a millionth of its modulus.
constexpr double kUnstrained = 1e-6;

/// A point counts as compressed where σ_min < −kCompressionShare s, s the largest |principal
/// stress| of its part. Below 1 % of the part's largest stress a compression is within the
/// discretization error of the stresses of a coarse membrane mesh, not evidence of wrinkling: a
/// closed tube of staggered triangles in plain axial stretch to λz = 1.5, whose hoop stress is
/// exactly 0, has σ_min = −4.4·10⁻⁴ σ_max with 16 elements around, −1.4·10⁻³ with 12 and
/// −6.8·10⁻³ with 8; and a membrane that wrinkled under such a compression would shed stresses
/// below 1 % of those it carries. A real compression (a tube shortened, a sac turned inside out) is a
/// sizable share of the tension or all of the stress.
constexpr double kCompressionShare = 1e-2;

/// A membrane part whose largest |principal stress| is below this share of the most loaded
/// membrane part's carries no load yet: the run does not note its compression
/// (output/run_writer.cpp), whose signs are then round-off.
constexpr double kUnloadedShare = 1e-3;

/// Per point: 1 if σ_min < −kCompressionShare s, s the largest |principal stress| over `points`,
/// else 0; all 0 if no point is strained beyond kUnstrained.
std::vector<char> compressed_points(const std::vector<MembranePoint>& points);

/// How strong the compression of `points` is: the most negative σ_min and the largest σ_max
/// (0 where none is negative or positive).
struct CompressionSize {
  double compression = 0;  ///< min over the points of min(σ_min, 0)
  double tension = 0;      ///< max over the points of max(σ_max, 0)
};
CompressionSize compression_size(const std::vector<MembranePoint>& points);

/// The fraction of the points' reference volume (Σ weight; for a uniform thickness, of the
/// reference area) in compression; 0 for no points.
double compressed_fraction(const std::vector<MembranePoint>& points);

}  // namespace tunica
