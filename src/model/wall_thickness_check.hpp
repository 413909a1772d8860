#pragma once
// A membrane part whose reference thickness does not fit its surface. The membrane model holds
// for a wall thin against the surface's radii of curvature (its error is of order H/2R, theory
// manual §1); a thickness larger than the whole part is no wall at all, and most often a mesh
// written in another length unit than the deck's (a mesh in metres read as millimetres).
#include <string>
#include <vector>

#include "model/model.hpp"

namespace tunica {

struct ThicknessMisfit {
  int part = -1;
  bool impossible = false;  ///< the thickness is at least the part's extent: an error, not a warning
  std::string message;
};

/// One entry per membrane part (3-D or axisymmetric; not solids or shells) whose thickness H is
///  - at least the diagonal of the part's bounding box (impossible: the mesh's length unit is
///    likely another than the deck's), or
///  - more than the part's typical radius of curvature, 1/(2 · median |H_e|) over its elements (a
///    tube's radius, half a sphere's, from the mean curvature H_e of model/surface_curvature.hpp and
///    model/meridian_curvature.hpp): a wall that thick is no membrane. The reference is measured: a
///    balloon folded or collapsed at rest may be thick against its reference radius and thin where it
///    carries the load, so a milder H/R is not flagged.
/// The message names the part, the thickness and the length measured, in the deck's length unit.
std::vector<ThicknessMisfit> wall_thickness_misfits(const Model& m);

}  // namespace tunica
