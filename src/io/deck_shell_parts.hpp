#pragma once
// Reading axisymmetric Kirchhoff–Love shell parts (`element: axisymmetric_shell`,
// elements/axisym_shell.hpp; issue #4 item 6: the paper's shell cross-check of
// the angioplasty). The meridian mesh is the membrane's (`type: line` or `arc`,
// read by the caller); this adds the quadrature, the reference slopes of the
// nodes (mesh/meridian_tangents.hpp) and checks every element at its reference
// state (thickness within the radii of curvature, slopes along the element).
#include <vector>

#include "io/deck_node.hpp"
#include "io/read_params.hpp"
#include "model/model.hpp"

namespace tunica {

/// The largest turn of a shell meridian where two of its pieces join (radians): 0.5 deg.
constexpr double kShellJointAngle = 0.5 * 3.14159265358979323846 / 180;

/// The keys of an `axisymmetric_shell` part (declared for the deck reference).
const ComponentSpec& shell_part_spec();

/// After the part's meridian is read (part.nodes, one shell2 block): its quadrature from `p`,
/// its reference tangents, and a reference evaluation of each element. Errors name the
/// part's `mesh` (geometry) or `thickness` key.
/// `joints`: the positions in part.nodes where a piece of a list meridian begins
/// (io/deck_meridian_parts.hpp); the pieces must meet tangentially (within kShellJointAngle).
void finish_shell_part(const DeckNode& node, const Params& p, Part& part, const Model& m,
                       const std::vector<int>& joints);

}  // namespace tunica
