#include "mesh/msh_surface.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <array>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <numeric>
#include <unordered_map>

#include "core/bounded_file.hpp"
#include "core/errors.hpp"
#include "core/printable.hpp"
#include "mesh/msh_parser.hpp"

namespace tunica {

namespace {

using Key = std::pair<int, int>;  // (dimension, tag)

/// Node tag -> index in MshFile::nodes, after checking that no tag is defined twice.
class NodeIndex {
public:
  NodeIndex(const MshFile& f, const std::string& path) : f_(f) {
    long max_tag = 0;
    for (const auto& n : f.nodes) max_tag = std::max(max_tag, n.tag);
    const long n = static_cast<long>(f.nodes.size());
    if (max_tag <= 4 * n + 1024) {  // dense tags (Gmsh's own numbering): a direct table
      dense_.assign(static_cast<std::size_t>(max_tag) + 1, -1);
      for (long i = 0; i < n; ++i) {
        long& slot = dense_[static_cast<std::size_t>(f.nodes[i].tag)];
        if (slot >= 0) twice(path, f.nodes[slot], f.nodes[i]);
        slot = i;
      }
    } else {
      sorted_.resize(f.nodes.size());
      std::iota(sorted_.begin(), sorted_.end(), 0L);
      std::sort(sorted_.begin(), sorted_.end(), [&](long a, long b) { return f.nodes[a].tag < f.nodes[b].tag; });
      for (std::size_t i = 1; i < sorted_.size(); ++i)
        if (f.nodes[sorted_[i]].tag == f.nodes[sorted_[i - 1]].tag)
          twice(path, f.nodes[std::min(sorted_[i], sorted_[i - 1])], f.nodes[std::max(sorted_[i], sorted_[i - 1])]);
    }
  }
  /// Index of the node with `tag`, or -1.
  long find(long tag) const {
    if (!dense_.empty() || sorted_.empty()) {
      return tag >= 0 && tag < static_cast<long>(dense_.size()) ? dense_[static_cast<std::size_t>(tag)] : -1;
    }
    auto it = std::lower_bound(sorted_.begin(), sorted_.end(), tag, [&](long i, long t) { return f_.nodes[i].tag < t; });
    return it != sorted_.end() && f_.nodes[*it].tag == tag ? *it : -1;
  }

private:
  [[noreturn]] static void twice(const std::string& path, const MshFile::Node& a, const MshFile::Node& b) {
    throw InputError(SourceLocation{path, b.line, 0, ""},
                     a.line > 0 ? fmt::format("node tag {} is defined twice (lines {} and {})", b.tag, a.line, b.line)
                                : fmt::format("node tag {} is defined twice", b.tag));
  }
  const MshFile& f_;
  std::vector<long> dense_, sorted_;
};

std::string element_ref(const MshFile::Element& e) {
  return e.line > 0 ? fmt::format("element {} (line {})", e.tag, e.line) : fmt::format("element {}", e.tag);
}
std::string node_ref(const MshFile::Node& n) {
  return n.line > 0 ? fmt::format("node {} (line {})", n.tag, n.line) : fmt::format("node {}", n.tag);
}

/// Refuses an element tag used twice; a 2.2 file may repeat an element once per physical
/// group it belongs to, with the same type and nodes.
void check_element_tags(const MshFile& f, const std::string& path) {
  std::vector<std::size_t> order(f.elements.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return f.elements[a].tag != f.elements[b].tag ? f.elements[a].tag < f.elements[b].tag : a < b;
  });
  for (std::size_t k = 1; k < order.size(); ++k) {
    const auto& a = f.elements[order[k - 1]];
    const auto& b = f.elements[order[k]];
    if (a.tag != b.tag) continue;
    const int n = msh_element_type(a.type).nodes;
    const bool same = f.version < 4 && a.type == b.type && a.physical != b.physical &&
                      std::equal(f.element_nodes.begin() + a.first, f.element_nodes.begin() + a.first + n,
                                 f.element_nodes.begin() + b.first);
    if (!same)
      throw InputError(SourceLocation{path, b.line, 0, ""},
                       a.line > 0 ? fmt::format("element tag {} is used twice (lines {} and {})", b.tag, a.line, b.line)
                                  : fmt::format("element tag {} is used twice", b.tag));
  }
}

/// Elements of each physical group, ordered by elementary entity, then as in the file.
std::map<Key, std::vector<std::size_t>> physical_groups(const MshFile& f, const std::string& path) {
  std::map<Key, std::vector<std::size_t>> groups;
  if (f.version >= 4) {
    // Every element is listed once per physical group of its entity: bounded before listing.
    std::size_t memberships = 0;
    for (const auto& el : f.elements)
      if (auto it = f.entity_physicals.find({el.entity_dim, el.entity}); it != f.entity_physicals.end())
        memberships += it->second.size();
    for (const auto& n : f.nodes)
      if (auto it = f.entity_physicals.find({n.entity_dim, n.entity}); it != f.entity_physicals.end())
        memberships += it->second.size();
    if (memberships > static_cast<std::size_t>(4 * kMaxMshElements))
      throw InputError(SourceLocation{path, 0, 0, ""},
                       fmt::format("the elements and nodes belong to {} physical groups in all, more than the {} "
                                   "Tunica reads (an entity in thousands of groups?)",
                                   memberships, 4 * kMaxMshElements));
    for (const auto& [entity, phys] : f.entity_physicals)
      for (int p : phys) groups[{entity.first, p}];
    for (std::size_t e = 0; e < f.elements.size(); ++e) {
      const auto& el = f.elements[e];
      auto it = f.entity_physicals.find({el.entity_dim, el.entity});
      if (it == f.entity_physicals.end()) continue;
      for (int p : it->second) groups[{el.entity_dim, p}].push_back(e);
    }
  } else {
    for (std::size_t e = 0; e < f.elements.size(); ++e)
      if (f.elements[e].physical != 0) groups[{f.elements[e].entity_dim, f.elements[e].physical}].push_back(e);
  }
  for (auto& [key, members] : groups) {
    auto& v = members;
    std::stable_sort(v.begin(), v.end(), [&](std::size_t a, std::size_t b) { return f.elements[a].entity < f.elements[b].entity; });
    v.erase(std::unique(v.begin(), v.end()), v.end());
  }
  return groups;
}

std::string group_name(const MshFile& f, const Key& g) {
  auto it = f.physical_names.find(g);
  if (it != f.physical_names.end() && !it->second.empty()) return it->second;
  return (g.first == 2 ? "surface_" : g.first == 1 ? "curve_" : g.first == 0 ? "point_" : "volume_") +
         std::to_string(g.second);
}

[[noreturn]] void coincide(const MshFile& f, long a, long b, const std::string& path) {
  const auto& p = f.nodes[std::min(a, b)];
  const auto& q = f.nodes[std::max(a, b)];
  throw InputError(SourceLocation{path, q.line, 0, ""},
                   fmt::format("{} and {} coincide at ({:.6g}, {:.6g}, {:.6g}): the surface is split there (a crack); "
                               "merge duplicate nodes (Gmsh: Coherence Mesh;) or give the elements one node",
                               node_ref(p), node_ref(q), p.x(0), p.x(1), p.x(2)));
}

/// Two used nodes at one position: a crack in the surface. Candidates are the pairs within
/// tol = 1e-9 of the size of the meshed region; a candidate is a coincidence when the two
/// are also within 1e-6 of the shortest edge at either (`h`, per node), so that one node
/// far away (which makes the region huge) cannot make neighbours "coincide". Fast path: nodes sorted by their projection on a direction no mesh is aligned
/// with, comparing only nodes whose projections are within tol. A file whose nodes crowd
/// one projection (all on one plane normal to it) would make that quadratic, so past
/// 16 comparisons per node the check goes over to grids of cells of size H = 2 tol,
/// shifted by 0 or H/2 along each axis (8 grids): two nodes within tol share a cell in
/// at least one of them, and all nodes of one cell lie within 2√3 tol of each other, so a
/// crowded cell is a coincidence too.
void check_coincident(const MshFile& f, const std::vector<long>& used, const std::vector<double>& h,
                      const std::string& path) {
  if (used.size() < 2) return;
  const auto same_point = [&](long a, long b) {
    const double dist = (f.nodes[a].x - f.nodes[b].x).norm();
    return dist == 0 || dist <= 1e-6 * std::min(h[a], h[b]);
  };
  Eigen::Vector3d lo = f.nodes[used[0]].x, hi = lo;
  for (long i : used) {
    lo = lo.cwiseMin(f.nodes[i].x);
    hi = hi.cwiseMax(f.nodes[i].x);
  }
  const double tol = 1e-9 * (hi - lo).norm();
  if (!(tol > 0)) coincide(f, used[0], used[1], path);  // every node at one point
  const Eigen::Vector3d d = Eigen::Vector3d(1.0, std::sqrt(2.0), std::sqrt(3.0)).normalized();
  std::vector<std::pair<double, long>> proj;
  proj.reserve(used.size());
  for (long i : used) proj.emplace_back(d.dot(f.nodes[i].x), i);
  std::sort(proj.begin(), proj.end());
  std::size_t budget = 16 * used.size();
  bool crowded = false;
  for (std::size_t a = 0; a < proj.size() && !crowded; ++a)
    for (std::size_t b = a + 1; b < proj.size() && proj[b].first - proj[a].first <= tol; ++b) {
      if (budget-- == 0) {
        crowded = true;
        break;
      }
      if ((f.nodes[proj[a].second].x - f.nodes[proj[b].second].x).norm() <= tol &&
          same_point(proj[a].second, proj[b].second))
        coincide(f, proj[a].second, proj[b].second, path);
    }
  if (!crowded) return;
  const double H = 2 * tol;
  std::vector<std::pair<std::array<long long, 3>, long>> cells(used.size());
  for (int shift = 0; shift < 8; ++shift) {
    for (std::size_t k = 0; k < used.size(); ++k) {
      const Eigen::Vector3d& x = f.nodes[used[k]].x;
      for (int c = 0; c < 3; ++c)
        cells[k].first[c] = static_cast<long long>(std::floor((x(c) - lo(c)) / H + ((shift >> c) & 1) * 0.5));
      cells[k].second = used[k];
    }
    std::sort(cells.begin(), cells.end());
    for (std::size_t k = 1; k < cells.size(); ++k)
      if (cells[k].first == cells[k - 1].first && same_point(cells[k - 1].second, cells[k].second))
        coincide(f, cells[k - 1].second, cells[k].second, path);
  }
}

/// `path` names a Gmsh script (.geo): the mesh is the one Gmsh made of it.
bool is_script(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext == ".geo";
}

/// The line of the Gmsh script `path` that defines the physical surface `name`
/// (`Physical Surface("name") = ...`, spaces anywhere), 0 if none does or the file cannot be read.
int script_line_of_physical_surface(const std::string& path, const std::string& name) {
  std::string text;
  try {
    text = read_file_bounded(path, std::size_t{64} << 20, "Gmsh script");
  } catch (const std::exception&) {
    return 0;
  }
  const auto squeeze = [](const std::string& t) {
    std::string out;
    for (char c : t)
      if (c != ' ' && c != '\t' && c != '\r') out += c;
    return out;
  };
  const std::string wanted = "PhysicalSurface(\"" + squeeze(name) + "\"";
  int line = 1;
  for (std::size_t start = 0; start < text.size(); ++line) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    if (squeeze(text.substr(start, end - start)).find(wanted) != std::string::npos) return line;
    start = end + 1;
  }
  return 0;
}

/// The message for the physical surface `name` (tag `tag`) that the file names but that holds
/// no elements and no entity: its Physical Surface lists surfaces the geometry does not have.
std::string empty_named_surface(const MshFile& f, const std::string& name, int tag, bool script) {
  std::vector<int> surfaces;  // the surface entities of a 4.1 file
  for (const auto& [entity, phys] : f.entity_physicals)
    if (entity.first == 2) surfaces.push_back(entity.second);
  std::string existing;
  if (!surfaces.empty()) {
    std::string list;
    for (std::size_t i = 0; i < std::min<std::size_t>(surfaces.size(), 12); ++i)
      list += (i ? ", " : "") + std::to_string(surfaces[i]);
    if (surfaces.size() > 12) list += fmt::format(", … ({} in all)", surfaces.size());
    existing = fmt::format("; the geometry's surfaces are numbered {}", list);
  }
  return fmt::format(
      "physical surface '{}' (tag {}) {} but holds no elements: {}. Likely its Physical Surface names surface "
      "numbers that do not exist after the geometry operations (BooleanFragments, BooleanUnion, BooleanDifference "
      "and Coherence renumber the surfaces they touch){}: check the numbering, e.g. in the Gmsh GUI with the surface "
      "labels shown (Tools > Options > Geometry > Visibility, or Geometry.SurfaceLabels = 1;), and list the "
      "surfaces as numbered after the operations",
      printable(name), tag, script ? "is defined" : "is named in $PhysicalNames",
      script ? "none of the surfaces it lists exists in the geometry Gmsh meshed" : "no surface of the file belongs to it",
      existing);
}

}  // namespace

SurfaceMesh surface_mesh_from_msh(const MshFile& f, const std::string& path, const std::string& direction_view) {
  const auto fail = [&](const std::string& what, int line = 0, const std::string& key = "") -> void {
    throw InputError(SourceLocation{path, line, 0, key}, what);
  };
  const NodeIndex index(f, path);
  check_element_tags(f, path);
  const auto groups = physical_groups(f, path);

  // Physical surfaces: element indices by type, after checking their types.
  struct Raw {
    std::string name;
    int tag = 0;
    std::vector<std::size_t> tri, quad;
  };
  std::vector<Raw> raw;
  std::map<std::string, int> surface_names;  // name -> physical tag
  std::size_t surface_elements = 0;
  for (const auto& [key, members] : groups) {
    if (key.first != 2) continue;
    Raw s;
    s.name = group_name(f, key);
    s.tag = key.second;
    if (auto [it, fresh] = surface_names.emplace(s.name, s.tag); !fresh)
      fail(fmt::format("physical surfaces {} and {} are both named '{}'", it->second, s.tag, printable(s.name)), 0,
           printable(s.name));
    for (std::size_t e : members) {
      const auto& el = f.elements[e];
      if (el.type == 2 || el.type == 9) {
        // A surface's triangles are all linear or all quadratic (Gmsh meshes one order at a time).
        if (!s.tri.empty() && f.elements[s.tri.front()].type != el.type)
          fail(fmt::format("physical surface '{}' mixes 3-node (type 2) and 6-node (type 9) triangles ({}): mesh it "
                           "with one Mesh.ElementOrder",
                           printable(s.name), element_ref(el)),
               el.line, printable(s.name));
        s.tri.push_back(e);
      } else if (el.type == 3) {
        s.quad.push_back(e);
      } else {
        const MshElementType t = msh_element_type(el.type);
        const std::string name = t.name;
        const bool vowel = name.rfind("8-", 0) == 0 || name.rfind("11-", 0) == 0 || name.rfind("18-", 0) == 0;
        fail(fmt::format("physical surface '{}': {} is {} {} (type {}); Tunica reads 3-node and 6-node triangles "
                         "(types 2 and 9) and 4-node quadrangles (type 3){}",
                         printable(s.name), element_ref(el), vowel ? "an" : "a", name, el.type,
                         t.dim == 2 ? ": mesh with Mesh.ElementOrder = 1, or 2 with triangles only" : ""),
             el.line, printable(s.name));
      }
    }
    if (s.tri.empty() && s.quad.empty())
      fail(fmt::format("physical surface '{}' has no elements (is the surface meshed?)", printable(s.name)), 0, printable(s.name));
    surface_elements += s.tri.size() + s.quad.size();
    raw.push_back(std::move(s));
  }
  // A named physical surface with no entity and no element: its Physical Surface listed surfaces
  // that the geometry does not have (Gmsh writes the name all the same).
  for (const auto& [key, name] : f.physical_names)
    if (key.first == 2 && !groups.count(key)) {
      const bool script = is_script(path);
      throw InputError(SourceLocation{path, script ? script_line_of_physical_surface(path, name) : 0, 0, printable(name)},
                       empty_named_surface(f, name, key.second, script));
    }
  // Surface elements outside every physical surface would leave holes unseen: refused.
  // (By tag: a 2.2 file repeats an element once per physical group it belongs to.)
  if (!raw.empty()) {
    std::vector<long> grouped;
    for (const auto& sf : raw)
      for (const auto* list : {&sf.tri, &sf.quad})
        for (std::size_t e : *list) grouped.push_back(f.elements[e].tag);
    std::sort(grouped.begin(), grouped.end());
    std::size_t orphans = 0;
    const MshFile::Element* first = nullptr;
    for (const auto& el : f.elements)
      if (msh_element_type(el.type).dim == 2 && !std::binary_search(grouped.begin(), grouped.end(), el.tag))
        if (orphans++ == 0) first = &el;
    if (first)
      fail(fmt::format("{} surface element(s), the first {}, belong to no physical surface: add them to one "
                       "(Physical Surface) or leave them out of the file (Gmsh: Mesh.SaveAll = 0)",
                       orphans, element_ref(*first)),
           first->line);
  }
  if (raw.empty()) {
    std::size_t two_d = 0;
    for (const auto& el : f.elements) two_d += msh_element_type(el.type).dim == 2;
    fail(fmt::format("the file defines no physical surface{}: name the membrane's surfaces, e.g. in the .geo file "
                     "Physical Surface(\"wall\") = {{1, 2}};",
                     two_d ? fmt::format(" (its {} surface elements belong to no physical group)", two_d) : ""));
  }

  // Used nodes, numbered compactly in the order of their tags.
  std::vector<long> used;  // indices into f.nodes
  const auto node_of = [&](const MshFile::Element& el, int k) {
    const long tag = f.element_nodes[el.first + k];
    const long i = index.find(tag);
    if (i < 0) fail(fmt::format("{} names node {}, which the file does not define", element_ref(el), tag), el.line);
    return i;
  };
  for (const auto& s : raw)
    for (const auto* list : {&s.tri, &s.quad})
      for (std::size_t e : *list) {
        const auto& el = f.elements[e];
        for (int k = 0; k < msh_element_type(el.type).nodes; ++k) used.push_back(node_of(el, k));
      }
  std::sort(used.begin(), used.end(), [&](long a, long b) { return f.nodes[a].tag < f.nodes[b].tag; });
  used.erase(std::unique(used.begin(), used.end()), used.end());
  if (static_cast<long>(used.size()) > kMaxMshNodes)
    fail(fmt::format("the physical surfaces have {} nodes (at most {} are allowed)", used.size(), kMaxMshNodes));
  // The shortest non-zero edge at each used node: the local length scale of the coincidence test.
  std::vector<double> h(f.nodes.size(), std::numeric_limits<double>::infinity());
  for (const auto& s : raw)
    for (const auto* list : {&s.tri, &s.quad})
      for (std::size_t e : *list) {
        const auto& el = f.elements[e];
        const int n = msh_element_type(el.type).nodes;
        for (int k = 0; k < n; ++k) {
          const long a = node_of(el, k), b = node_of(el, (k + 1) % n);
          const double len = (f.nodes[a].x - f.nodes[b].x).norm();
          if (len > 0) {
            h[a] = std::min(h[a], len);
            h[b] = std::min(h[b], len);
          }
        }
      }
  check_coincident(f, used, h, path);
  std::vector<int> compact(f.nodes.size(), -1);  // f.nodes index -> mesh node, -1 if unused
  SurfaceMesh mesh;
  mesh.nodes.reserve(used.size());
  mesh.node_tags.reserve(used.size());
  for (std::size_t i = 0; i < used.size(); ++i) {
    compact[used[i]] = static_cast<int>(i);
    mesh.nodes.push_back(f.nodes[used[i]].x);
    mesh.node_tags.push_back(f.nodes[used[i]].tag);
  }

  for (const auto& s : raw) {
    SurfaceMesh::Surface out;
    out.name = s.name;
    for (std::size_t e : s.tri) {
      const auto& el = f.elements[e];
      out.triangles.push_back({compact[node_of(el, 0)], compact[node_of(el, 1)], compact[node_of(el, 2)]});
      if (el.type == 9)
        out.triangle_midsides.push_back({compact[node_of(el, 3)], compact[node_of(el, 4)], compact[node_of(el, 5)]});
      out.triangle_tags.push_back(el.tag);
      out.triangle_lines.push_back(el.line);
    }
    for (std::size_t e : s.quad) {
      const auto& el = f.elements[e];
      out.quads.push_back({compact[node_of(el, 0)], compact[node_of(el, 1)], compact[node_of(el, 2)],
                           compact[node_of(el, 3)]});
      out.quad_tags.push_back(el.tag);
      out.quad_lines.push_back(el.line);
    }
    mesh.surfaces.push_back(std::move(out));
  }

  // An element that shares no edge with another hangs by a node at most: a mechanism.
  if (surface_elements > 1) {
    std::vector<std::pair<std::pair<int, int>, std::pair<int, int>>> edges;  // (edge, (surface, element))
    for (int si = 0; si < static_cast<int>(mesh.surfaces.size()); ++si) {
      const auto& s = mesh.surfaces[si];
      const int nt = static_cast<int>(s.triangles.size());
      for (int e = 0; e < nt + static_cast<int>(s.quads.size()); ++e) {
        const int* v = e < nt ? s.triangles[e].data() : s.quads[e - nt].data();
        const int nv = e < nt ? 3 : 4;
        for (int k = 0; k < nv; ++k) {
          const int a = v[k], b = v[(k + 1) % nv];
          edges.push_back({{std::min(a, b), std::max(a, b)}, {si, e}});
        }
      }
    }
    std::sort(edges.begin(), edges.end());
    std::vector<std::vector<char>> has_neighbour(mesh.surfaces.size());
    for (std::size_t si = 0; si < mesh.surfaces.size(); ++si)
      has_neighbour[si].assign(mesh.surfaces[si].triangles.size() + mesh.surfaces[si].quads.size(), 0);
    for (std::size_t k = 0; k < edges.size();) {
      std::size_t j = k;
      while (j < edges.size() && edges[j].first == edges[k].first) ++j;
      if (j - k > 1)
        for (std::size_t m = k; m < j; ++m) has_neighbour[edges[m].second.first][edges[m].second.second] = 1;
      k = j;
    }
    for (std::size_t si = 0; si < raw.size(); ++si) {
      const auto& s = raw[si];
      for (std::size_t e = 0; e < has_neighbour[si].size(); ++e) {
        if (has_neighbour[si][e]) continue;
        const auto& el = f.elements[e < s.tri.size() ? s.tri[e] : s.quad[e - s.tri.size()]];
        fail(fmt::format("physical surface '{}': {} shares no edge with any other element (it hangs by a node at "
                         "most, a mechanism); remove it or connect it to the surface",
                         printable(s.name), element_ref(el)),
             el.line, printable(s.name));
      }
    }
  }

  // Physical curves and points: the nodes of their elements and (4.1) the nodes classified
  // on their entities, restricted to the nodes of the physical surfaces.
  std::map<Key, std::vector<Key>> entity_groups;  // entity (dim, tag) -> its physical groups (4.1)
  for (const auto& [entity, phys] : f.entity_physicals)
    if (entity.first <= 1)
      for (int p : phys) entity_groups[entity].push_back({entity.first, p});
  std::map<Key, std::vector<int>> sets;
  for (const auto& [key, members] : groups) {
    if (key.first != 0 && key.first != 1) continue;
    std::vector<int>& set = sets[key];
    for (std::size_t e : members) {
      const auto& el = f.elements[e];
      for (int k = 0; k < msh_element_type(el.type).nodes; ++k)
        if (const int c = compact[node_of(el, k)]; c >= 0) set.push_back(c);
    }
  }
  if (!entity_groups.empty())
    for (long i = 0; i < static_cast<long>(f.nodes.size()); ++i) {
      if (f.nodes[i].entity_dim < 0 || f.nodes[i].entity_dim > 1) continue;
      auto g = entity_groups.find({f.nodes[i].entity_dim, f.nodes[i].entity});
      if (g == entity_groups.end()) continue;
      const int c = compact[i];
      if (c < 0) continue;
      for (const Key& key : g->second) sets[key].push_back(c);
    }
  std::map<std::string, Key> named;  // node-set name -> the group that took it
  for (auto& [key, set] : sets) {
    const std::string name = group_name(f, key);
    if (auto [it, fresh] = named.emplace(name, key); !fresh)
      fail(fmt::format("physical groups {} (dimension {}) and {} (dimension {}) are both named '{}': a node set needs a "
                       "name of its own",
                       it->second.second, it->second.first, key.second, key.first, printable(name)),
           0, printable(name));
    std::sort(set.begin(), set.end());
    set.erase(std::unique(set.begin(), set.end()), set.end());
    mesh.node_sets[name] = std::move(set);
    mesh.node_set_origins[name] = fmt::format("physical {} {}", key.first == 0 ? "point" : "curve", key.second);
  }

  // Per-element direction-1 vectors from a 3-component element-data view.
  if (!direction_view.empty()) {
    const MshFile::ElementData* view = nullptr;
    std::string names;
    for (const auto& d : f.element_data) {
      names += (names.empty() ? "'" : ", '") + printable(d.name) + "'";
      if (d.name == direction_view && !view) view = &d;
    }
    if (!view)
      fail(fmt::format("no $ElementData view named '{}' for the element directions (views in the file: {})",
                       printable(direction_view), names.empty() ? "none" : names),
           0, printable(direction_view));
    if (view->components != 3)
      fail(fmt::format("view '{}' must hold 3 components per element (a vector); it holds {}", printable(direction_view),
                       view->components),
           view->line, printable(direction_view));
    std::unordered_map<long, Eigen::Vector3d> by_element;
    by_element.reserve(view->tags.size());
    for (std::size_t k = 0; k < view->tags.size(); ++k)
      by_element.emplace(view->tags[k], Eigen::Vector3d(view->values[3 * k], view->values[3 * k + 1], view->values[3 * k + 2]));
    auto lookup = [&](const std::string& surface, long element) {
      auto it = by_element.find(element);
      if (it == by_element.end())
        fail(fmt::format("view '{}' has no direction for element {} of physical surface '{}'", printable(direction_view),
                         element, printable(surface)),
             view->line, printable(direction_view));
      if (!it->second.allFinite() || it->second.norm() == 0)
        fail(fmt::format("view '{}': the direction of element {} of physical surface '{}' is zero or not finite",
                         printable(direction_view), element, printable(surface)),
             view->line, printable(direction_view));
      return it->second;
    };
    for (std::size_t i = 0; i < raw.size(); ++i) {
      for (long t : mesh.surfaces[i].triangle_tags) mesh.surfaces[i].triangle_direction.push_back(lookup(raw[i].name, t));
      for (long t : mesh.surfaces[i].quad_tags) mesh.surfaces[i].quad_direction.push_back(lookup(raw[i].name, t));
    }
  }
  return mesh;
}

}  // namespace tunica
