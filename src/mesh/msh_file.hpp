#pragma once
// The contents of a Gmsh .msh file (versions 2.2 and 4.1, ASCII and binary) as
// read, before any interpretation: nodes and elements with the tags written in
// the file (and, in ASCII files, the line each stands on), physical names,
// entities with their physical groups (4.1), and element-data views.
// Parsed by msh_parser.hpp; turned into a SurfaceMesh by msh_surface.hpp.
#include <Eigen/Dense>
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace tunica {

/// Gmsh element type: its dimension, node count and name ("3-node triangle").
struct MshElementType {
  int dim = -1;
  int nodes = 0;
  const char* name = "unknown";
};
/// The element type `type` of the Gmsh numbering; dim = -1 if Tunica does not know it.
MshElementType msh_element_type(int type);

struct MshFile {
  double version = 0;  ///< 2.2 or 4.1
  bool binary = false;

  struct Node {
    long tag = 0;
    Eigen::Vector3d x = Eigen::Vector3d::Zero();
    int entity_dim = -1, entity = 0;  ///< entity the node is classified on (4.1), -1 unknown
    int line = 0;                     ///< line in the file (ASCII), 0 if unknown
  };
  std::vector<Node> nodes;

  struct Element {
    long tag = 0;
    int type = 0;
    int entity_dim = 0, entity = 0;  ///< elementary entity
    int physical = 0;                ///< 2.2: the element's physical tag (0: none); 4.1: 0
    int line = 0;
    std::uint32_t first = 0;         ///< first of its node tags in element_nodes
  };
  std::vector<Element> elements;
  std::vector<long> element_nodes;  ///< node tags, msh_element_type(type).nodes per element

  /// (dim, tag) of a physical group -> its name.
  std::map<std::pair<int, int>, std::string> physical_names;
  /// (dim, entity tag) -> physical tags of the entity (4.1 $Entities).
  std::map<std::pair<int, int>, std::vector<int>> entity_physicals;

  struct ElementData {
    std::string name;
    int components = 0;
    int line = 0;
    std::vector<long> tags;
    std::vector<double> values;  ///< components per tag
  };
  std::vector<ElementData> element_data;
};

}  // namespace tunica
