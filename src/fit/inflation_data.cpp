#include "fit/inflation_data.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

#include "core/bounded_file.hpp"

namespace tunica {

namespace {

constexpr std::size_t kMaxDataBytes = 64u << 20;  ///< a data file of experiments: far below 64 MiB

/// What a recognised column measures.
enum class Role { pressure, outer_diameter, radius, axial_force, axial_stretch, green_strain_z };

struct RoleName {
  const char* name;
  Role role;
  Dimension dim;
};

constexpr RoleName kRoles[] = {
    {"pressure", Role::pressure, Dimension::pressure},
    {"outer_diameter", Role::outer_diameter, Dimension::length},
    {"radius", Role::radius, Dimension::length},
    {"axial_force", Role::axial_force, Dimension::force},
    {"axial_stretch", Role::axial_stretch, Dimension::dimensionless},
    {"lambda_z", Role::axial_stretch, Dimension::dimensionless},
    {"E_z", Role::green_strain_z, Dimension::dimensionless},
};

/// A field of a CSV line and the 1-based character column where it starts.
struct Field {
  std::string text;
  int column = 1;
};

std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t\r");
  if (a == std::string::npos) return "";
  const auto b = s.find_last_not_of(" \t\r");
  return s.substr(a, b - a + 1);
}

std::vector<Field> split_fields(const std::string& line) {
  std::vector<Field> out;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    const std::string raw = line.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    const std::size_t lead = raw.find_first_not_of(" \t");
    out.push_back({trim(raw), static_cast<int>(start + (lead == std::string::npos ? 0 : lead)) + 1});
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

/// A recognised column: its index, header, role, unit and factor to internal units.
struct Column {
  int index = -1;
  std::string header;
  Role role = Role::pressure;
  std::string unit;
  double factor = 1;
  int char_column = 1;
};

/// Matches "name", "name_unit", "name [unit]" or "name (unit)"; returns the unit ("" if none).
std::optional<std::string> match_header(const std::string& header, const std::string& name) {
  if (header == name) return std::string();
  if (header.rfind(name, 0) != 0) return std::nullopt;
  std::string rest = header.substr(name.size());
  if (rest[0] == '_') {
    // "N_per_mm2" (Tunica's own column suffix) means N/mm2.
    const std::string suffix = rest.substr(1);
    std::string unit;
    for (std::size_t i = 0; i < suffix.size();) {
      if (suffix.compare(i, 5, "_per_") == 0) {
        unit += '/';
        i += 5;
      } else {
        unit += suffix[i++];
      }
    }
    return unit;
  }
  rest = trim(rest);
  if (rest.size() >= 2 && ((rest.front() == '[' && rest.back() == ']') || (rest.front() == '(' && rest.back() == ')')))
    return trim(rest.substr(1, rest.size() - 2));
  return std::nullopt;
}

const char* role_description(Role r) {
  switch (r) {
    case Role::pressure: return "pressure";
    case Role::outer_diameter: return "outer diameter";
    case Role::radius: return "mid-surface radius";
    case Role::axial_force: return "axial force";
    case Role::axial_stretch: return "axial stretch";
    case Role::green_strain_z: return "axial Green strain";
  }
  return "?";
}


}  // namespace

std::pair<std::string, double> parse_row_selection(const std::string& text) {
  const auto eq = text.find('=');
  const SourceLocation where{"--select", 0, 0, text};
  if (eq == std::string::npos || eq == 0) throw InputError(where, "expected COLUMN=VALUE, e.g. step=2");
  const std::string value = trim(text.substr(eq + 1));
  char* end = nullptr;
  const double v = std::strtod(value.c_str(), &end);
  if (value.empty() || *end != '\0' || !std::isfinite(v))
    throw InputError(where, "'" + value + "' is not a number (expected COLUMN=VALUE, e.g. step=2)");
  return {trim(text.substr(0, eq)), v};
}

InflationData read_inflation_data(const std::string& path, const InflationDataOptions& options) {
  return read_inflation_data_text(read_file_bounded(path, kMaxDataBytes, "data file"), path, options);
}

InflationData read_inflation_data_text(const std::string& text, const std::string& file,
                                       const InflationDataOptions& options) {
  InflationData data;
  data.file = file;
  auto fail = [&](int line, int column, const std::string& key, const std::string& what) -> void {
    throw InputError({file, line, column, key}, what);
  };

  // Pass 1: the specimen comment, the header and the data lines.
  std::optional<DeckNode> specimen_node = options.specimen;
  std::vector<Field> header;
  std::vector<std::pair<int, std::vector<Field>>> rows;
  {
    std::istringstream in(text);
    std::string line;
    int ln = 0;
    bool file_specimen_seen = false;
    while (std::getline(in, line)) {
      ++ln;
      const std::string t = trim(line);
      if (t.empty()) continue;
      if (t[0] == '#') {
        const std::size_t hash = line.find('#');
        const std::size_t key = line.find_first_not_of(" \t", hash + 1);
        if (key == std::string::npos || line.compare(key, 9, "specimen:") != 0) continue;
        if (file_specimen_seen) fail(ln, static_cast<int>(key) + 1, "specimen", "a second `# specimen:` line");
        file_specimen_seen = true;
        if (options.specimen) continue;  // replaced by --specimen
        // Pad the YAML so that its marks are this file's line and column.
        const std::size_t value = key + 9;
        const std::string yaml = std::string(ln - 1, '\n') + std::string(value, ' ') + line.substr(value);
        try {
          specimen_node =
              DeckNode(YAML::Load(yaml), file, "specimen", {file, ln, static_cast<int>(key) + 1, "specimen"});
        } catch (const YAML::Exception& e) {
          fail(ln, e.mark.is_null() ? 0 : e.mark.column + 1, "specimen", "YAML syntax error: " + e.msg);
        }
        continue;
      }
      if (header.empty()) {
        header = split_fields(line);
        data.header_line = ln;
      } else {
        rows.emplace_back(ln, split_fields(line));
      }
    }
  }
  if (header.empty()) fail(0, 0, "", "no header line: the first line that is not a `#` comment names the columns");

  // Header: recognised columns and their units.
  const UnitSystem units("mm", "N");
  std::vector<Column> columns;
  std::string all_headers;
  for (std::size_t i = 0; i < header.size(); ++i) {
    const Field& f = header[i];
    all_headers += (all_headers.empty() ? "" : ", ") + f.text;
    for (const RoleName& r : kRoles) {
      const auto unit = match_header(f.text, r.name);
      if (!unit) continue;
      Column c{static_cast<int>(i), f.text, r.role, *unit, 1.0, f.column};
      if (r.dim != Dimension::dimensionless && unit->empty())
        fail(data.header_line, f.column, f.text,
             fmt::format("the {} column needs a unit in its header, e.g. '{}_{}'", role_description(r.role), r.name,
                         r.dim == Dimension::pressure ? "mmHg"
                         : r.dim == Dimension::force  ? "N"
                                                      : "mm"));
      try {
        c.factor = units.to_internal(1.0, *unit, r.dim);
      } catch (const std::invalid_argument& e) {
        fail(data.header_line, f.column, f.text,
             fmt::format("{} (the {} column's unit)", e.what(), role_description(r.role)));
      }
      for (const Column& other : columns) {
        const bool same = other.role == c.role || (other.role == Role::radius && c.role == Role::outer_diameter) ||
                          (other.role == Role::outer_diameter && c.role == Role::radius) ||
                          (other.role == Role::axial_stretch && c.role == Role::green_strain_z) ||
                          (other.role == Role::green_strain_z && c.role == Role::axial_stretch);
        if (same)
          fail(data.header_line, f.column, f.text,
               "column '" + f.text + "' gives the same quantity as column '" + other.header + "'");
      }
      columns.push_back(c);
      break;
    }
  }
  auto find = [&](std::initializer_list<Role> roles) -> const Column* {
    for (const Column& c : columns)
      for (Role r : roles)
        if (c.role == r) return &c;
    return nullptr;
  };
  const Column* pressure = find({Role::pressure});
  const Column* size = find({Role::radius, Role::outer_diameter});
  const Column* force = find({Role::axial_force});
  const Column* stretch = find({Role::axial_stretch, Role::green_strain_z});
  auto missing = [&](const std::string& what, const std::string& example) {
    fail(data.header_line, 0, "",
         "missing column: " + what + " (e.g. '" + example + "'); the header has: " + all_headers);
  };
  if (!pressure) missing("pressure", "pressure_mmHg");
  if (!size) missing("outer diameter or mid-surface radius", "outer_diameter_mm' or 'radius_mm");
  if (!force) missing("axial force", "axial_force_N");

  // Specimen.
  if (!specimen_node)
    fail(data.header_line, 0, "specimen",
         "no specimen: add a line '# specimen: {outer_diameter: 1.648 mm, thickness: 0.122 mm, ends: open}' "
         "or give --specimen");
  data.specimen = read_specimen(*specimen_node);
  if (!stretch && !data.specimen.axial_stretch)
    missing("axial stretch (or give the specimen's `axial_stretch` for all rows)", "axial_stretch' or 'E_z");
  if (stretch && data.specimen.axial_stretch)
    throw InputError(specimen_node->where(), "the specimen's axial_stretch and the data column '" + stretch->header +
                                                 "' both give the axial stretch: keep one");
  data.size = size->role == Role::radius ? SizeMeasure::mid_radius : SizeMeasure::outer_diameter;
  data.pressure_unit = pressure->unit;
  data.force_unit = force->unit;
  data.length_unit = size->unit;

  // Row selection columns.
  std::vector<std::pair<int, double>> select;
  for (const auto& [name, value] : options.select) {
    int index = -1;
    for (std::size_t i = 0; i < header.size(); ++i)
      if (header[i].text == name) index = static_cast<int>(i);
    if (index < 0)
      fail(data.header_line, 0, "--select " + name,
           "no column '" + name + "' to select rows by; the header has: " + all_headers);
    select.emplace_back(index, value);
  }

  // Rows.
  auto cell = [&](int ln, const std::vector<Field>& fields, int index) {
    const Field& f = fields[index];
    const std::string& h = header[index].text;
    if (f.text.empty()) fail(ln, f.column, h, "empty cell");
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(f.text.c_str(), &end);
    if (*end != '\0') fail(ln, f.column, h, "'" + f.text + "' is not a number");
    if (!std::isfinite(v) || errno == ERANGE) fail(ln, f.column, h, "'" + f.text + "' is not a finite number");
    return v;
  };
  const TubeGeometry& g = data.specimen.geometry;
  std::vector<double> raw_pressure, raw_size;
  std::vector<int> size_char_column;
  for (const auto& [ln, fields] : rows) {
    if (fields.size() != header.size())
      fail(ln, 0, "",
           fmt::format("{} fields, but the header (line {}) has {} columns", fields.size(), data.header_line,
                       header.size()));
    bool keep = true;
    for (const auto& [index, value] : select) keep = keep && cell(ln, fields, index) == value;
    if (!keep) continue;
    InflationPoint pt;
    pt.line = ln;
    const double p_raw = cell(ln, fields, pressure->index);
    pt.pressure = p_raw * pressure->factor;
    pt.axial_force = cell(ln, fields, force->index) * force->factor;
    if (stretch) {
      const double v = cell(ln, fields, stretch->index) * stretch->factor;
      const Field& f = fields[stretch->index];
      if (stretch->role == Role::green_strain_z) {
        if (!(1.0 + 2.0 * v > 0))
          fail(ln, f.column, stretch->header,
               fmt::format("axial Green strain {:g} gives no positive stretch (need E_z > −1/2)", v));
        pt.lambda_z = std::sqrt(1.0 + 2.0 * v);  // E = ½(λ² − 1)
      } else {
        if (!(v > 0)) fail(ln, f.column, stretch->header, fmt::format("axial stretch {:g} is not positive", v));
        pt.lambda_z = v;
      }
    } else {
      pt.lambda_z = *data.specimen.axial_stretch;
    }
    const double s_raw = cell(ln, fields, size->index);
    const Field& sf = fields[size->index];
    pt.measured_size = s_raw * size->factor;
    if (!(pt.measured_size > 0))
      fail(ln, sf.column, size->header,
           fmt::format("{} {:g} is not positive (the hoop stretch would be {:g})", role_description(size->role), s_raw,
                       s_raw * size->factor / (size->role == Role::radius ? g.R : 2.0 * g.R + g.H)));
    if (size->role == Role::radius) {
      pt.mid_radius = pt.measured_size;
    } else {
      const auto r = mid_radius_from_outer_diameter(g, pt.measured_size, pt.lambda_z);
      if (!r)
        fail(ln, sf.column, size->header,
             fmt::format("outer diameter {:g} {} is too small for the wall at axial stretch {:g}: no mid-surface "
                         "radius r satisfies r + H R/(2 r λz) = D/2",
                         s_raw, size->unit, pt.lambda_z));
      pt.mid_radius = *r;
    }
    pt.lambda_theta = pt.mid_radius / g.R;
    data.points.push_back(pt);
    raw_pressure.push_back(p_raw);
    raw_size.push_back(s_raw);
    size_char_column.push_back(sf.column);
  }
  if (data.points.empty())
    fail(data.header_line, 0, "", options.select.empty() ? "no data rows" : "no data rows match --select");

  // Monotone hoop stretch: the rows of one axial-stretch level (consecutive rows with the
  // same λz) form one branch, loading or unloading: the size, hence λθ, never turns back.
  // (The pressure is not checked: its measurement noise may reverse small steps.)
  if (!options.allow_non_monotone) {
    int direction = 0;     // +1 widening, −1 narrowing, 0 not yet known
    std::size_t turn = 0;  // index of the row that set the direction
    for (std::size_t i = 1; i < data.points.size(); ++i) {
      const InflationPoint& a = data.points[i - 1];
      const InflationPoint& b = data.points[i];
      if (std::abs(b.lambda_z - a.lambda_z) > 1e-6 * a.lambda_z) {
        direction = 0;
        continue;
      }
      const double ds = raw_size[i] - raw_size[i - 1];
      const int d = ds > 0 ? 1 : ds < 0 ? -1 : 0;
      if (d == 0) continue;
      if (direction == 0) {
        direction = d;
        turn = i;
        continue;
      }
      if (d != direction) {
        const InflationPoint& t = data.points[turn];
        fail(b.line, size_char_column[i], size->header,
             fmt::format("non-monotone hoop stretch at axial stretch {:g}: the {} {} from line {} to {} "
                         "({:g} → {:g} {}) but {} from line {} to {} ({:g} → {:g} {}); the rows of one "
                         "axial-stretch level must form one loading (or unloading) branch — split cycles into "
                         "files, or pass --allow-non-monotone",
                         b.lambda_z, role_description(size->role), direction > 0 ? "rises" : "falls",
                         data.points[turn - 1].line, t.line, raw_size[turn - 1], raw_size[turn], size->unit,
                         d > 0 ? "rises" : "falls", a.line, b.line, raw_size[i - 1], raw_size[i], size->unit));
      }
    }
  }
  return data;
}

}  // namespace tunica
