#pragma once
// Reading 3-D membrane parts (`element: membrane`): the surface mesh, from a
// generator (tube, sphere, octant) or a Gmsh file, and the material frame rule.
#include <map>
#include <string>
#include <vector>

#include "io/deck_node.hpp"
#include "io/read_params.hpp"
#include "mesh/surface_mesh.hpp"
#include "model/model.hpp"

namespace tunica {

/// Gmsh files read so far (by resolved path and direction view), with the global
/// node number of each of their nodes, so that parts meshed in one file share nodes.
struct SurfaceMeshCache {
  struct Entry {
    SurfaceMesh mesh;
    std::vector<int> global;  ///< per file node
  };
  std::map<std::string, Entry> files;
  bool allow_scripts = false;  ///< mesh Gmsh scripts (.geo): ReadOptions::allow_scripts
};

/// Reads the `mesh` and `frame` of a 3-D part into `part` and the model (nodes,
/// element blocks, node sets: `<part>.all`, `<part>.<set>` for generator sets,
/// the Gmsh file's physical curve/point names for Gmsh sets).
void read_surface_part(const DeckNode& node, Part& part, Model& m, SurfaceMeshCache& cache);

/// After all parts: drops nodes no element uses (from sets too) and computes the
/// reference data of every element, turning a bad element or frame into an
/// InputError at the part's `mesh` or `frame` key.
void finish_surface_parts(const DeckNode& parts, Model& m);

/// Declarations of the `frame` and Gmsh `mesh` maps, for the deck reference.
const ComponentSpec& frame_spec();
const ComponentSpec& gmsh_mesh_spec();

}  // namespace tunica
