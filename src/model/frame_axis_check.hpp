#pragma once
// A cylindrical material frame (FrameRule::cylindrical) that does not fit its surface. Direction 1
// is the circumferential direction a × (x − p) projected on the tangent plane: on a surface of
// revolution about the frame's axis it already lies in the tangent plane; an axis or a point
// given wrongly (a vessel along x with the default axis z) gives fibre directions that are valid
// but not meant, with no error.
#include <string>
#include <vector>

#include "model/model.hpp"

namespace tunica {

/// A part whose frame does not fit its surface, and why (the message names the part).
struct FrameMisfit {
  int part = -1;
  std::string message;
};

/// One message per 3-D part of an anisotropic material with a cylindrical frame whose
/// circumferential direction a × (x − p) stands more than 30° out of the element's tangent plane,
/// or whose axis lies within 30° of the element's normal, over more than a fifth of the part's
/// reference area: the fraction, and the direction to which the part's normals are most nearly
/// perpendicular (the axis of a tube), as the likely `axis`. Empty when every such frame fits.
std::vector<FrameMisfit> frame_axis_warnings(const Model& m);

}  // namespace tunica
