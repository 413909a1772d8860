#include "contributions/surface_references.hpp"

#include <fmt/format.h>

namespace tunica {

DirectionRule direction_rule(const Model& model, const FrameRule& frame, const ElementBlock& block, int e) {
  switch (frame.type) {
    case FrameRule::Type::cylindrical: {
      // Direction 1 circumferential about the axis: a × (X − p); tangent to any surface of revolution about it.
      const Eigen::Vector3d a = frame.axis, p = frame.point;
      return [a, p](const Eigen::Vector3d& X, const Eigen::Vector3d&) -> Eigen::Vector3d { return a.cross(X - p); };
    }
    case FrameRule::Type::vector: {
      const Eigen::Vector3d v = frame.vector;
      return [v](const Eigen::Vector3d&, const Eigen::Vector3d&) -> Eigen::Vector3d { return v; };
    }
    case FrameRule::Type::mesh: {
      const Eigen::Vector3d v = block.direction.at(e);
      return [v](const Eigen::Vector3d&, const Eigen::Vector3d&) -> Eigen::Vector3d { return v; };
    }
    case FrameRule::Type::edge: break;
  }
  // Direction 1 along the element's first edge (node 0 → node 1): any frame does for isotropic materials.
  const int* n = block.element(e);
  const Eigen::Vector3d v = model.X[n[1]] - model.X[n[0]];
  return [v](const Eigen::Vector3d&, const Eigen::Vector3d&) -> Eigen::Vector3d { return v; };
}

template <int N>
std::vector<MembraneReference<N>> block_references(const Model& model, const Part& part, const ElementBlock& block,
                                                   int first_element) {
  std::vector<MembraneReference<N>> out;
  out.reserve(block.size());
  SurfaceNodes<N> X;
  for (int e = 0; e < block.size(); ++e) {
    const int* n = block.element(e);
    for (int a = 0; a < N; ++a) X.col(a) = model.X[n[a]];
    try {
      out.push_back(membrane_reference<N>(X, part.thickness, direction_rule(model, part.frame, block, e)));
    } catch (const BadElement& err) {
      // Named as in the mesh file where the elements come from one, else by 0-based index.
      const bool from_file = static_cast<int>(block.tags.size()) == block.size();
      std::string nodes;
      for (int a = 0; a < N; ++a) {
        const long tag = n[a] < static_cast<int>(model.node_tags.size()) ? model.node_tags[n[a]] : 0;
        nodes += fmt::format("{}{}", a ? ", " : "", from_file && tag > 0 ? tag : n[a]);
      }
      if (from_file)
        throw BadElement(fmt::format("{}: element {} ({}, nodes {}): {}", block.file, block.tags[e],
                                     N == 3 ? "a triangle" : "a quadrilateral", nodes, err.what()));
      throw BadElement(fmt::format("element {} ({}, nodes {}): {}", first_element + e, N == 3 ? "triangle" : "quadrilateral",
                                   nodes, err.what()));
    }
  }
  return out;
}

template std::vector<MembraneReference<3>> block_references<3>(const Model&, const Part&, const ElementBlock&, int);
template std::vector<MembraneReference<4>> block_references<4>(const Model&, const Part&, const ElementBlock&, int);

}  // namespace tunica
