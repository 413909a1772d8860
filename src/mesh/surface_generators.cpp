#include "mesh/surface_generators.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <unordered_map>

#include "core/limits.hpp"

namespace tunica {

namespace {

constexpr double kPi = std::numbers::pi;
/// Relative tolerance of the node sets on planes. Nodes meant to lie on a plane are
/// generated with that coordinate exactly 0.0, so any small tolerance selects them
/// exactly; 1e-12 R is far below the spacing of any mesh within kMaxNodes.
constexpr double kPlaneTol = 1e-12;

/// cos/sin with the roundoff of values that should be 0 (cos π/2 = 6e-17, sin π = 1e-16)
/// removed, so that nodes at multiples of 90° lie exactly on the coordinate planes.
/// A genuine |cos| below 1e-14 would need more than 1e14 divisions around: never.
double clean(double v) { return std::abs(v) < 1e-14 ? 0.0 : v; }

/// Appends a quad (a, b, c, d counterclockwise about the outward normal) as one quad or
/// as two triangles, split along a–c or b–d alternately by `parity` (a "union jack"
/// pattern, which avoids a preferred diagonal direction). Both keep the orientation.
void add_quad(SurfaceMesh::Surface& s, int a, int b, int c, int d, bool triangles, bool parity) {
  if (!triangles) {
    s.quads.push_back({a, b, c, d});
  } else if (!parity) {
    s.triangles.push_back({a, b, c});
    s.triangles.push_back({a, c, d});
  } else {
    s.triangles.push_back({a, b, d});
    s.triangles.push_back({b, c, d});
  }
}

/// The indices i < count of the node columns at θ = offset + step·i (column i of a tube) that lie
/// at one of the angles `planes`, taken by index rather than by coordinate: a column within a
/// thousandth of an element's angle of a plane counts as on it, so a sector written as 1.5708 for
/// 90° (its last column 4·10⁻⁶ rad off x = 0) still has that column in `x0`.
std::vector<int> columns_at(double offset, double step, int count, std::initializer_list<double> planes) {
  std::vector<int> out;
  for (double phi : planes) {
    const double t = (phi - offset) / step;
    const double i = std::round(t);
    if (std::abs(t - i) <= 1e-3 && i >= 0 && i < count) out.push_back(static_cast<int>(i));
  }
  return out;
}

/// θ of the planes y = 0 and x = 0 (0 and 2π both: a closed tube's column 0 is its column at 2π).
const std::initializer_list<double> kOnY0 = {0.0, kPi, 2 * kPi};
const std::initializer_list<double> kOnX0 = {kPi / 2, 3 * kPi / 2};

/// The node set `name` of the nodes of columns `columns` of every ring (id(i, j)), or, when there
/// are none, `why` as the reason the mesh has no such set.
template <class Id>
void add_column_set(SurfaceMesh& m, const std::string& name, const std::vector<int>& columns, int rings, const Id& id,
                    const std::string& why) {
  if (columns.empty()) {
    m.absent_sets[name] = why;
    return;
  }
  auto& set = m.node_sets[name];
  for (int j = 0; j < rings; ++j)
    for (int i : columns) set.push_back(id(i, j));
  std::sort(set.begin(), set.end());
  set.erase(std::unique(set.begin(), set.end()), set.end());
}

/// Node set of all nodes whose coordinate `axis` equals `value` within kPlaneTol·radius;
/// not added if empty.
void add_plane_set(SurfaceMesh& m, const std::string& name, int axis, double value, double radius) {
  std::vector<int> set;
  for (int i = 0; i < static_cast<int>(m.nodes.size()); ++i)
    if (std::abs(m.nodes[i](axis) - value) <= kPlaneTol * radius) set.push_back(i);
  if (!set.empty()) m.node_sets[name] = std::move(set);
}

/// Equal-angle gnomonic coordinate on the cube [−1, 1]: u(a) = tan(α0 + a (α1 − α0)/n).
/// Values are made exactly antisymmetric (u(n − a) = −u(a) for a full face) and exact at
/// ±1 and 0, so that nodes on cube edges, symmetry planes and poles are placed exactly.
std::vector<double> cube_coordinates(int n, bool full_face) {
  std::vector<double> u(n + 1);
  if (full_face) {  // α from −π/4 to π/4
    for (int a = 0; 2 * a <= n; ++a) {
      const double t = std::tan(-kPi / 4 + (kPi / 2) * a / n);
      u[a] = t;
      u[n - a] = -t;
    }
    u[0] = -1.0;
    u[n] = 1.0;
    if (n % 2 == 0) u[n / 2] = 0.0;
  } else {  // α from 0 to π/4
    for (int a = 0; a <= n; ++a) u[a] = std::tan((kPi / 4) * a / n);
    u[0] = 0.0;
    u[n] = 1.0;
  }
  return u;
}

/// Cube-projection mesh shared by sphere_mesh and octant_mesh. The lattice points
/// (i, j, k) ∈ [lo, n]³ lying on the faces listed in `faces` (axis, side: side is 0 for
/// the lattice value 0 (the −1 face) or n (the +1 face)) are mapped to the cube point
/// (u_i, u_j, u_k) and projected radially onto the sphere (x = R u/|u|); nodes on cube
/// edges are shared between faces through a lattice-index map. Each face's quads are
/// ordered counterclockwise about the outward normal: with in-face axes (e1, e2) chosen
/// so that e1 × e2 points out of the cube, (a,b), (a+1,b), (a+1,b+1), (a,b+1) is
/// counterclockwise, and the radial projection from the centre keeps the orientation.
SurfaceMesh cube_sphere(double radius, int n, bool triangles, bool full) {
  const std::vector<double> u = cube_coordinates(n, full);
  SurfaceMesh m;
  m.surfaces.resize(1);
  auto& s = m.surfaces[0];
  s.name = "surface";
  const long side = n + 1;
  std::unordered_map<long, int> index;
  const long expected = full ? 6L * n * n + 2 : 3L * n * n + 3L * n + 1;
  index.reserve(static_cast<std::size_t>(expected));
  m.nodes.reserve(static_cast<std::size_t>(expected));
  auto node = [&](const std::array<int, 3>& l) {
    const long key = (l[0] * side + l[1]) * side + l[2];
    auto [it, inserted] = index.emplace(key, static_cast<int>(m.nodes.size()));
    if (inserted) {
      const Eigen::Vector3d c(u[l[0]], u[l[1]], u[l[2]]);
      Eigen::Vector3d x = c * (radius / c.norm());
      for (int d = 0; d < 3; ++d)
        if (c(d) == 0.0) x(d) = 0.0;  // exactly on the symmetry plane (also no −0.0)
      // A point with two zero cube coordinates lies exactly on an axis: (0, 0, ±R).
      m.nodes.push_back(x);
    }
    return it->second;
  };
  for (int axis = 0; axis < 3; ++axis) {
    for (int sgn : {+1, -1}) {
      if (!full && sgn < 0) continue;  // octant: only the faces x = 1, y = 1, z = 1
      const int e1 = sgn > 0 ? (axis + 1) % 3 : (axis + 2) % 3;
      const int e2 = sgn > 0 ? (axis + 2) % 3 : (axis + 1) % 3;
      const int fixed = sgn > 0 ? n : 0;
      for (int b = 0; b < n; ++b) {
        for (int a = 0; a < n; ++a) {
          auto at = [&](int p, int q) {
            std::array<int, 3> l{};
            l[axis] = fixed;
            l[e1] = p;
            l[e2] = q;
            return node(l);
          };
          add_quad(s, at(a, b), at(a + 1, b), at(a + 1, b + 1), at(a, b + 1), triangles, (a + b) % 2 != 0);
        }
      }
    }
  }
  return m;
}

void require(bool ok, const char* what) {
  if (!ok) throw std::invalid_argument(what);
}

}  // namespace

SurfaceMesh tube_mesh(double radius, double length, double sector, int around, int along, bool triangles) {
  require(radius > 0 && length > 0, "tube_mesh: radius and length must be positive");
  require(sector > 0 && sector <= 2 * kPi * (1 + 1e-9), "tube_mesh: sector must be in (0, 2π]");
  const bool closed = std::abs(sector - 2 * kPi) <= 1e-9 * 2 * kPi;
  require(along >= 1 && around >= (closed ? 3 : 1), "tube_mesh: too few elements");
  require(static_cast<long>(closed ? around : around + 1) * (along + 1) <= kMaxNodes, "tube_mesh: too many nodes");
  if (closed) sector = 2 * kPi;
  // Columns of nodes at θ_i = sector·i/around; the closed tube has no column at 2π
  // (its last elements use column 0 again: the seam shares nodes).
  const int columns = closed ? around : around + 1;
  SurfaceMesh m;
  m.nodes.reserve(static_cast<std::size_t>(columns) * (along + 1));
  for (int j = 0; j <= along; ++j) {
    const double z = j == along ? length : length * j / along;
    for (int i = 0; i < columns; ++i) {
      const double theta = i == around ? sector : sector * i / around;
      m.nodes.emplace_back(radius * clean(std::cos(theta)), radius * clean(std::sin(theta)), z);
    }
  }
  m.surfaces.resize(1);
  auto& s = m.surfaces[0];
  s.name = "surface";
  auto id = [&](int i, int j) { return j * columns + (i % columns); };
  // Parametrization x(θ, z) = (R cos θ, R sin θ, z): x_θ × x_z = R (cos θ, sin θ, 0) is the
  // outward normal, so increasing θ then increasing z is counterclockwise seen from outside.
  for (int j = 0; j < along; ++j)
    for (int i = 0; i < around; ++i)
      add_quad(s, id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1), triangles, (i + j) % 2 != 0);
  auto& bottom = m.node_sets["bottom"];
  auto& top = m.node_sets["top"];
  for (int i = 0; i < columns; ++i) {
    bottom.push_back(id(i, 0));
    top.push_back(id(i, along));
  }
  if (!closed) {
    auto& start = m.node_sets["start"];
    auto& end = m.node_sets["end"];
    for (int j = 0; j <= along; ++j) {
      start.push_back(id(0, j));
      end.push_back(id(around, j));
    }
  }
  // The symmetry-plane sets by column index (θ_i = sector·i/around), not by coordinate.
  const double step = sector / around;
  const double degrees = sector * 180 / kPi;
  add_column_set(m, "y0", columns_at(0.0, step, columns, kOnY0), along + 1, id, "");  // column 0 always
  add_column_set(
      m, "x0", columns_at(0.0, step, columns, kOnX0), along + 1, id,
      closed ? fmt::format("`x0` holds the nodes at θ = 90° and 270°, on the plane x = 0, and a closed tube has a "
                           "column of nodes there only when `around` is a multiple of 4 (it is {})",
                           around)
      : degrees < 90 * (1 - 1e-9)
          ? fmt::format("`x0` holds the nodes at θ = 90° and 270°, on the plane x = 0, and this tube's sector, {:.6g} "
                        "deg, ends before 90° (a quarter tube is `sector: 90 deg`)",
                        degrees)
          : fmt::format("`x0` holds the nodes at θ = 90° and 270°, on the plane x = 0, and a sector tube has a column "
                        "of nodes there only when 90 deg × around / sector is a whole number (here {:.6g}: sector {:.6g} "
                        "deg, around {}), e.g. `sector: 90 deg`, or 180 deg with `around` even",
                        90 * around / degrees, degrees, around));
  return m;
}

SurfaceMesh sphere_mesh(double radius, int n, bool triangles) {
  require(radius > 0, "sphere_mesh: radius must be positive");
  require(n >= 1 && 6L * n * n + 2 <= kMaxNodes, "sphere_mesh: n out of range");
  SurfaceMesh m = cube_sphere(radius, n, triangles, true);
  for (auto [name, z] : {std::pair<const char*, double>{"north", radius}, {"south", -radius}}) {
    std::vector<int> set;  // a pole node exists for even n (the centre of the ±z face)
    for (int i = 0; i < static_cast<int>(m.nodes.size()); ++i)
      if (m.nodes[i](0) == 0.0 && m.nodes[i](1) == 0.0 && m.nodes[i](2) == z) set.push_back(i);
    if (!set.empty()) m.node_sets[name] = std::move(set);
  }
  add_plane_set(m, "equator", 2, 0.0, radius);
  for (const std::string name : {"north", "south", "equator"})
    if (!m.node_sets.count(name))
      m.absent_sets[name] = fmt::format("`{}` exists for even n only: a sphere of odd n has no node {} (n = {})", name,
                                        name == "equator" ? "on the plane z = 0" : "at the pole", n);
  return m;
}

SurfaceMesh octant_mesh(double radius, int n, bool triangles) {
  require(radius > 0, "octant_mesh: radius must be positive");
  require(n >= 1 && 3L * n * n + 3L * n + 1 <= kMaxNodes, "octant_mesh: n out of range");
  SurfaceMesh m = cube_sphere(radius, n, triangles, false);
  add_plane_set(m, "x0", 0, 0.0, radius);
  add_plane_set(m, "y0", 1, 0.0, radius);
  add_plane_set(m, "z0", 2, 0.0, radius);
  for (int i = 0; i < static_cast<int>(m.nodes.size()); ++i)
    if (m.nodes[i](0) == 0.0 && m.nodes[i](1) == 0.0) m.node_sets["pole"] = {i};
  return m;
}

namespace {

const ParamSpec kRadius = required(positive(number("radius", Dimension::length, "radius")));
const ParamSpec kShape = with_default(
    one_of(text("shape", "element shape: quadrilaterals, or each split into two triangles"), {"quad", "triangle"}),
    "quad");
const ParamSpec kN = required(at_most(at_least(integer("n", "elements along each edge of a cube face"), 1), 1e7));

bool triangles(const Params& p) { return p.text("shape") == "triangle"; }

/// Refuses n whose mesh would exceed kMaxNodes, before anything is allocated.
int checked_n(const Params& p, long nodes_per_n(long)) {
  const long n = p.integer("n");
  const long nodes = nodes_per_n(n);
  if (nodes > kMaxNodes)
    p.fail("n", fmt::format("n = {} would make {} nodes (at most {} are allowed)", n, nodes, kMaxNodes));
  return static_cast<int>(n);
}

}  // namespace

SurfaceMesh staggered_tube_mesh(double radius, double length, int around, int along) {
  require(radius > 0 && length > 0, "staggered_tube_mesh: radius and length must be positive");
  require(along >= 1 && around >= 3, "staggered_tube_mesh: too few elements");
  require(static_cast<long>(around) * (along + 1) <= kMaxNodes, "staggered_tube_mesh: too many nodes");
  SurfaceMesh m;
  m.nodes.reserve(static_cast<std::size_t>(around) * (along + 1));
  for (int j = 0; j <= along; ++j) {
    const double z = j == along ? length : length * j / along;
    for (int i = 0; i < around; ++i) {
      const double theta = 2 * kPi * (i + 0.5 * (j % 2)) / around;
      m.nodes.emplace_back(radius * clean(std::cos(theta)), radius * clean(std::sin(theta)), z);
    }
  }
  m.surfaces.resize(1);
  auto& s = m.surfaces[0];
  s.name = "surface";
  auto id = [&](int i, int j) { return j * around + (i % around); };
  // Counterclockwise seen from outside (increasing θ, then z; see tube_mesh). Between an
  // even ring j and the shifted ring j+1, node (i, j+1) lies above the middle of (i, j)–(i+1, j);
  // between an odd ring and the unshifted one, node (i+1, j+1) lies above that middle.
  for (int j = 0; j < along; ++j)
    for (int i = 0; i < around; ++i) {
      if (j % 2 == 0) {
        s.triangles.push_back({id(i, j), id(i + 1, j), id(i, j + 1)});
        s.triangles.push_back({id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
      } else {
        s.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
        s.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
      }
    }
  auto& bottom = m.node_sets["bottom"];
  auto& top = m.node_sets["top"];
  for (int i = 0; i < around; ++i) {
    bottom.push_back(id(i, 0));
    top.push_back(id(i, along));
  }
  // By index, per ring: even rings at θ = 2π i/around, odd ones shifted by half an element.
  const double step = 2 * kPi / around;
  for (const auto& [name, planes] :
       {std::pair<const char*, std::initializer_list<double>>{"y0", kOnY0}, {"x0", kOnX0}}) {
    auto& set = m.node_sets[name];
    for (int j = 0; j <= along; ++j)
      for (int i : columns_at(j % 2 ? step / 2 : 0.0, step, around, planes)) set.push_back(id(i, j));
    std::sort(set.begin(), set.end());
    if (set.empty()) {  // only x0: every even ring has its column 0 at θ = 0
      m.node_sets.erase(name);
      m.absent_sets[name] = fmt::format("`{}` holds the nodes on the plane {} = 0, and a staggered tube has nodes "
                                        "there only when `around` is even (it is {})",
                                        name, name[0], around);
    }
  }
  return m;
}

const std::map<std::string, SurfaceGeneratorType>& surface_generator_types() {
  static const std::map<std::string, SurfaceGeneratorType> types = {
      {"tube",
       {ComponentSpec{
            "mesh", "tube",
            "Circular tube about the z axis from z = 0 to z = `length` over the angle sector [0, `sector`] "
            "(360 deg: the closed tube). Node sets: `bottom`, `top`; `start`, `end` (θ = 0, θ = sector) for an "
            "open sector; `y0` (the columns of nodes at θ = 0 and 180°, on the plane y = 0) and `x0` (at θ = 90° and "
            "270°, on x = 0) where there are such columns: `x0` needs a column at 90° or 270° (a sector of 90 deg; "
            "360 deg with `around` a multiple of 4). A column within a thousandth of an element of such an angle "
            "counts (`sector: 1.5708`).",
            {kRadius, required(positive(number("length", Dimension::length, "length along z"))),
             with_default(at_most(positive(number("sector", Dimension::angle, "angle spanned (360 deg: closed tube)")),
                                  2 * kPi * (1 + 1e-9)),
                          "360 deg"),
             required(at_most(at_least(integer("around", "elements around (>= 3 for the closed tube)"), 1), 1e7)),
             required(at_most(at_least(integer("along", "elements along z"), 1), 1e7)),
             with_default(one_of(text("shape", "element shape: quadrilaterals, each split into two triangles, or "
                                               "staggered_triangle (closed tube only: rings shifted by half an "
                                               "element, no coplanar neighbours, so a clamped tube can be loaded "
                                               "from its stress-free state)"),
                                 {"quad", "triangle", "staggered_triangle"}),
                          "quad")}},
        [](const Params& p) {
          const double sector = p.number("sector");
          const long around = p.integer("around"), along = p.integer("along");
          const bool closed = std::abs(sector - 2 * kPi) <= 1e-9 * 2 * kPi;
          if (closed && around < 3) p.fail("around", "a closed tube needs at least 3 elements around");
          const long nodes = (closed ? around : around + 1) * (along + 1);
          if (nodes > kMaxNodes)
            p.fail("around", fmt::format("{} × {} elements would make {} nodes (at most {} are allowed)", around,
                                         along, nodes, kMaxNodes));
          if (p.text("shape") == "staggered_triangle") {
            if (!closed) p.fail("shape", "staggered_triangle needs the closed tube (sector 360 deg)");
            return staggered_tube_mesh(p.number("radius"), p.number("length"), static_cast<int>(around),
                                       static_cast<int>(along));
          }
          return tube_mesh(p.number("radius"), p.number("length"), sector, static_cast<int>(around),
                           static_cast<int>(along), triangles(p));
        }}},
      {"sphere",
       {ComponentSpec{"mesh", "sphere",
                      "Whole sphere about the origin: the six faces of a cube projected onto it (n × n elements "
                      "per face, equal angles). Node sets: `north`, `south` (the poles ±z) and `equator` (z = 0), "
                      "for even n only.",
                      {kRadius, kN, kShape}},
        [](const Params& p) {
          const int n = checked_n(p, [](long k) { return 6 * k * k + 2; });
          return sphere_mesh(p.number("radius"), n, triangles(p));
        }}},
      {"octant",
       {ComponentSpec{"mesh", "octant",
                      "The octant x, y, z ≥ 0 of a sphere about the origin: three cube-projection patches of "
                      "n × n elements. Node sets: `x0`, `y0`, `z0` (the symmetry planes) and `pole` (the node on +z).",
                      {kRadius, kN, kShape}},
        [](const Params& p) {
          const int n = checked_n(p, [](long k) { return 3 * k * k + 3 * k + 1; });
          return octant_mesh(p.number("radius"), n, triangles(p));
        }}},
  };
  return types;
}

}  // namespace tunica
