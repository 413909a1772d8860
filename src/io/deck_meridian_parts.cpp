#include "io/deck_meridian_parts.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <string>

#include "core/limits.hpp"
#include "core/suggest.hpp"
#include "io/meridian_checks.hpp"
#include "io/read_params.hpp"
#include "io/unitless_values.hpp"
#include "mesh/meridian.hpp"

namespace tunica {

namespace {

const char* const kPieceExpected =
    "expected a map with `type: line` or `type: arc` and its keys, or a list of such maps joined end to start "
    "(e.g. a capsule: an arc, a line and an arc)";

/// One generator map: its points, checked as a meridian of its own.
Meridian read_piece(const DeckNode& mesh, Model& m, long& elements) {
  if (!mesh.is_map()) mesh.fail(kPieceExpected);
  const std::string type = mesh.required("type").as_string();
  auto gen = meridian_types().find(type);
  if (gen == meridian_types().end())
    mesh["type"].fail("unknown mesh type '" + type + "' for an axisymmetric part (known: line, arc)" +
                      did_you_mean(type, {"line", "arc"}));
  const Params mp = read_params(mesh, gen->second.spec, m.units, {"type"});
  warn_unitless_values(mesh, gen->second.spec, m);
  elements += mp.integer("elements");
  if (m.num_nodes() + elements + 1 > kMaxNodes)
    mp.fail("elements", fmt::format("the model would have more than {} nodes", kMaxNodes));
  Meridian points = gen->second.make(mp);
  check_meridian(mesh, gen->second, mp, points, m.units);
  const std::string unit = m.units.display_unit(Dimension::length);
  if (type == "line" && points.front() == points.back())
    mesh["to"].fail(fmt::format("`to` is `from`, [{:g}, {:g}] {}: the line has no length; give its other end (a tube "
                                "of length L at radius R: `from: [R, 0 mm], to: [R, L]`)",
                                points.front()(0), points.front()(1), unit));
  if (type == "line" && points.front()(0) == 0 && points.back()(0) == 0)
    mesh["from"].fail("the line lies on the axis (r = 0 at both ends), where a surface of revolution has no area: "
                      "points are [r, z], the radius first (a tube of radius R along z: `from: [R, 0 mm], to: [R, L]`)");
  if (type == "arc" && mp.number("start_angle") == mp.number("end_angle"))
    mesh["end_angle"].fail("the arc spans 0 deg (`end_angle` is `start_angle`): give the angle where it ends (a "
                           "sphere from pole to pole: `start_angle: -90 deg, end_angle: 90 deg`)");
  return points;
}

/// The key of a piece that places its first point (`from` of a line, `start_angle` of an arc).
DeckNode start_key(const DeckNode& piece) {
  for (const char* key : {"from", "start_angle", "center"})
    if (piece.has(key)) return piece[key];
  return piece;
}

}  // namespace

std::vector<int> read_meridian_part(const DeckNode& node, Part& part, Model& m) {
  const DeckNode mesh = node.required("mesh");
  std::vector<DeckNode> pieces;
  if (mesh.is_sequence()) {
    pieces = mesh.items();
    if (pieces.empty()) mesh.fail(std::string("an empty list: ") + kPieceExpected);
  } else if (mesh.is_map()) {
    pieces = {mesh};
  } else {
    mesh.fail(kPieceExpected);
  }
  if (node.has("frame")) node["frame"].fail("an axisymmetric part's frame is fixed (1 = hoop, 2 = meridian)");
  const std::string unit = m.units.display_unit(Dimension::length);
  Meridian points;
  std::vector<int> joints;
  long elements = 0;
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const Meridian piece = read_piece(pieces[k], m, elements);
    if (k > 0) {
      const Eigen::Vector2d end = points.back();
      const double h = std::min((points[points.size() - 1] - points[points.size() - 2]).norm(),
                                (piece[1] - piece[0]).norm());
      const double gap = (piece.front() - end).norm();
      if (!(gap <= kMeridianJoinFraction * h)) {
        const bool reversed = (piece.back() - end).norm() <= kMeridianJoinFraction * h;
        start_key(pieces[k]).fail(fmt::format(
            "this piece starts at [{:g}, {:g}] {} but the piece before it (mesh[{}]) ends at [{:g}, {:g}] {}, {:.4g} {} "
            "apart: the pieces of a meridian join end to start, in node order{}",
            piece.front()(0), piece.front()(1), unit, k - 1, end(0), end(1), unit, gap, unit,
            reversed ? std::string("; this piece ends there, so it runs the other way: swap `from` and `to` (or "
                                   "`start_angle` and `end_angle`)")
                     : fmt::format(" (start it at [{:g}, {:g}] {})", end(0), end(1), unit)));
      }
      // The shared node keeps the earlier piece's end, unless the later one puts it on the axis.
      if (piece.front()(0) == 0) points.back() = piece.front();
      joints.push_back(static_cast<int>(points.size()) - 1);
      points.insert(points.end(), piece.begin() + 1, piece.end());
    } else {
      points = piece;
    }
  }
  const int first = m.num_nodes();
  for (std::size_t i = 0; i < points.size(); ++i) {
    m.X.push_back(Eigen::Vector3d(points[i](0), points[i](1), 0.0));
    part.nodes.push_back(first + static_cast<int>(i));
  }
  ElementBlock block;
  block.kind = ElementKind::axisym2;
  for (std::size_t e = 0; e + 1 < points.size(); ++e) {
    const double L = (points[e + 1] - points[e]).norm();
    if (!(L > 0)) mesh.fail(fmt::format("element {} has zero length", e));
    if (points[e](0) == 0 && points[e + 1](0) == 0) mesh.fail(fmt::format("element {} lies on the axis (r = 0)", e));
    block.nodes.push_back(first + static_cast<int>(e));
    block.nodes.push_back(first + static_cast<int>(e) + 1);
  }
  part.blocks.push_back(std::move(block));
  const std::string origin = fmt::format("part '{}' (line {}) as one of its generated sets", part.name, node.where().line);
  m.node_sets.push_back({part.name + ".start", {part.nodes.front()}, origin});
  m.node_sets.push_back({part.name + ".end", {part.nodes.back()}, origin});
  m.node_sets.push_back({part.name + ".all", part.nodes, origin});
  return joints;
}

}  // namespace tunica
