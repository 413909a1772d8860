#pragma once
// The zero-pressure geometry an inverse step finds (theory manual §13), as a file a deck of its
// own can start from: at the end of the step, the reference positions X = x̂ + u of every node.
//   3-D models: a Gmsh mesh (format 2.2, ASCII) with the model's nodes at X, each part's elements
//     (3-node triangles, 4-node quadrilaterals, 6-node triangles) as the physical surface named
//     after the part, and each node set (but the `<part>.all` sets every part has) as a physical point group of the same name (a deck reads
//     them as node sets of the part that names the file: `mesh: {file: ..., surface: <part>}`);
//   axisymmetric models: a CSV table node, R, Z (mm) of the meridian nodes (meridians are
//     generated, not read: for plots and for a deck's own `line`/`arc` fit).
#include <Eigen/Core>
#include <string>

#include "model/model.hpp"

namespace tunica {

/// The file name of step `step`'s zero-pressure geometry: `reference_<name>.msh` (3-D) or `.csv`,
/// the step's name with characters other than letters, digits, '-' and '_' replaced by '_'.
std::string reference_mesh_name(const Model& m, int step);

/// The text of that file for the displacement u (all DOFs) of the inverse step.
std::string reference_mesh_text(const Model& m, const Eigen::VectorXd& u);

}  // namespace tunica
