#include "io/deck_surface_parts.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "contributions/element_type.hpp"
#include "elements/membrane3d.hpp"
#include "core/printable.hpp"
#include "io/deck_limits.hpp"
#include "io/deck_names.hpp"
#include "io/unitless_values.hpp"
#include "mesh/gmsh_reader.hpp"
#include "mesh/mesh_checks.hpp"
#include "mesh/surface_formats.hpp"
#include "mesh/surface_generators.hpp"

namespace tunica {

const ComponentSpec& frame_spec() {
  static const ComponentSpec s{
      "parts.frame", "",
      "Material frame of a 3-D part: direction 1 at each Gauss point is the rule's vector projected on the "
      "reference tangent plane and normalized; direction 2 = n × direction 1 (n: the element normal). "
      "`cylindrical`: direction 1 circumferential about `axis` through `point` (for a tube along the axis, "
      "2 is axial); `vector`: `direction` projected; `mesh`: per-element vectors of the Gmsh element-data "
      "view `view`; `edge` (default): along each element's first edge, for isotropic materials. A "
      "direction within 0.06° of the normal is an error. ParaView output shows both directions per element.",
      {with_default(one_of(text("type", "frame rule"), {"edge", "cylindrical", "vector", "mesh"}), "edge"),
       with_default(numbers("axis", Dimension::dimensionless, 3, "cylindrical: axis direction"), "[0, 0, 1]"),
       with_default(numbers("point", Dimension::length, 3, "cylindrical: a point on the axis"), "[0, 0, 0]"),
       with_default(numbers("direction", Dimension::dimensionless, 3, "vector: direction 1 before projection"),
                    "[1, 0, 0]"),
       text("view", "mesh: name of the 3-component element-data view in the Gmsh file")}};
  return s;
}

const ComponentSpec& gmsh_mesh_spec() {
  static const ComponentSpec s{
      "mesh", "gmsh",
      "A physical surface of a Gmsh file: a mesh (.msh 4.1 or 2.2, ASCII or binary, read as data) or a "
      "geometry script (.geo, meshed in 2-D when read, only with --allow-scripts: a script can run commands). "
      "Parts that name the same file share its nodes. Its physical curves and points become node sets "
      "under their own names. Linear (3-node) and quadratic (6-node, Mesh.ElementOrder = 2) triangles "
      "and linear quadrilaterals; their node order gives the side pressure acts on.",
      {required(text("file", "path of the .msh or .geo file, relative to the deck")),
       required(text("surface", "name of the physical surface"))}};
  return s;
}

namespace {

Eigen::Vector3d vec3(const std::vector<double>& v) { return Eigen::Vector3d(v[0], v[1], v[2]); }

FrameRule read_frame(const DeckNode& node, const Model& m, const Part& part) {
  FrameRule f;
  if (!node.defined()) {
    if (!part.material->isotropic())
      node.fail("material '" + part.material_name +
                "' is anisotropic: give the part a `frame` (e.g. `frame: {type: cylindrical, axis: [0, 0, 1]}`)");
    return f;
  }
  const Params p = read_params(node, frame_spec(), m.units);
  const std::string& t = p.text("type");
  if (t == "cylindrical") {
    f.type = FrameRule::Type::cylindrical;
    f.axis = vec3(p.numbers("axis"));
    if (!(f.axis.norm() > 0)) p.fail("axis", "the axis direction must not be zero");
    f.axis.normalize();
    f.point = vec3(p.numbers("point"));
  } else if (t == "vector") {
    f.type = FrameRule::Type::vector;
    f.vector = vec3(p.numbers("direction"));
    if (!(f.vector.norm() > 0)) p.fail("direction", "the direction must not be zero");
  } else if (t == "mesh") {
    f.type = FrameRule::Type::mesh;
    if (!p.has("view")) p.fail("type", "frame `mesh` needs the key `view` (the element-data view name)");
    f.view = p.text("view");
  } else {
    f.type = FrameRule::Type::edge;
  }
  return f;
}

/// Adds the node set `name`, defined by `origin` (NodeSet::origin), unless a set of that name is
/// defined already.
void add_set(Model& m, const std::string& name, std::vector<int> nodes, const DeckNode& where, const std::string& origin) {
  if (const int earlier = m.find_node_set(name); earlier >= 0)
    where.fail(fmt::format("node set '{}' is defined twice: by {}, and by {}. Rename one of them (a physical group "
                           "in its mesh file: Physical Curve(\"new name\") in Gmsh)",
                           printable(name), m.node_sets[earlier].origin, origin));
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  m.node_sets.push_back({name, std::move(nodes), origin});
}

/// Blocks of a mesh surface with node numbers mapped to global ones.
void add_blocks(const SurfaceMesh::Surface& s, const std::vector<int>& global, bool directions, Part& part,
                const std::string& file = "") {
  if (!s.triangles.empty()) {
    // Quadratic triangles: the corners, then the mid-edge nodes (model.hpp, ElementKind::tri6).
    const bool quadratic = !s.triangle_midsides.empty();
    ElementBlock b;
    b.kind = quadratic ? ElementKind::tri6 : ElementKind::tri3;
    for (std::size_t e = 0; e < s.triangles.size(); ++e) {
      for (int n : s.triangles[e]) b.nodes.push_back(global[n]);
      if (quadratic)
        for (int n : s.triangle_midsides[e]) b.nodes.push_back(global[n]);
    }
    if (directions) b.direction = s.triangle_direction;
    b.tags = s.triangle_tags;
    b.file = file;
    part.blocks.push_back(std::move(b));
  }
  if (!s.quads.empty()) {
    ElementBlock b;
    b.kind = ElementKind::quad4;
    for (const auto& q : s.quads)
      for (int n : q) b.nodes.push_back(global[n]);
    if (directions) b.direction = s.quad_direction;
    b.tags = s.quad_tags;
    b.file = file;
    part.blocks.push_back(std::move(b));
  }
  for (const auto& b : part.blocks) part.nodes.insert(part.nodes.end(), b.nodes.begin(), b.nodes.end());
  std::sort(part.nodes.begin(), part.nodes.end());
  part.nodes.erase(std::unique(part.nodes.begin(), part.nodes.end()), part.nodes.end());
}

/// A file a deck could mean as a mesh: a Gmsh mesh or script, or a surface format that
/// surface_format_advice explains.
bool mesh_like(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  for (const char* e : {".msh", ".geo", ".stl", ".vtk", ".vtp", ".vtu", ".obj", ".ply", ".off"})
    if (ext == e) return true;
  return false;
}

/// "no such mesh file: <path as resolved>", what a relative path is relative to, and a mesh
/// file of that folder whose name is really close (core/suggest.hpp, nearest_file_name); else
/// the mesh files there when they are few.
std::string missing_file_message(const std::string& written, const std::string& resolved) {
  namespace fs = std::filesystem;
  constexpr std::size_t kListed = 8;
  std::error_code ec;
  const fs::path absolute = fs::absolute(resolved, ec);
  std::string s = "no such mesh file: " + printable((ec ? fs::path(resolved) : absolute).lexically_normal().string(), 200);
  if (fs::path(written).is_relative()) s += " ('" + printable(written, 200) + "' is read relative to the deck's folder)";
  std::vector<std::string> meshes;
  const fs::path folder = fs::path(resolved).parent_path().empty() ? fs::path(".") : fs::path(resolved).parent_path();
  if (!fs::exists(folder, ec)) return s + "; the folder " + printable(folder.string(), 200) + " does not exist either";
  std::size_t seen = 0;
  for (fs::directory_iterator it(folder, ec), end; !ec && it != end && seen < 1000; it.increment(ec), ++seen)
    if (mesh_like(it->path()) && !it->is_directory(ec)) meshes.push_back(it->path().filename().string());
  std::sort(meshes.begin(), meshes.end());
  if (const std::string best = nearest_file_name(fs::path(resolved).filename().string(), meshes); !best.empty())
    return s + "; did you mean '" + printable(best) + "'?";
  if (meshes.empty()) return s + "; that folder holds no mesh file (.msh, or a .geo script)";
  if (meshes.size() > kListed) return s + fmt::format("; that folder holds {} mesh files, none with a near name", meshes.size());
  std::string list;
  for (const auto& f : meshes) list += (list.empty() ? "" : ", ") + printable(f);
  return s + "; the mesh files in that folder are: " + list;
}

}  // namespace

void read_surface_part(const DeckNode& node, Part& part, Model& m, SurfaceMeshCache& cache) {
  const DeckNode mesh = node.required("mesh");
  if (!mesh.is_map()) mesh.fail("expected a map with `type: tube`, `sphere`, `octant` or `gmsh`");
  const std::string type = mesh.required("type").as_string();
  // The mesh type first: a meridian mesh (`line`, `arc`) on a 3-D part is the likelier mistake
  // than a missing frame.
  if (type != "gmsh" && !surface_generator_types().count(type))
    mesh["type"].fail("unknown mesh type '" + type + "' for a membrane part (known: gmsh, octant, sphere, tube)" +
                      did_you_mean(type, {"gmsh", "octant", "sphere", "tube"}) +
                      (type == "line" || type == "arc"
                           ? "; `" + type + "` meshes a meridian: for an axisymmetric part write `element: axisymmetric_membrane`"
                           : ""));
  const DeckNode frame = node["frame"];
  part.frame = read_frame(frame, m, part);

  if (type == "gmsh") {
    const Params mp = read_params(mesh, gmsh_mesh_spec(), m.units, {"type"});
    std::filesystem::path file(mp.text("file"));
    if (file.is_relative()) file = std::filesystem::path(m.deck_file).parent_path() / file;
    const std::string path = file.lexically_normal().string();
    const std::string key = path + "\n" + part.frame.view;
    auto it = cache.files.find(key);
    if (it == cache.files.end()) {
      std::error_code ec;
      if (!std::filesystem::exists(path, ec)) mp.fail("file", missing_file_message(mp.text("file"), path));
      if (!std::filesystem::is_regular_file(path, ec))
        mp.fail("file", "the mesh file " + path + " is not a regular file (a device, pipe, socket or directory)");
      if (const std::string advice = surface_format_advice(path, mp.text("surface")); !advice.empty())
        mp.fail("file", advice);
      SurfaceMesh sm;
      try {
        sm = read_gmsh(path, part.frame.view, cache.allow_scripts);
      } catch (const InputError& e) {
        // Keep the mesh file's own location, and say which deck key asked for it.
        throw InputError(e.where(), e.reason() + fmt::format(" (the mesh of {}:{}, key '{}')", mp.where("file").file,
                                                              mp.where("file").line, mp.where("file").key));
      }
      if (static_cast<long>(m.num_nodes()) + static_cast<long>(sm.nodes.size()) > kMaxNodes)
        mp.fail("file", fmt::format("the model would have more than {} nodes", kMaxNodes));
      SurfaceMeshCache::Entry entry;
      entry.global.resize(sm.nodes.size());
      m.node_tags.resize(m.X.size(), 0);
      for (std::size_t i = 0; i < sm.nodes.size(); ++i) {
        entry.global[i] = m.num_nodes();
        m.X.push_back(sm.nodes[i]);
        m.node_tags.push_back(i < sm.node_tags.size() ? sm.node_tags[i] : 0);
      }
      for (const auto& [name, nodes] : sm.node_sets) {
        std::vector<int> g;
        for (int n : nodes) g.push_back(entry.global[n]);
        const auto group = sm.node_set_origins.find(name);
        add_set(m, name, g, mesh["file"],
                fmt::format("{} '{}' of {} (the mesh of part '{}', line {})",
                            group == sm.node_set_origins.end() ? "a physical group" : group->second, printable(name),
                            mp.text("file"), part.name, mp.where("file").line));
      }
      entry.mesh = std::move(sm);
      it = cache.files.emplace(key, std::move(entry)).first;
    }
    const auto& surfaces = it->second.mesh.surfaces;
    auto s = std::find_if(surfaces.begin(), surfaces.end(), [&](const auto& x) { return x.name == mp.text("surface"); });
    if (s == surfaces.end()) {
      std::string list;
      for (const auto& x : surfaces) list += (list.empty() ? "" : ", ") + printable(x.name);
      mp.fail("surface", path + " has no physical surface '" + printable(mp.text("surface")) + "' (it has: " + list + ")");
    }
    if (const std::string why = check_surface(it->second.mesh, *s); !why.empty())
      mp.fail("surface", path + ": " + why);  // `why` names the surface
    add_blocks(*s, it->second.global, part.frame.type == FrameRule::Type::mesh, part, path);
  } else {
    auto gen = surface_generator_types().find(type);
    if (gen == surface_generator_types().end())
      mesh["type"].fail("unknown mesh type '" + type + "' for a membrane part (known: gmsh, octant, sphere, tube)" +
                        did_you_mean(type, {"gmsh", "octant", "sphere", "tube"}));
    if (part.frame.type == FrameRule::Type::mesh)
      frame["type"].fail("frame `mesh` needs a Gmsh mesh with an element-data view");
    const Params mp = read_params(mesh, gen->second.spec, m.units, {"type"});
    warn_unitless_values(mesh, gen->second.spec, m);
    const SurfaceMesh sm = gen->second.make(mp);
    if (static_cast<long>(m.num_nodes()) + static_cast<long>(sm.nodes.size()) > kMaxNodes)
      mesh.fail(fmt::format("the model would have more than {} nodes", kMaxNodes));
    std::vector<int> global(sm.nodes.size());
    for (std::size_t i = 0; i < sm.nodes.size(); ++i) {
      global[i] = m.num_nodes();
      m.X.push_back(sm.nodes[i]);
    }
    const std::string generated = fmt::format("part '{}' (line {}) as one of its generated sets", part.name,
                                              node.where().line);
    for (const auto& [name, nodes] : sm.node_sets) {
      std::vector<int> g;
      for (int n : nodes) g.push_back(global[n]);
      add_set(m, part.name + "." + name, g, mesh, generated);
    }
    for (const auto& [name, why] : sm.absent_sets) m.absent_node_sets[part.name + "." + name] = why;
    if (const std::string why = check_surface(sm, sm.surfaces.at(0)); !why.empty()) mesh.fail(why);
    add_blocks(sm.surfaces.at(0), global, false, part);
  }
  add_set(m, part.name + ".all", part.nodes, mesh,
          fmt::format("part '{}' (line {}) as one of its generated sets", part.name, node.where().line));
}

void finish_surface_parts(const DeckNode& parts, Model& m) {
  // Renumber the nodes elements use; drop the others (e.g. of Gmsh surfaces no part names).
  std::vector<int> map(m.num_nodes(), -1);
  int n = 0;
  for (const auto& part : m.parts)
    for (const auto& b : part.blocks)
      for (int v : b.nodes)
        if (map[v] < 0) map[v] = 0;
  std::vector<Eigen::Vector3d> X;
  std::vector<long> tags;
  for (int i = 0; i < m.num_nodes(); ++i)
    if (map[i] == 0) {
      map[i] = n++;
      X.push_back(m.X[i]);
      tags.push_back(i < static_cast<int>(m.node_tags.size()) ? m.node_tags[i] : 0);
    }
  if (n != m.num_nodes()) {
    m.X = std::move(X);
    m.node_tags = std::move(tags);
    for (auto& part : m.parts) {
      for (auto& b : part.blocks)
        for (int& v : b.nodes) v = map[v];
      for (int& v : part.nodes) v = map[v];
    }
    for (auto& set : m.node_sets) {
      std::vector<int> kept;
      for (int v : set.nodes)
        if (map[v] >= 0) kept.push_back(map[v]);
      set.nodes = std::move(kept);
    }
  }
  for (const auto& part : m.parts) {
    int first = 0;
    for (const auto& block : part.blocks) {
      try {
        if (const ElementType& type = element_type(block.kind); type.check) type.check(m, part, block, first);
      } catch (const BadElement& e) {
        const std::string what = e.what();
        const DeckNode pn = parts[part.name];
        const bool frame_fault = what.find("direction") != std::string::npos && pn.has("frame");
        (frame_fault ? pn["frame"] : pn["mesh"]).fail("part '" + part.name + "': " + what);
      }
      first += block.size();
    }
  }
}

}  // namespace tunica
