// Reading Gmsh files through the Gmsh SDK (C++ API, libgmsh 4.8).
//
// How the Gmsh 4.8 API reports errors (found by reading gmsh.h and by experiment):
// gmsh::initialize sets "General.AbortOnError" to 2, with which every error Gmsh
// reports (Msg::Error) is thrown as a C++ exception of type std::string holding the
// message (e.g. "'x.geo', line 1: syntax error (a)"); gmsh::logger::getLastError
// returns the same text. Some failures are not errors at all: gmsh::open of a file
// that does not exist only logs nothing and leaves an empty model. Worse, a syntax
// error thrown out of the .geo parser leaves the parser's (global, flex/bison) state
// corrupted: every later .geo or .msh read in the same process then fails with a
// spurious syntax error. So this reader sets "General.AbortOnError" to 0 (errors are
// only logged; the parser recovers and finishes), records Gmsh's messages with
// gmsh::logger, and turns any new "Error: ..." message after each API call into an
// InputError. Exceptions still thrown (std::string, std::exception, anything) are
// converted too. The file's existence is checked beforehand.
//
// Gmsh is a global singleton: read_gmsh serialises all use of it with a mutex and
// initializes / finalizes it around each read (RAII guard), so it is not re-entrant
// and must not be used while anything else in the process uses the Gmsh API.
// Note: a .geo file is a script Gmsh executes; it can run commands (`System`), so
// only read .geo files from trusted sources.
#include "mesh/gmsh_reader.hpp"

#include <fmt/format.h>
#include <gmsh.h>

#include <algorithm>
#include <cerrno>
#include <clocale>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <regex>
#include <unordered_map>

#include "core/errors.hpp"
#include "io/deck_limits.hpp"

namespace tunica {

namespace {

std::mutex gmsh_mutex;

/// Initializes Gmsh quietly (no configuration files, no terminal output, errors logged
/// rather than thrown, the logger on) and always finalizes it, also when an exception
/// leaves the reader. Restores the numeric locale Gmsh sets to "C".
class GmshSession {
public:
  explicit GmshSession(const std::string& path)
      : locale_(std::setlocale(LC_NUMERIC, nullptr) ? std::setlocale(LC_NUMERIC, nullptr) : "C") {
    try {
      gmsh::initialize(0, nullptr, false);  // argc, argv, readConfigFiles
      gmsh::option::setNumber("General.Terminal", 0);
      gmsh::option::setNumber("General.Verbosity", 2);  // errors and warnings only
      gmsh::option::setNumber("General.AbortOnError", 0);
      gmsh::logger::start();
    } catch (...) {
      close();  // finalize what was initialized
      throw InputError(SourceLocation{path, 0, 0, ""}, "could not initialize Gmsh to read the file");
    }
  }
  ~GmshSession() { close(); }
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;

private:
  void close() noexcept {
    try {
      gmsh::logger::stop();
      gmsh::finalize();
    } catch (...) {  // nothing sensible to do; never throw from a destructor
    }
    std::setlocale(LC_NUMERIC, locale_.c_str());
  }
  std::string locale_;
};

/// Turns Gmsh's failures into InputErrors naming the file (and the line, when Gmsh's
/// message has one, "'file', line N: ...").
class Reporter {
public:
  explicit Reporter(std::string path) : path_(std::move(path)) {
    std::vector<std::string> log;
    gmsh::logger::get(log);
    seen_ = log.size();
  }

  [[noreturn]] void fail(const std::string& message, const std::string& key = "", int line = 0) const {
    throw InputError(SourceLocation{path_, line, 0, key}, message);
  }

  /// Fails with Gmsh's own message.
  [[noreturn]] void fail_gmsh(const std::string& doing, std::string message, const std::string& key = "") const {
    int line = 0;
    static const std::regex located(R"(^'[^']*', line (\d+): (.*)$)");
    std::smatch m;
    if (std::regex_match(message, m, located)) {
      line = std::stoi(m[1].str());
      message = m[2].str();
    }
    fail(fmt::format("Gmsh error while {}: {}", doing, message), key, line);
  }

  /// Runs a Gmsh API call; fails on an exception or on an error it logged.
  template <class F>
  void call(const std::string& doing, F&& f, const std::string& key = "") {
    try {
      f();
    } catch (const std::string& s) {
      fail_gmsh(doing, s, key);
    } catch (const char* s) {
      fail_gmsh(doing, s ? s : "unknown error", key);
    } catch (const InputError&) {
      throw;
    } catch (const std::exception& e) {
      fail_gmsh(doing, e.what(), key);
    } catch (...) {
      std::string last;
      try {
        gmsh::logger::getLastError(last);
      } catch (...) {
      }
      fail_gmsh(doing, last.empty() ? "unknown error" : last, key);
    }
    std::vector<std::string> log;
    gmsh::logger::get(log);
    for (std::size_t i = seen_; i < log.size(); ++i)
      if (log[i].rfind("Error: ", 0) == 0) fail_gmsh(doing, log[i].substr(7), key);
    seen_ = log.size();
  }

private:
  std::string path_;
  std::size_t seen_ = 0;
};

/// Description of an unsupported element type, with a hint.
std::string unsupported_element(int type) {
  static const std::map<int, const char*> names = {
      {9, "6-node second-order triangle"},          {10, "9-node second-order quadrangle"},
      {16, "8-node second-order quadrangle"},       {20, "9-node third-order incomplete triangle"},
      {21, "10-node third-order triangle"},         {22, "12-node fourth-order incomplete triangle"},
      {23, "15-node fourth-order triangle"},        {24, "15-node fifth-order incomplete triangle"},
      {25, "21-node fifth-order complete triangle"}, {36, "16-node third-order quadrangle"},
      {37, "25-node fourth-order quadrangle"},
  };
  std::string name;
  int order = 0;
  if (auto it = names.find(type); it != names.end()) {
    name = it->second;
    order = 2;
  } else {
    try {
      int dim = 0, num_nodes = 0, primary = 0;
      std::vector<double> local;
      gmsh::model::mesh::getElementProperties(type, name, dim, order, num_nodes, local, primary);
    } catch (...) {
      name = "unknown";
    }
  }
  return fmt::format("element type {} ({}) is not supported; {}", type, name,
                     order > 1 ? "mesh with Mesh.ElementOrder = 1"
                               : "only 3-node triangles (type 2) and 4-node quadrangles (type 3) are");
}

}  // namespace

SurfaceMesh read_gmsh(const std::string& path, const std::string& direction_view) {
  // The file must exist and be readable: gmsh::open silently ignores a missing file.
  {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec))
      throw InputError(SourceLocation{path, 0, 0, ""}, "cannot open the mesh file: no such file");
    if (std::filesystem::is_directory(path, ec))
      throw InputError(SourceLocation{path, 0, 0, ""}, "cannot open the mesh file: it is a directory");
    std::ifstream probe(path);
    if (!probe) throw InputError(SourceLocation{path, 0, 0, ""}, std::string("cannot open the mesh file: ") + std::strerror(errno));
  }

  std::lock_guard<std::mutex> lock(gmsh_mutex);
  GmshSession session(path);
  Reporter r(path);

  r.call("reading the file", [&] { gmsh::open(path); });

  // A geometry without a 2-D mesh (a .geo without `Mesh 2;`): mesh its surfaces.
  {
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> tags, nodes;
    gmsh::vectorpair surfaces;
    r.call("reading the elements", [&] {
      gmsh::model::mesh::getElements(types, tags, nodes, 2, -1);
      gmsh::model::getEntities(surfaces, 2);
    });
    if (types.empty() && !surfaces.empty()) r.call("meshing the surfaces", [&] { gmsh::model::mesh::generate(2); });
  }

  gmsh::vectorpair groups;
  r.call("reading the physical groups", [&] { gmsh::model::getPhysicalGroups(groups, -1); });
  auto group_name = [&](int dim, int tag) {
    std::string name;
    r.call("reading the physical names", [&] { gmsh::model::getPhysicalName(dim, tag, name); });
    if (name.empty()) name = (dim == 2 ? "surface_" : dim == 1 ? "curve_" : "point_") + std::to_string(tag);
    return name;
  };
  auto entities_of = [&](int dim, int tag, const std::string& name) {
    std::vector<int> entities;
    r.call("reading the physical groups", [&] { gmsh::model::getEntitiesForPhysicalGroup(dim, tag, entities); },
           name);
    return entities;
  };

  // Physical surfaces: elements by Gmsh node tags, with their Gmsh element tags.
  struct RawSurface {
    std::string name;
    std::vector<std::array<std::size_t, 3>> tri;
    std::vector<std::array<std::size_t, 4>> quad;
    std::vector<std::size_t> tri_tags, quad_tags;
  };
  std::vector<RawSurface> raw;
  std::vector<std::size_t> used;  // Gmsh tags of the nodes of physical surfaces
  for (const auto& [dim, tag] : groups) {
    if (dim != 2) continue;
    RawSurface s;
    s.name = group_name(dim, tag);
    for (int entity : entities_of(dim, tag, s.name)) {
      std::vector<int> types;
      std::vector<std::vector<std::size_t>> etags, enodes;
      r.call("reading the elements", [&] { gmsh::model::mesh::getElements(types, etags, enodes, 2, entity); }, s.name);
      for (std::size_t t = 0; t < types.size(); ++t) {
        if (types[t] == 2) {
          for (std::size_t e = 0; e < etags[t].size(); ++e) {
            s.tri.push_back({enodes[t][3 * e], enodes[t][3 * e + 1], enodes[t][3 * e + 2]});
            s.tri_tags.push_back(etags[t][e]);
          }
        } else if (types[t] == 3) {
          for (std::size_t e = 0; e < etags[t].size(); ++e) {
            s.quad.push_back({enodes[t][4 * e], enodes[t][4 * e + 1], enodes[t][4 * e + 2], enodes[t][4 * e + 3]});
            s.quad_tags.push_back(etags[t][e]);
          }
        } else if (!etags[t].empty()) {
          r.fail(fmt::format("physical surface '{}': {}", s.name, unsupported_element(types[t])), s.name);
        }
      }
      for (const auto& v : enodes) used.insert(used.end(), v.begin(), v.end());
    }
    if (s.tri.empty() && s.quad.empty())
      r.fail(fmt::format("physical surface '{}' has no elements (is the surface meshed?)", s.name), s.name);
    raw.push_back(std::move(s));
  }
  if (raw.empty())
    r.fail("the file defines no physical surface: name the membrane's surfaces, e.g. Physical Surface(\"wall\") = "
           "{1, 2};");

  // Compact numbering of the nodes of physical surfaces, in the order of their Gmsh tags.
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  if (static_cast<long>(used.size()) > kMaxNodes)
    r.fail(fmt::format("the physical surfaces have {} nodes (at most {} are allowed)", used.size(), kMaxNodes));
  std::unordered_map<std::size_t, int> index;
  index.reserve(used.size());
  for (std::size_t i = 0; i < used.size(); ++i) index.emplace(used[i], static_cast<int>(i));

  SurfaceMesh mesh;
  mesh.nodes.assign(used.size(), Eigen::Vector3d::Constant(std::nan("")));
  {
    std::vector<std::size_t> tags;
    std::vector<double> coord, param;
    r.call("reading the nodes", [&] { gmsh::model::mesh::getNodes(tags, coord, param, -1, -1, false, false); });
    std::vector<char> found(used.size(), 0);
    for (std::size_t k = 0; k < tags.size(); ++k) {
      auto it = index.find(tags[k]);
      if (it == index.end()) continue;
      mesh.nodes[it->second] = Eigen::Vector3d(coord[3 * k], coord[3 * k + 1], coord[3 * k + 2]);
      found[it->second] = 1;
    }
    for (std::size_t i = 0; i < used.size(); ++i)
      if (!found[i]) r.fail(fmt::format("node {} used by an element is not defined", used[i]));
  }

  for (auto& s : raw) {
    SurfaceMesh::Surface out;
    out.name = s.name;
    for (const auto& t : s.tri) out.triangles.push_back({index.at(t[0]), index.at(t[1]), index.at(t[2])});
    for (const auto& q : s.quad) out.quads.push_back({index.at(q[0]), index.at(q[1]), index.at(q[2]), index.at(q[3])});
    mesh.surfaces.push_back(std::move(out));
  }

  // Physical curves and points: all nodes of their entities, with the nodes bounding
  // them (includeBoundary) and those of their elements (for files without topology),
  // restricted to nodes of the physical surfaces (others are dropped from the mesh).
  for (const auto& [group_dim, tag] : groups) {
    const int dim = group_dim;  // a plain variable: lambdas may not capture bindings before C++20 in clang 14
    if (dim != 0 && dim != 1) continue;
    const std::string name = group_name(dim, tag);
    std::vector<int>& set = mesh.node_sets[name];
    for (int entity : entities_of(dim, tag, name)) {
      std::vector<std::size_t> tags;
      std::vector<double> coord, param;
      std::vector<int> types;
      std::vector<std::vector<std::size_t>> etags, enodes;
      r.call("reading the nodes of physical groups", [&] {
        gmsh::model::mesh::getNodes(tags, coord, param, dim, entity, true, false);
        gmsh::model::mesh::getElements(types, etags, enodes, dim, entity);
      }, name);
      for (const auto& v : enodes) tags.insert(tags.end(), v.begin(), v.end());
      for (std::size_t t : tags)
        if (auto it = index.find(t); it != index.end()) set.push_back(it->second);
    }
    std::sort(set.begin(), set.end());
    set.erase(std::unique(set.begin(), set.end()), set.end());
  }

  // Per-element direction-1 vectors from a 3-component element-data view.
  if (!direction_view.empty()) {
    std::vector<int> views;
    r.call("reading the views", [&] { gmsh::view::getTags(views); }, direction_view);
    int view = -1;
    std::string names;
    for (int v : views) {
      std::string name;
      r.call("reading the views", [&] {
        gmsh::option::getString("View[" + std::to_string(gmsh::view::getIndex(v)) + "].Name", name);
      }, direction_view);
      names += (names.empty() ? "" : ", ") + ("'" + name + "'");
      if (name == direction_view && view < 0) view = v;
    }
    if (view < 0)
      r.fail(fmt::format("no post-processing view named '{}' for the element directions (views in the file: {})",
                         direction_view, names.empty() ? "none" : names),
             direction_view);
    std::string type;
    std::vector<std::size_t> tags;
    std::vector<std::vector<double>> data;
    double time = 0;
    int components = 0;
    r.call("reading the view data", [&] { gmsh::view::getModelData(view, 0, type, tags, data, time, components); },
           direction_view);
    if (type != "ElementData" || components != 3)
      r.fail(fmt::format("view '{}' must hold element data with 3 components (a vector per element); it holds {} "
                         "with {} components",
                         direction_view, type.empty() ? "no model data" : type, components),
             direction_view);
    std::unordered_map<std::size_t, Eigen::Vector3d> by_element;
    by_element.reserve(tags.size());
    for (std::size_t k = 0; k < tags.size(); ++k) {
      if (data[k].size() < 3) continue;
      by_element.emplace(tags[k], Eigen::Vector3d(data[k][0], data[k][1], data[k][2]));
    }
    auto lookup = [&](const std::string& surface, std::size_t element) {
      auto it = by_element.find(element);
      if (it == by_element.end())
        r.fail(fmt::format("view '{}' has no direction for element {} of physical surface '{}'", direction_view,
                           element, surface),
               direction_view);
      if (!it->second.allFinite() || it->second.norm() == 0)
        r.fail(fmt::format("view '{}': the direction of element {} of physical surface '{}' is zero or not finite",
                           direction_view, element, surface),
               direction_view);
      return it->second;
    };
    for (std::size_t i = 0; i < raw.size(); ++i) {
      for (std::size_t t : raw[i].tri_tags) mesh.surfaces[i].triangle_direction.push_back(lookup(raw[i].name, t));
      for (std::size_t t : raw[i].quad_tags) mesh.surfaces[i].quad_direction.push_back(lookup(raw[i].name, t));
    }
  }
  return mesh;
}

}  // namespace tunica
