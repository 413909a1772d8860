#pragma once
// A symmetry boundary whose node set's name was likely swapped with another's: it holds one
// translational DOF of nodes that all lie on a coordinate plane normal to another axis. A
// symmetry plane x = c holds x of its nodes (user guide §3.1); a set that lies on y = 0 but holds
// x lets its nodes slide along the wrong plane, which reads as valid and gives results for another
// structure (a quarter tube whose symmetry edges slide along each other's planes carries any
// pressure). Gmsh's `Extrude` numbers a quarter tube's edges in an order that makes the swap easy.
#include <string>
#include <vector>

#include "model/model.hpp"

namespace tunica {

/// A boundary condition that likely holds the wrong DOF for its node set.
struct SymmetryMisfit {
  int boundary = -1;
  std::string message;  ///< names the node set, the plane its nodes lie on and the DOF a symmetry plane there holds
};

/// One per boundary of a 3-D model that holds exactly one translational DOF d of a node set of at
/// least 3 nodes that all lie on one coordinate plane k = c (k ≠ d, to 10⁻⁶ of the model's size)
/// that the surface crosses there (the mean |n_k| of the surface's unit normals at the nodes below
/// ½; a plane tangent to the surface is no symmetry plane of it), when no plane d = c through
/// all the nodes is such a plane too. Where the nodes lie on no 3-D surface (no normals), the
/// nodes must span the plane (not lie on one line), so that the plane is the only one they lie on.
std::vector<SymmetryMisfit> symmetry_name_warnings(const Model& m);

}  // namespace tunica
