#pragma once
// Generated surface meshes for examples and tests. Every generator makes one
// surface named "surface" with outward normals (node order counterclockwise
// seen from outside) and the node sets listed with it.
#include <map>
#include <string>

#include "params/param_spec.hpp"
#include "params/params.hpp"
#include "mesh/surface_mesh.hpp"

namespace tunica {

/// Circular tube (cylinder) of the given radius about the z axis, from z = 0 to
/// z = length, over the angle sector [0, sector] (2π: the closed tube, nodes
/// shared across the seam), `around` elements around and `along` along, quads
/// or triangles (each quad split along its diagonal, alternating direction).
/// Node sets: "bottom" (z = 0), "top" (z = length), and for an open sector
/// "start" (θ = 0) and "end" (θ = sector); also "y0" / "x0", the columns of nodes at θ = 0, 180°
/// / 90°, 270° (on the planes y = 0 / x = 0), taken by column index: a column within a thousandth
/// of an element's angle of such an angle is in the set (`sector: 1.5708` has `x0`). A tube
/// without an `x0` says why in SurfaceMesh::absent_sets.
SurfaceMesh tube_mesh(double radius, double length, double sector, int around, int along, bool triangles);

/// Closed circular tube of triangles whose node rings alternate by half an element
/// around (θ_i = 2π (i + ½ (j mod 2)) / around on ring j): no two neighbouring
/// triangles are coplanar, so the unstressed faceted tube has no first-order
/// inextensional (zero-stiffness) modes, which the union-jack split of coplanar quad
/// halves has: a clamped tube can then be loaded from its stress-free state.
/// 2 · around · along triangles; node sets "bottom", "top", and "x0" / "y0" (nodes on
/// the planes x = 0 / y = 0, by index: "x0" on the even rings when around is a multiple of 4,
/// on the odd ones when it is 2 more).
SurfaceMesh staggered_tube_mesh(double radius, double length, int around, int along);

/// Whole sphere of the given radius about the origin: the six faces of a cube
/// projected onto the sphere (quads, n × n per face, equal angles), or each
/// quad split into two triangles. Node sets: "north" and "south" (the nodes at
/// the poles ±z), "equator" (z = 0 for even n).
SurfaceMesh sphere_mesh(double radius, int n, bool triangles);

/// The octant x, y, z ≥ 0 of a sphere of the given radius: three quad patches
/// from the cube projection (n × n each, equal angles) or split triangles.
/// Node sets: "x0", "y0", "z0" (nodes on the symmetry planes), "pole" (the node on +z).
SurfaceMesh octant_mesh(double radius, int n, bool triangles);

/// A surface generator a deck can name (`mesh: {type: tube, ...}`).
struct SurfaceGeneratorType {
  ComponentSpec spec;
  SurfaceMesh (*make)(const Params&);
};

/// All surface generators by deck name ("tube", "sphere", "octant").
const std::map<std::string, SurfaceGeneratorType>& surface_generator_types();

}  // namespace tunica
