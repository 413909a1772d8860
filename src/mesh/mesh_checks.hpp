#pragma once
// Checks of a surface mesh before analysis, with messages naming the surface
// and the element (0-based, triangles numbered first, then quadrilaterals).
#include <string>

#include "mesh/surface_mesh.hpp"

namespace tunica {

/// Returns "" if surface `s` is usable, else the reason: an element with a
/// repeated node, a node index outside the mesh, a degenerate element (zero
/// area: area ≤ 1e-12 × square of its longest edge), an inverted element (its
/// normal opposite to a neighbour's across a shared edge, so the surface's
/// orientation is not consistent), or an edge shared by more than two elements.
std::string check_surface(const SurfaceMesh& mesh, const SurfaceMesh::Surface& s);

}  // namespace tunica
