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

FrameDirection frame_direction(const Model&, const FrameRule& frame, const ElementBlock& block, int e) {
  FrameDirection d;
  switch (frame.type) {
    case FrameRule::Type::cylindrical:
      d.kind = FrameDirection::Kind::about_axis;
      d.axis = frame.axis;
      d.point = frame.point;
      return d;
    case FrameRule::Type::vector: d.vector = frame.vector; return d;
    case FrameRule::Type::mesh: d.vector = block.direction.at(e); return d;
    case FrameRule::Type::edge: break;
  }
  d.kind = FrameDirection::Kind::first_edge;
  return d;
}

}  // namespace tunica
