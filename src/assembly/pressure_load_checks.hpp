#pragma once
// Warnings about pressure loads that read as valid but are likely not what the user meant,
// found at the reference state (`tunica check` and `tunica run` print them):
//  - the load pushes its surface inward: the volume on the side the pressure pushes away from,
//    theory manual (6.6)–(6.7), is negative, so the surface's normals point into the volume it
//    encloses, or `flip: true` turned the pressure against normals that point out of it (a
//    pressure from outside is meant that way; one inside a vessel is not);
//  - a 3-D load whose volume is reported (history `volume`) or controlled (`volume_control`),
//    measured about a point (no `volume_axis`), on a surface with open edges that no
//    plane through p₀ closes: the caps that would close it are missing from the enclosed volume
//    (an open tube without `volume_axis` reports about ⅔ of its lumen);
//  - a loaded 3-D surface with a chain of open edges that no boundary condition holds (a hole).
#include <string>
#include <vector>

#include "assembly/system.hpp"

namespace tunica {

/// A chain of open edges (used by one element) of a 3-D surface part of which no node is held by
/// a boundary condition: a hole or a gap in a wall, or a free edge.
struct UnheldEdges {
  int edges = 0;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  ///< mean of its edges' midpoints
  int node = -1;                                     ///< one of its nodes
};
std::vector<UnheldEdges> unheld_open_edges(const Model& m, int part);

/// Why load's pressure pushes its surface inward (its reference volume is negative): its `flip`, or
/// normals that point into the volume.
std::string inward_load_cause(const PressureLoad& load);
/// The fix for a load that pushes its surface inward: remove `flip: true`, or set it (or reverse the
/// mesh's orientation).
std::string inward_load_fix(const Model& m, const PressureLoad& load);

/// One message per suspicious load, each at the load's place in the deck (file:line:column: key),
/// naming the load, what was measured (in the deck's length unit) and the key that fixes it.
std::vector<std::string> pressure_load_warnings(const System& system);

/// The volume of the caps that would close the open edges of a surface, measured as the load
/// measures it (about the point p₀), each cap taken as the plane region its edges bound, from the
/// point of its plane nearest p₀ (exact for planar caps). Open edges that lie with their
/// neighbours in one plane through p₀ (symmetry planes, an end at p₀) need no cap and are
/// left out. `open_count` receives the number of open edges counted.
double missing_cap_volume(const Model& m, int part, const Eigen::Vector3d& p0, int* open_count = nullptr);

/// Whether load `l`'s volume is an enclosed volume whose sign is the surface's orientation, so that
/// a converged state where it has the other sign than at the state before is the surface passed
/// through itself (or through its mirror image at a symmetry plane): turned inside out, a state
/// the membrane's strains cannot tell from the right one (C = FᵀF and the normal do not change
/// under x → −x about p₀), while its volume (theory manual (6.6)–(6.7)) has the other sign and the
/// pressure pushes it inward, so that it has equilibria of its own (theory manual §7). True for
///  - a closed 3-D surface;
///  - a 3-D surface measured about a point whose open edges lie in planes through p₀
///    (missing_cap_volume finds no cap missing), unless an open edge is clamped (every
///    translational DOF of both its nodes held): a rim clamped in a plane through p₀ is not a
///    mirror, and a membrane may snap through that plane (its volume changes sign legitimately);
///  - a 3-D surface measured about an axis that fits its open ends (volume_axis_misfit is
///    empty): the sign changes only where the wall passes through the axis;
///  - an axisymmetric membrane or shell (V = π∫r² dz) whose meridian ends lie on the axis or are
///    held in fewer than both of r and z (the same exception for a clamped end).
/// False for an open sheet measured about a point (its volume about a point can change sign
/// legitimately) and for solid parts.
bool volume_sign_is_orientation(const Model& m, int l);

}  // namespace tunica
