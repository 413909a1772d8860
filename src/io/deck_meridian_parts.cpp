#include "io/deck_meridian_parts.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <limits>
#include <string>

#include "core/bounded_file.hpp"
#include "core/errors.hpp"
#include "core/limits.hpp"
#include "core/printable.hpp"
#include "core/suggest.hpp"
#include "io/meridian_checks.hpp"
#include "io/read_params.hpp"
#include "io/unitless_values.hpp"
#include "mesh/meridian.hpp"
#include "mesh/meridian_crossing.hpp"
#include "mesh/meridian_csv.hpp"

namespace tunica {

namespace {

const char* const kPieceExpected =
    "expected a map with `type: line`, `type: arc` or `type: points` and its keys, or a list of such maps joined "
    "end to start (e.g. a capsule: an arc, a line and an arc)";

/// `{type: points, file: F, nodes: [first, last]}`: the nodes of a meridian CSV file (a
/// `reference_<step>.csv`), read relative to the deck's folder.
Meridian read_points_file(const DeckNode& mesh, Model& m, long& elements) {
  namespace fs = std::filesystem;
  const std::string written = mesh["file"].as_string();
  fs::path path(written);
  if (path.is_relative()) path = fs::path(m.deck_file).parent_path() / path;
  long first = 0, last = 0;
  if (mesh.has("nodes")) {
    const DeckNode range = mesh["nodes"];
    if (!range.is_sequence() || range.items().size() != 2)
      range.fail("expected `[first, last]`, the node numbers of the file's first column (1 first)");
    first = range.items()[0].as_integer();
    last = range.items()[1].as_integer();
    if (first < 1 || last <= first)
      range.fail(fmt::format("expected 1 ≤ first < last, got [{}, {}]", first, last));
  }
  std::error_code ec;
  if (!fs::exists(path, ec))
    mesh["file"].fail(fmt::format("no such file: {}{}", printable(path.lexically_normal().string(), 200),
                                  fs::path(written).is_relative() ? " (read relative to the deck's folder)" : ""));
  Meridian points;
  try {
    points = parse_meridian_csv(read_file_bounded(path.string(), kMaxMeridianCsvBytes, "meridian file"),
                                path.string(), m.units, first, last);
  } catch (const InputError& e) {
    // The file's own line, and where the deck names it.
    throw InputError(e.where(), e.reason() + fmt::format(" (the meridian of {}:{}, key '{}')", m.deck_file,
                                                         mesh["file"].where().line, mesh["file"].path()));
  }
  if (m.num_nodes() + elements + static_cast<long>(points.size()) > kMaxNodes)
    mesh["file"].fail(fmt::format("the model would have more than {} nodes", kMaxNodes));
  for (std::size_t k = 1; k < points.size(); ++k)
    if (points[k] == points[k - 1] || (points[k](0) == 0 && points[k - 1](0) == 0))
      mesh["file"].fail(fmt::format("nodes {} and {} of the file {}: an element there has no {}",
                                    k + (first > 0 ? first - 1 : 0), k + 1 + (first > 0 ? first - 1 : 0),
                                    points[k] == points[k - 1] ? "coincide" : "both lie on the axis (R = 0)",
                                    points[k] == points[k - 1] ? "length" : "area"));
  elements += static_cast<long>(points.size()) - 1;
  return points;
}

/// `{type: points, points: [[r, z], ...]}`: the meridian's nodes as written, each pair of
/// consecutive points one element.
Meridian read_points_piece(const DeckNode& mesh, Model& m, long& elements) {
  mesh.expect_map_with_keys({"type", "points", "file", "nodes"});
  if (mesh.has("file") && mesh.has("points"))
    mesh["file"].fail("give the nodes as `points` or as a `file`, not both");
  if (mesh.has("nodes") && !mesh.has("file"))
    mesh["nodes"].fail("`nodes: [first, last]` picks the rows of a `file`; with `points`, list just the points meant");
  if (mesh.has("file")) return read_points_file(mesh, m, elements);
  const DeckNode list =
      mesh.required("points", ": add the meridian's nodes in order, e.g. `points: [[1 mm, 0 mm], [1.2 mm, 1 mm], "
                              "[1 mm, 2 mm]]`");
  if (!list.is_sequence() || list.items().size() < 2)
    list.fail("expected a list of at least 2 points [r, z], the meridian's nodes in order (each two consecutive "
              "points are one element)");
  const std::vector<DeckNode> items = list.items();
  if (m.num_nodes() + elements + static_cast<long>(items.size()) > kMaxNodes)
    list.fail(fmt::format("the model would have more than {} nodes", kMaxNodes));
  const std::string unit = m.units.display_unit(Dimension::length);
  Meridian points;
  for (std::size_t k = 0; k < items.size(); ++k) {
    const DeckNode& item = items[k];
    if (!item.is_sequence() || item.items().size() != 2) item.fail("expected a point [r, z]");
    const Eigen::Vector2d x(read_quantity(item.items()[0], Dimension::length, m.units),
                            read_quantity(item.items()[1], Dimension::length, m.units));
    if (x(0) < 0)
      item.items()[0].fail(fmt::format("r = {:g} {} is negative: a meridian stays at r ≥ 0 (points are [r, z], the "
                                       "radius first)",
                                       x(0), unit));
    if (k > 0 && x == points.back())
      item.fail(fmt::format("point {} is point {} again: consecutive points must differ (each two are one element)",
                            k, k - 1));
    if (k > 0 && x(0) == 0 && points.back()(0) == 0)
      item.fail(fmt::format("points {} and {} both lie on the axis (r = 0): an element there has no area", k - 1, k));
    points.push_back(x);
  }
  elements += static_cast<long>(points.size()) - 1;
  return points;
}

/// One generator map: its points, checked as a meridian of its own.
Meridian read_piece(const DeckNode& mesh, Model& m, long& elements) {
  if (!mesh.is_map()) mesh.fail(kPieceExpected);
  const std::string type = mesh.required("type").as_string();
  if (type == "points") return read_points_piece(mesh, m, elements);
  auto gen = meridian_types().find(type);
  if (gen == meridian_types().end())
    mesh["type"].fail("unknown mesh type '" + type + "' for an axisymmetric part (known: line, arc, points)" +
                      did_you_mean(type, {"line", "arc", "points"}) +
                      (type == "tube" || type == "sphere" || type == "octant" || type == "gmsh"
                           ? "; `" + type + "` meshes a 3-D surface: for a 3-D part write `element: membrane`, "
                             "or describe the meridian with `line`, `arc` or `points`"
                           : ""));
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

/// The key of a piece that places its first point (`from` of a line, `start_angle` of an arc, the
/// first of `points`).
DeckNode start_key(const DeckNode& piece) {
  for (const char* key : {"from", "start_angle", "center"})
    if (piece.has(key)) return piece[key];
  if (piece.has("points") && piece["points"].is_sequence() && !piece["points"].items().empty())
    return piece["points"].items().front();
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
  Meridian previous;  // the piece before, as written
  long elements = 0;
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const Meridian piece = read_piece(pieces[k], m, elements);
    if (k > 0) {
      const Eigen::Vector2d end = points.back();
      const double h = std::min((points[points.size() - 1] - points[points.size() - 2]).norm(),
                                (piece[1] - piece[0]).norm());
      const double gap = (piece.front() - end).norm();
      if (!(gap <= kMeridianJoinFraction * h)) {
        const auto near = [&](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
          return (a - b).norm() <= kMeridianJoinFraction * h;
        };
        const std::string swap = "swap `from` and `to` (or `start_angle` and `end_angle`, or reverse its `points`)";
        std::string advice = fmt::format(" (start it at [{:g}, {:g}] {})", end(0), end(1), unit);
        if (near(piece.back(), end))
          advice = "; this piece ends there, so it runs the other way: " + swap;
        else if (k == 1 && near(piece.front(), previous.front()))
          advice = fmt::format("; it starts where mesh[0] starts, so mesh[0] runs the other way: in mesh[0], {}", swap);
        else if (const std::size_t later = [&] {
                   for (std::size_t j = k + 1; j < pieces.size(); ++j) {
                     long count = 0;
                     const std::size_t warned = m.warnings.size();  // read again later: warned then
                     try {
                       const bool starts_here = near(read_piece(pieces[j], m, count).front(), end);
                       m.warnings.resize(warned);
                       if (starts_here) return j;
                     } catch (const InputError&) {
                       m.warnings.resize(warned);
                     }
                   }
                   return std::size_t{0};
                 }();
                 later > 0)
          advice = fmt::format("; mesh[{}] starts there: list the pieces in the meridian's order, mesh[{}] before this "
                               "one",
                               later, later);
        else if (near(piece.back(), previous.front()))
          advice = fmt::format(
              "; it ends where mesh[{}] starts, so the list runs from the meridian's far end: list the pieces in "
              "the meridian's order, this one before mesh[{}] (and if each piece also runs the other way, keep the "
              "list and in every piece {})",
              k - 1, k - 1, swap);
        start_key(pieces[k]).fail(fmt::format(
            "this piece starts at [{:g}, {:g}] {} but the piece before it (mesh[{}]) ends at [{:g}, {:g}] {}, {:.4g} {} "
            "apart: the pieces of a meridian join end to start, in node order{}",
            piece.front()(0), piece.front()(1), unit, k - 1, end(0), end(1), unit, gap, unit, advice));
      }
      // The shared node keeps the earlier piece's end, unless the later one puts it on the axis.
      if (piece.front()(0) == 0) points.back() = piece.front();
      joints.push_back(static_cast<int>(points.size()) - 1);
      points.insert(points.end(), piece.begin() + 1, piece.end());
    } else {
      points = piece;
    }
    previous = piece;
  }
  if (auto c = meridian_crossing(points)) {
    for (int k = 0; k < 2; ++k)  // round-off of a generated angle (cos 180° = −1.2e-16) printed as 0
      if (std::abs(c->at(k)) <= 1e-9 * (points[1] - points[0]).norm()) c->at(k) = 0;
    // At the piece that holds the later element.
    std::size_t piece = 0;
    while (piece < joints.size() && joints[piece] <= c->second) ++piece;
    const bool ring = c->first == 0 && c->second + 2 == static_cast<int>(points.size()) &&
                      (points.front() - points.back()).norm() <= 1e-9 * (points[1] - points[0]).norm();
    pieces[piece].fail(fmt::format(
        "{}: a meridian runs from one end to the other without crossing or running back over itself{}",
        ring ? fmt::format("the meridian's last node lies on its first, at [{:g}, {:g}] {}, where the ring is not "
                           "joined",
                           c->at(0), c->at(1), unit)
        : c->second == c->first + 1
            ? fmt::format("the meridian turns back on itself at node {}, [{:g}, {:g}] {}: element {} runs back along "
                          "element {}",
                          c->second, c->at(0), c->at(1), unit, c->second, c->first)
            : fmt::format("the meridian crosses itself at [{:g}, {:g}] {}: element {} (nodes {} and {}) meets element {} "
                          "(nodes {} and {})",
                          c->at(0), c->at(1), unit, c->second, c->second, c->second + 1, c->first, c->first,
                          c->first + 1),
        ring ? " (a closed ring, a torus, is not a meridian Tunica joins: end it on the axis or leave it open)"
             : " (check the pieces' ends and directions, or the points' order)"));
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
