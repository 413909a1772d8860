#include "output/vtk_writer.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <numbers>

#include "output/atomic_file.hpp"

namespace tunica {

namespace {

struct CellField {
  std::string name;
  std::vector<double> values;
};

/// Cell-averaged Gauss-point fields of all parts, in part/element order.
std::vector<CellField> cell_fields(const Analysis& a) {
  const Model& m = a.model();
  const std::string s = unit_suffix(m.units, Dimension::pressure);
  const std::string l = unit_suffix(m.units, Dimension::length);
  std::vector<CellField> f = {{"lambda_hoop", {}},       {"lambda_meridional", {}}, {"lambda_thickness", {}},
                              {"S_hoop" + s, {}},        {"S_meridional" + s, {}},  {"sigma_hoop" + s, {}},
                              {"sigma_meridional" + s, {}}, {"thickness" + l, {}},  {"part", {}}};
  for (std::size_t p = 0; p < m.parts.size(); ++p) {
    const auto pts = a.system().points(a.displacement(), static_cast<int>(p));
    for (std::size_t e = 0; 2 * e + 1 < pts.size(); ++e) {
      const MembranePoint& g0 = pts[2 * e];
      const MembranePoint& g1 = pts[2 * e + 1];
      const double v[9] = {g0.lambda(0) + g1.lambda(0), g0.lambda(1) + g1.lambda(1), g0.lambda(2) + g1.lambda(2),
                           g0.S(0) + g1.S(0),           g0.S(1) + g1.S(1),           g0.sigma(0) + g1.sigma(0),
                           g0.sigma(1) + g1.sigma(1),   g0.thickness + g1.thickness, 2.0 * p};
      for (int k = 0; k < 9; ++k) f[k].values.push_back(0.5 * v[k]);
    }
  }
  return f;
}

/// Base64 of raw bytes (RFC 4648), as VTK's inline binary format expects.
void base64(const unsigned char* data, std::size_t n, std::string& out) {
  static const char* t = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::size_t i = 0;
  for (; i + 2 < n; i += 3) {
    const unsigned v = (data[i] << 16) | (data[i + 1] << 8) | data[i + 2];
    out += {t[v >> 18], t[(v >> 12) & 63], t[(v >> 6) & 63], t[v & 63]};
  }
  if (i + 1 == n) {
    const unsigned v = data[i] << 16;
    out += {t[v >> 18], t[(v >> 12) & 63], '=', '='};
  } else if (i + 2 == n) {
    const unsigned v = (data[i] << 16) | (data[i + 1] << 8);
    out += {t[v >> 18], t[(v >> 12) & 63], t[(v >> 6) & 63], '='};
  }
}

/// A DataArray in VTK's inline binary format: base64 of (UInt64 byte count, values).
template <class T>
std::string data_array(const std::string& name, const char* type, int components, const std::vector<T>& v) {
  std::string s = fmt::format("<DataArray type=\"{}\" Name=\"{}\" NumberOfComponents=\"{}\" format=\"binary\">\n", type,
                              name, components);
  std::vector<unsigned char> bytes(sizeof(std::uint64_t) + v.size() * sizeof(T));
  const std::uint64_t count = v.size() * sizeof(T);
  std::memcpy(bytes.data(), &count, sizeof count);
  if (!v.empty()) std::memcpy(bytes.data() + sizeof count, v.data(), count);
  base64(bytes.data(), bytes.size(), s);
  return s + "\n</DataArray>\n";
}

std::string grid(const std::vector<double>& points, const std::vector<std::int64_t>& connectivity, int nodes_per_cell,
                 std::uint8_t vtk_type, const std::vector<double>& displacement, const std::vector<CellField>& cells,
                 int cell_repeat) {
  const std::size_t np = points.size() / 3, nc = connectivity.size() / nodes_per_cell;
  std::string s =
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
      "header_type=\"UInt64\">\n<UnstructuredGrid>\n";
  s += fmt::format("<Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n<Points>\n", np, nc);
  s += data_array("Points", "Float64", 3, points) + "</Points>\n<Cells>\n";
  std::vector<std::int64_t> offsets(nc);
  for (std::size_t c = 0; c < nc; ++c) offsets[c] = static_cast<std::int64_t>((c + 1) * nodes_per_cell);
  s += data_array("connectivity", "Int64", 1, connectivity);
  s += data_array("offsets", "Int64", 1, offsets);
  s += data_array("types", "UInt8", 1, std::vector<std::uint8_t>(nc, vtk_type));
  s += "</Cells>\n<PointData Vectors=\"displacement\">\n";
  s += data_array("displacement", "Float64", 3, displacement) + "</PointData>\n<CellData>\n";
  for (const auto& f : cells) {
    std::vector<double> v;
    v.reserve(f.values.size() * cell_repeat);
    for (double x : f.values)
      for (int k = 0; k < cell_repeat; ++k) v.push_back(x);
    s += data_array(f.name, "Float64", 1, v);
  }
  return s + "</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
}

}  // namespace

std::string meridian_vtu(const Analysis& a) {
  const Model& m = a.model();
  const Eigen::VectorXd& u = a.displacement();
  std::vector<double> pts, disp;
  for (int n = 0; n < m.num_nodes(); ++n) {
    const double ur = u(kDofsPerNode * n), uz = u(kDofsPerNode * n + 1);
    pts.insert(pts.end(), {m.X[n](0) + ur, 0.0, m.X[n](1) + uz});
    disp.insert(disp.end(), {ur, 0.0, uz});
  }
  std::vector<std::int64_t> conn;
  for (const auto& p : m.parts)
    for (const auto& e : p.elements) conn.insert(conn.end(), {e[0], e[1]});
  return grid(pts, conn, 2, 3 /*VTK_LINE*/, disp, cell_fields(a), 1);
}

std::string surface_vtu(const Analysis& a, int segments) {
  const Model& m = a.model();
  const Eigen::VectorXd& u = a.displacement();
  std::vector<double> pts, disp;
  for (int n = 0; n < m.num_nodes(); ++n) {
    const double ur = u(kDofsPerNode * n), uz = u(kDofsPerNode * n + 1);
    const double r = m.X[n](0) + ur, z = m.X[n](1) + uz;
    for (int j = 0; j < segments; ++j) {
      const double phi = 2.0 * std::numbers::pi * j / segments, c = std::cos(phi), s = std::sin(phi);
      pts.insert(pts.end(), {r * c, r * s, z});
      disp.insert(disp.end(), {ur * c, ur * s, uz});
    }
  }
  std::vector<std::int64_t> conn;
  for (const auto& p : m.parts)
    for (const auto& e : p.elements)
      for (int j = 0; j < segments; ++j) {
        const int k = (j + 1) % segments;
        conn.insert(conn.end(), {e[0] * segments + j, e[1] * segments + j, e[1] * segments + k, e[0] * segments + k});
      }
  return grid(pts, conn, 4, 9 /*VTK_QUAD*/, disp, cell_fields(a), segments);
}

void PvdSeries::add(double time, const std::string& file) {
  entries_.emplace_back(time, file);
  std::string s = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
  for (const auto& [t, f] : entries_)
    s += fmt::format("<DataSet timestep=\"{:.12g}\" group=\"\" part=\"0\" file=\"{}\"/>\n", t, f);
  s += "</Collection>\n</VTKFile>\n";
  write_file_atomically(path_, s);
}

}  // namespace tunica
