#pragma once
// An enclosed volume measured about an axis (a load's `volume_axis`) that the surface's open
// ends do not fit. About the axis a through p₀ the volume is V = ½∫(x − p₀)⊥·n dA, with
// y⊥ = y − (a·y) a (theory manual (6.6)). Since div y⊥ = 2, V is the volume that the surface
// and the caps closing its open edge loops enclose, less ½∫ y⊥·n dA over each cap. A plane cap
// of area A, unit normal n and centroid c adds ½ A n·(c − p₀)⊥ to that: nothing when the cap is
// normal to the axis (n ∥ a, wherever the axis passes) or when the axis passes through its
// centroid; and y⊥·n = 0 on a plane that holds the axis (a symmetry plane through it). Any other
// open end leaves its cap's share out of V: a tube along z measured about x reports half its
// lumen.
#include <string>

#include "model/model.hpp"

namespace tunica {

/// "" when every open edge loop of part `part` has a cap whose share ½∫cap y⊥·n dA is
/// negligible for the measure `how` (at most 10⁻³ A r, A the cap's area and r the loop's radius;
/// exactly 0 for the cases above), the loop's edges in planes that hold the axis left out.
/// Otherwise why not, for the first loop that fails: its number of edges, centre and a node, the
/// share its cap would miss (in the deck's units), whether the loop lies in a plane at all, and
/// the first likely fix that fits every loop: the direction the part's normals are most nearly
/// perpendicular to (a tube's axis), the loop's normal, the line through the centroids of a
/// tube's two ends, the axis through the loop's centroid. Empty for a part that is not a 3-D surface.
std::string volume_axis_misfit(const Model& m, int part, const VolumeMeasure& how);

}  // namespace tunica
