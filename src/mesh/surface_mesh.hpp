#pragma once
// Surface meshes for 3-D membrane parts: node positions, named surfaces made
// of 3-node or 6-node triangles and 4-node quadrilaterals (node order counterclockwise
// about the surface normal), and named node sets (symmetry planes, edges,
// physical curves and points). Built by the generators (tube, sphere, sphere
// octant) or read from Gmsh files (gmsh_reader.hpp).
#include <Eigen/Dense>
#include <array>
#include <map>
#include <string>
#include <vector>

namespace tunica {

struct SurfaceMesh {
  struct Surface {
    std::string name;
    std::vector<std::array<int, 3>> triangles;
    std::vector<std::array<int, 4>> quads;
    /// Quadratic triangles: per triangle, its mid-edge nodes on edges 0–1, 1–2, 2–0 (the triangle's
    /// corners are `triangles`); empty for linear triangles. A surface's triangles are all of one order.
    std::vector<std::array<int, 3>> triangle_midsides;
    /// Optional per-element direction-1 vectors (empty, or one per triangle / quad).
    std::vector<Eigen::Vector3d> triangle_direction, quad_direction;
    /// Element tags as written in the mesh file (empty for generated meshes), one per triangle / quad.
    std::vector<long> triangle_tags, quad_tags;
    /// The line each element stands on in an ASCII mesh file (0: unknown), one per triangle / quad.
    std::vector<int> triangle_lines, quad_lines;
  };
  std::vector<Eigen::Vector3d> nodes;
  std::vector<Surface> surfaces;
  std::map<std::string, std::vector<int>> node_sets;  ///< sorted, unique node indices
  /// Node sets the generator makes for other parameters but not for these, each with why (a tube
  /// whose sector ends short of 90° has no `x0`): for the message of a deck that names one.
  std::map<std::string, std::string> absent_sets;
  /// Per node set of a mesh file, the group that defines it ("physical curve 3"); for messages.
  std::map<std::string, std::string> node_set_origins;
  /// Node tags as written in the mesh file (empty for generated meshes), one per node.
  std::vector<long> node_tags;
};

}  // namespace tunica
