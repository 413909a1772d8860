#include "output/vtk_writer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <type_traits>

#include <zlib.h>

#include "elements/membrane_compression.hpp"


namespace tunica {

namespace {

struct CellField {
  std::string name;
  std::vector<double> values;
  int components = 1;
};

/// Cell-averaged Gauss-point fields of all parts of an axisymmetric model, in part/element order.
/// Membrane fields (the first 8) are NaN on solid cells. Every cell has the Cauchy stress in
/// cylindrical axes (σ_rr, σ_θθ, σ_zz, σ_rz), the hydrostatic pressure −tr σ/3 and J: solids from
/// their Gauss points; membranes from σ = σ_ss t⊗t + σ_θθ e_θ⊗e_θ (t the meridian tangent; a tube's
/// σ_zz is its meridional stress, σ_rr = σ_rz = 0) and J = 1. Shells report as membranes with their
/// membrane-equivalent stresses N/h (elements/shell_output.hpp) and add the bending moments and the
/// outer/inner surface stresses (the last 6 fields: 0 on membranes, NaN on solids).
std::vector<CellField> cell_fields(const Analysis& a) {
  const Model& m = a.model();
  const std::string s = unit_suffix(m.units, Dimension::pressure);
  const std::string l = unit_suffix(m.units, Dimension::length);
  const std::string fo = unit_suffix(m.units, Dimension::force);
  std::vector<CellField> f = {{"lambda_hoop", {}},       {"lambda_meridional", {}}, {"lambda_thickness", {}},
                              {"S_hoop" + s, {}},        {"S_meridional" + s, {}},  {"sigma_hoop" + s, {}},
                              {"sigma_meridional" + s, {}}, {"thickness" + l, {}},  {"part", {}},
                              {"sigma_rr" + s, {}},      {"sigma_thetatheta" + s, {}}, {"sigma_zz" + s, {}},
                              {"sigma_rz" + s, {}},      {"hydrostatic_pressure" + s, {}}, {"J", {}},
                              {"M_hoop" + fo, {}},       {"M_meridional" + fo, {}},
                              {"sigma_hoop_outer" + s, {}}, {"sigma_hoop_inner" + s, {}},
                              {"sigma_meridional_outer" + s, {}}, {"sigma_meridional_inner" + s, {}},
                              {"reference_thickness" + l, {}}};
  constexpr int kFields = 21;  // and reference_thickness, f[21] (models with an imaged thickness only)
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t p = 0; p < m.parts.size(); ++p) {
    if (m.parts[p].is_solid()) {
      const auto pts = a.system().solid_points(a.displacement(), static_cast<int>(p));
      for (std::size_t e = 0; 4 * e + 3 < pts.size(); ++e) {
        Eigen::Vector4d sigma = Eigen::Vector4d::Zero();  // (rr, zz, θθ, rz)
        double J = 0;
        for (int g = 0; g < 4; ++g) {
          sigma += 0.25 * pts[4 * e + g].sigma;
          J += 0.25 * pts[4 * e + g].J;
        }
        const double v[kFields] = {nan, nan, nan, nan, nan, nan, nan, nan, static_cast<double>(p),
                                   sigma(0), sigma(2), sigma(1), sigma(3), -(sigma(0) + sigma(1) + sigma(2)) / 3.0, J,
                                   nan, nan, nan, nan, nan, nan};
        for (int k = 0; k < kFields; ++k) f[k].values.push_back(v[k]);
        f[kFields].values.push_back(nan);
      }
      continue;
    }
    const auto pts = a.system().points(a.displacement(), static_cast<int>(p), a.loads().step);
    const int q = points_per_element(m.parts[p], m.parts[p].blocks.front().kind);
    for (std::size_t e = 0; q * (e + 1) <= pts.size(); ++e) {
      MembranePoint g;  // the element's Gauss-point average
      g.lambda.setZero();
      for (int k = 0; k < q; ++k) {
        const MembranePoint& x = pts[q * e + k];
        g.lambda += x.lambda / q;
        g.S += x.S / q;
        g.sigma += x.sigma / q;
        g.thickness += x.thickness / q;
        g.cauchy += x.cauchy / q;  // in the meridian plane θ = 0: x = r, y = hoop, z = z
        g.moment += x.moment / q;
        g.sigma_outer += x.sigma_outer / q;
        g.sigma_inner += x.sigma_inner / q;
        g.reference_thickness += x.reference_thickness / q;
      }
      const Eigen::Matrix3d& c = g.cauchy;
      const double v[kFields] = {g.lambda(0), g.lambda(1), g.lambda(2), g.S(0), g.S(1), g.sigma(0), g.sigma(1),
                                 g.thickness, static_cast<double>(p), c(0, 0), c(1, 1), c(2, 2), c(0, 2),
                                 -c.trace() / 3.0, 1.0, g.moment(0), g.moment(1), g.sigma_outer(0), g.sigma_inner(0),
                                 g.sigma_outer(1), g.sigma_inner(1)};
      for (int k = 0; k < kFields; ++k) f[k].values.push_back(v[k]);
      f[kFields].values.push_back(g.reference_thickness);
    }
  }
  // The reference thickness per cell where an inverse step computes it (theory manual (13.12)).
  if (std::none_of(m.parts.begin(), m.parts.end(), [](const Part& part) { return part.imaged_thickness; })) f.pop_back();
  return f;
}

/// The arrays output.vtk_fields selects: a name as written (with its unit suffix) matches a
/// selected name alone or followed by the suffix of the model's pressure, length or force unit.
class FieldFilter {
public:
  explicit FieldFilter(const Model& m)
      : selected_(m.output.vtk_fields),
        suffixes_{"", unit_suffix(m.units, Dimension::pressure), unit_suffix(m.units, Dimension::length),
                  unit_suffix(m.units, Dimension::force)} {}
  bool operator()(const std::string& array) const {
    if (selected_.empty()) return true;
    for (const auto& name : selected_)
      for (const auto& suffix : suffixes_)
        if (array == name + suffix) return true;
    return false;
  }

private:
  const std::vector<std::string>& selected_;
  std::vector<std::string> suffixes_;
};

/// Writes the DataArrays of one .vtu in the chosen format. ascii: the values as text inside the
/// DataArray element (doubles with 17 significant digits, so they read back exactly). binary and
/// compressed: an empty DataArray element with the offset of its block in the AppendedData
/// section at the end of the file, `<AppendedData encoding="raw">_` followed by the blocks.
/// A binary block is a UInt64 byte count and the bytes; a compressed block is VTK's zlib layout:
/// UInt64 [number of chunks, chunk size, size of the last chunk if partial (else 0), the
/// compressed size of each chunk], then the chunks, each compressed on its own.
class ArrayEncoder {
public:
  explicit ArrayEncoder(VtkFormat format) : format_(format) {}

  template <class T>
  std::string array(const std::string& name, const char* type, int components, const std::vector<T>& v) {
    std::string s = fmt::format("<DataArray type=\"{}\" Name=\"{}\" NumberOfComponents=\"{}\"", type, name, components);
    if (format_ == VtkFormat::ascii) {
      s += " format=\"ascii\">\n";
      for (std::size_t i = 0; i < v.size(); ++i) {
        if constexpr (std::is_floating_point_v<T>)
          fmt::format_to(std::back_inserter(s), "{:.17g}", v[i]);
        else
          fmt::format_to(std::back_inserter(s), "{}", static_cast<std::int64_t>(v[i]));
        s += (i + 1) % 9 == 0 || i + 1 == v.size() ? '\n' : ' ';
      }
      return s + "</DataArray>\n";
    }
    s += fmt::format(" format=\"appended\" offset=\"{}\"/>\n", appended_.size());
    const auto* bytes = reinterpret_cast<const unsigned char*>(v.data());
    const std::uint64_t n = v.size() * sizeof(T);
    if (format_ == VtkFormat::binary) {
      put(n);
      appended_.append(reinterpret_cast<const char*>(bytes), n);
    } else {
      compressed_block(bytes, n);
    }
    return s;
  }
  /// The attribute of the VTKFile element naming the compressor ("" unless compressed).
  std::string compressor_attribute() const {
    return format_ == VtkFormat::compressed ? " compressor=\"vtkZLibDataCompressor\"" : "";
  }
  /// What follows the grid: the AppendedData section (empty for ascii).
  std::string appended_section() const {
    if (format_ == VtkFormat::ascii) return "";
    return "<AppendedData encoding=\"raw\">\n_" + appended_ + "\n</AppendedData>\n";
  }

private:
  void put(std::uint64_t x) { appended_.append(reinterpret_cast<const char*>(&x), sizeof x); }
  void compressed_block(const unsigned char* data, std::uint64_t n) {
    constexpr std::uint64_t kChunkBytes = 1 << 15;
    const std::uint64_t chunks = (n + kChunkBytes - 1) / kChunkBytes;
    std::vector<std::string> packed(chunks);
    for (std::uint64_t c = 0; c < chunks; ++c) {
      const uLong in = static_cast<uLong>(std::min(kChunkBytes, n - c * kChunkBytes));
      uLongf out = compressBound(in);
      packed[c].resize(out);
      if (compress2(reinterpret_cast<Bytef*>(packed[c].data()), &out, data + c * kChunkBytes, in, 6) != Z_OK)
        throw std::runtime_error("zlib could not compress a ParaView frame");
      packed[c].resize(out);
    }
    put(chunks);
    put(kChunkBytes);
    put(n % kChunkBytes);
    for (const auto& p : packed) put(p.size());
    for (const auto& p : packed) appended_ += p;
  }

  VtkFormat format_;
  std::string appended_;
};

/// An UnstructuredGrid: cell c has the nodes connectivity[offsets[c−1] … offsets[c]) and type types[c];
/// each cell field value is repeated `cell_repeat` times (the revolved surface's hoop segments).
std::string grid(const std::vector<double>& points, const std::vector<std::int64_t>& connectivity,
                 const std::vector<std::int64_t>& offsets, const std::vector<std::uint8_t>& types,
                 const std::vector<double>& displacement, const std::vector<CellField>& cells, int cell_repeat,
                 VtkFormat format, const FieldFilter& wanted, const std::vector<CellField>& point_fields = {}) {
  const std::size_t np = points.size() / 3, nc = offsets.size();
  ArrayEncoder enc(format);
  const auto data_array = [&](const std::string& name, const char* type, int components, const auto& v) {
    return enc.array(name, type, components, v);
  };
  std::string s = "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
                  "header_type=\"UInt64\"" + enc.compressor_attribute() + ">\n<UnstructuredGrid>\n";
  s += fmt::format("<Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n<Points>\n", np, nc);
  s += data_array("Points", "Float64", 3, points) + "</Points>\n<Cells>\n";
  s += data_array("connectivity", "Int64", 1, connectivity);
  s += data_array("offsets", "Int64", 1, offsets);
  s += data_array("types", "UInt8", 1, types);
  s += wanted("displacement") ? "</Cells>\n<PointData Vectors=\"displacement\">\n" : "</Cells>\n<PointData>\n";
  if (wanted("displacement")) s += data_array("displacement", "Float64", 3, displacement);
  for (const auto& f : point_fields) {  // one value per model node, repeated like the points (cell_repeat)
    if (!wanted(f.name)) continue;
    std::vector<double> v;
    v.reserve(f.values.size() * cell_repeat);
    for (std::size_t c = 0; c < f.values.size(); c += f.components)
      for (int k = 0; k < cell_repeat; ++k) v.insert(v.end(), f.values.begin() + c, f.values.begin() + c + f.components);
    s += data_array(f.name, "Float64", f.components, v);
  }
  s += "</PointData>\n<CellData>\n";
  for (const auto& f : cells) {
    if (!wanted(f.name)) continue;
    std::vector<double> v;
    v.reserve(f.values.size() * cell_repeat);
    for (std::size_t c = 0; c < f.values.size(); c += f.components)
      for (int k = 0; k < cell_repeat; ++k) v.insert(v.end(), f.values.begin() + c, f.values.begin() + c + f.components);
    s += data_array(f.name, "Float64", f.components, v);
  }
  return s + "</CellData>\n</Piece>\n</UnstructuredGrid>\n" + enc.appended_section() + "</VTKFile>\n";
}

/// Cell averages of the Gauss-point states of a 3-D model, with the material frame and the Cauchy tensor.
std::vector<CellField> surface_cell_fields(const Analysis& a) {
  const Model& m = a.model();
  const std::string s = unit_suffix(m.units, Dimension::pressure);
  const std::string l = unit_suffix(m.units, Dimension::length);
  std::vector<CellField> f = {{"lambda_1", {}},          {"lambda_2", {}},          {"lambda_3", {}},
                              {"E_1", {}},               {"E_2", {}},               {"E_12", {}},
                              {"S_1" + s, {}},           {"S_2" + s, {}},           {"S_12" + s, {}},
                              {"sigma_1" + s, {}},       {"sigma_2" + s, {}},       {"sigma_max" + s, {}},
                              {"sigma_min" + s, {}},     {"thickness" + l, {}},     {"part", {}},
                              {"direction_1", {}, 3},    {"direction_2", {}, 3},    {"cauchy_stress" + s, {}, 9},
                              {"compressed", {}},        {"reference_thickness" + l, {}}};
  for (std::size_t p = 0; p < m.parts.size(); ++p) {
    const auto pts = a.system().points(a.displacement(), static_cast<int>(p), a.loads().step);
    const std::vector<char> compressed = compressed_points(pts);
    std::size_t k = 0;
    for (const auto& block : m.parts[p].blocks) {
      const int q = points_per_element(m.parts[p], block.kind);
      for (int e = 0; e < block.size(); ++e, k += q) {
        MembranePoint avg;
        avg.lambda.setZero();
        for (int g = 0; g < q; ++g) {
          const MembranePoint& x = pts[k + g];
          avg.lambda += x.lambda / q;
          avg.E += x.E / q;
          avg.S += x.S / q;
          avg.sigma += x.sigma / q;
          avg.sigma_principal += x.sigma_principal / q;
          avg.thickness += x.thickness / q;
          avg.reference_thickness += x.reference_thickness / q;
          avg.cauchy += x.cauchy / q;
        }
        const double v[15] = {avg.lambda(0), avg.lambda(1), avg.lambda(2), avg.E(0), avg.E(1), avg.E(2),
                              avg.S(0), avg.S(1), avg.S(2), avg.sigma(0), avg.sigma(1), avg.sigma_principal(0),
                              avg.sigma_principal(1), avg.thickness, static_cast<double>(p)};
        for (int i = 0; i < 15; ++i) f[i].values.push_back(v[i]);
        // The frame at the first Gauss point (exact for triangles).
        for (int i = 0; i < 3; ++i) f[15].values.push_back(pts[k].e1(i));
        for (int i = 0; i < 3; ++i) f[16].values.push_back(pts[k].e2(i));
        for (int i = 0; i < 9; ++i) f[17].values.push_back(avg.cauchy(i / 3, i % 3));
        // The fraction of the element's Gauss points in compression (where it would wrinkle).
        double c = 0;
        for (int g = 0; g < q; ++g) c += compressed[k + g];
        f[18].values.push_back(c / q);
        f[19].values.push_back(avg.reference_thickness);
      }
    }
  }
  // The reference thickness per cell where an inverse step computes it (theory manual (13.12)).
  if (std::none_of(m.parts.begin(), m.parts.end(), [](const Part& part) { return part.imaged_thickness; })) f.pop_back();
  return f;
}

}  // namespace

/// Axisymmetric point fields: the contact pressure (normal force over the current tributary
/// area, summed over the pairs a node belongs to; 0 off contact) when the model has contact pairs.
/// A two-pass pair's is on its slave's nodes, both passes' forces (theory manual §9.1, (9.9)).
std::vector<CellField> contact_point_fields(const Analysis& a) {
  const Model& m = a.model();
  if (m.contacts.empty()) return {};
  CellField f;
  f.name = "contact_pressure" + unit_suffix(m.units, Dimension::pressure);
  f.components = 1;
  f.values.assign(m.num_nodes(), 0.0);
  for (std::size_t c = 0; c < m.contacts.size(); ++c) {
    if (m.contacts[c].is_reverse_pass()) continue;  // reported on its pair's slave nodes (contact_states)
    for (const auto& s : a.system().contact_states(a.displacement(), static_cast<int>(c), a.loads().step)) f.values[s.node] += s.pressure;
  }
  return {f};
}

std::string meridian_vtu(const Analysis& a, VtkFormat format) {
  const Model& m = a.model();
  const Eigen::VectorXd& u = a.displacement();
  std::vector<double> pts, disp;
  for (int n = 0; n < m.num_nodes(); ++n) {
    const double ur = u(2 * n), uz = u(2 * n + 1);
    pts.insert(pts.end(), {m.X[n](0) + ur, 0.0, m.X[n](1) + uz});
    disp.insert(disp.end(), {ur, 0.0, uz});
  }
  // Membranes as lines, solids as their quadrilaterals (counter-clockwise in the (r, z) plane).
  std::vector<std::int64_t> conn, offsets;
  std::vector<std::uint8_t> types;
  for (const auto& p : m.parts)
    for (const auto& b : p.blocks) {
      const int nen = nodes_per_element(b.kind);
      for (int e = 0; e < b.size(); ++e) {
        conn.insert(conn.end(), b.element(e), b.element(e) + nen);
        offsets.push_back(static_cast<std::int64_t>(conn.size()));
        types.push_back(vtk_cell_type(b.kind));
      }
    }
  return grid(pts, conn, offsets, types, disp, cell_fields(a), 1, format, FieldFilter(m), contact_point_fields(a));
}

std::string surface_vtu(const Analysis& a, int segments, VtkFormat format) {
  const Model& m = a.model();
  const Eigen::VectorXd& u = a.displacement();
  std::vector<double> pts, disp;
  for (int n = 0; n < m.num_nodes(); ++n) {
    const double ur = u(2 * n), uz = u(2 * n + 1);
    const double r = m.X[n](0) + ur, z = m.X[n](1) + uz;
    for (int j = 0; j < segments; ++j) {
      const double phi = 2.0 * std::numbers::pi * j / segments, c = std::cos(phi), s = std::sin(phi);
      pts.insert(pts.end(), {r * c, r * s, z});
      disp.insert(disp.end(), {ur * c, ur * s, uz});
    }
  }
  // Membranes revolve into quadrilaterals, solids into hexahedra: the element's quadrilateral at the
  // angle of hoop node k (bottom face, its normal −e_θ points towards hoop node j) and at hoop node j.
  std::vector<std::int64_t> conn, offsets;
  std::vector<std::uint8_t> types;
  for (const auto& p : m.parts)
    for (const auto& b : p.blocks) {
      const std::uint8_t type = vtk_revolved_cell_type(b.kind);
      for (int el = 0; el < b.size(); ++el) {
        const int* e = b.element(el);
        for (int j = 0; j < segments; ++j) {
          const int k = (j + 1) % segments;
          if (type == 12 /*VTK_HEXAHEDRON*/) {
            for (int hoop : {k, j})
              for (int q = 0; q < 4; ++q) conn.push_back(static_cast<std::int64_t>(e[q]) * segments + hoop);
          } else {
            conn.insert(conn.end(), {e[0] * segments + j, e[1] * segments + j, e[1] * segments + k, e[0] * segments + k});
          }
          types.push_back(type);
          offsets.push_back(static_cast<std::int64_t>(conn.size()));
        }
      }
    }
  return grid(pts, conn, offsets, types, disp, cell_fields(a), segments, format, FieldFilter(m), contact_point_fields(a));
}

std::string surface3d_vtu(const Analysis& a, VtkFormat format) {
  const Model& m = a.model();
  const Eigen::VectorXd& u = a.displacement();
  std::vector<double> pts, disp;
  pts.reserve(3 * m.num_nodes());
  disp.reserve(3 * m.num_nodes());
  for (int n = 0; n < m.num_nodes(); ++n)
    for (int i = 0; i < 3; ++i) {
      pts.push_back(m.X[n](i) + u(3 * n + i));
      disp.push_back(u(3 * n + i));
    }
  std::vector<std::int64_t> conn, offsets;
  std::vector<std::uint8_t> types;
  for (const auto& p : m.parts)
    for (const auto& b : p.blocks) {
      const int nen = nodes_per_element(b.kind);
      for (int e = 0; e < b.size(); ++e) {
        conn.insert(conn.end(), b.element(e), b.element(e) + nen);
        offsets.push_back(static_cast<std::int64_t>(conn.size()));
        types.push_back(vtk_cell_type(b.kind));
      }
    }
  return grid(pts, conn, offsets, types, disp, surface_cell_fields(a), 1, format, FieldFilter(m));
}

std::string pvd_head() { return "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n"; }
std::string pvd_tail() { return "</Collection>\n</VTKFile>\n"; }
std::string pvd_entry(double time, const std::string& file) {
  return fmt::format("<DataSet timestep=\"{:.12g}\" group=\"\" part=\"0\" file=\"{}\"/>\n", time, file);
}

}  // namespace tunica
