#include "fit/synthetic_data.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <random>
#include <sstream>

namespace tunica {

namespace {

/// Standard normal deviates: Box–Muller on 53-bit uniforms of std::mt19937_64
/// (both fully specified by the standard, so the data are the same everywhere).
class NormalDeviates {
public:
  explicit NormalDeviates(std::uint64_t seed) : rng_(seed) {}
  double next() {
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    const double u1 = (static_cast<double>(rng_() >> 11) + 1.0) * 0x1.0p-53;  // (0, 1]
    const double u2 = static_cast<double>(rng_() >> 11) * 0x1.0p-53;          // [0, 1)
    const double rho = std::sqrt(-2.0 * std::log(u1));
    spare_ = rho * std::sin(2.0 * std::numbers::pi * u2);
    has_spare_ = true;
    return rho * std::cos(2.0 * std::numbers::pi * u2);
  }

private:
  std::mt19937_64 rng_;
  double spare_ = 0;
  bool has_spare_ = false;
};

}  // namespace

InflationData synthesize_inflation_data(const MembraneMaterial& material, const Specimen& specimen,
                                        const std::vector<double>& axial_stretches,
                                        const std::vector<double>& pressures, SizeMeasure size,
                                        const NoiseLevels& noise, std::uint64_t seed) {
  InflationData data;
  data.file = "<synthetic>";
  data.specimen = specimen;
  data.specimen.axial_stretch.reset();
  data.size = size;
  // The internal units of an mm–N system, for reports.
  data.pressure_unit = std::string("MPa");
  data.force_unit = std::string("N");
  data.length_unit = std::string("mm");
  const TubeGeometry& g = specimen.geometry;
  std::vector<TubeState> truth;
  double p_max = 0, f_max = 0, s_max = 0;
  for (double lz : axial_stretches)
    for (double p : pressures) {
      const TubeState s = tube_state(material, g, hoop_stretch_at_pressure(material, g, p, lz), lz);
      truth.push_back(s);
      p_max = std::max(p_max, std::abs(s.pressure));
      f_max = std::max(f_max, std::abs(s.axial_force));
      s_max = std::max(s_max, size == SizeMeasure::mid_radius ? s.r : s.outer_diameter);
    }
  NormalDeviates normal(seed);
  int line = 0;
  for (const TubeState& s : truth) {
    const double ep = normal.next(), es = normal.next(), ef = normal.next();
    InflationPoint pt;
    pt.line = ++line;
    pt.lambda_z = s.lambda_z;
    pt.pressure = s.pressure + noise.pressure * p_max * ep;
    pt.axial_force = s.axial_force + noise.axial_force * f_max * ef;
    pt.measured_size = (size == SizeMeasure::mid_radius ? s.r : s.outer_diameter) + noise.size * s_max * es;
    pt.mid_radius = size == SizeMeasure::mid_radius
                        ? pt.measured_size
                        : mid_radius_from_outer_diameter(g, pt.measured_size, pt.lambda_z).value_or(s.r);
    pt.lambda_theta = pt.mid_radius / g.R;
    data.points.push_back(pt);
  }
  return data;
}

std::string inflation_data_csv(const InflationData& data, const std::string& comment, const std::string& pressure_unit,
                               const std::string& force_unit, const std::string& length_unit) {
  const UnitSystem u("mm", "N");
  const TubeGeometry& g = data.specimen.geometry;
  std::ostringstream s;
  std::istringstream lines(comment);
  for (std::string l; std::getline(lines, l);) s << "# " << l << "\n";
  const bool radius = data.size == SizeMeasure::mid_radius;
  const double L = u.from_internal(1.0, length_unit, Dimension::length);
  s << fmt::format("# specimen: {{{}: {:.10g} {}, thickness: {:.10g} {}, ends: {}}}\n",
                   radius ? "radius" : "outer_diameter", (radius ? g.R : 2.0 * g.R + g.H) * L, length_unit, g.H * L,
                   length_unit, tube_ends_name(g.ends));
  s << fmt::format("axial_stretch,pressure_{},{}_{},axial_force_{}\n", pressure_unit,
                   radius ? "radius" : "outer_diameter", length_unit, force_unit);
  const double P = u.from_internal(1.0, pressure_unit, Dimension::pressure);
  const double F = u.from_internal(1.0, force_unit, Dimension::force);
  for (const InflationPoint& pt : data.points)
    s << fmt::format("{:.10g},{:.10g},{:.10g},{:.10g}\n", pt.lambda_z, pt.pressure * P, pt.measured_size * L,
                     pt.axial_force * F);
  return s.str();
}

const ComponentSpec& synthesis_plan_spec() {
  static const ComponentSpec s{
      "synthesis plan",
      "",
      "A plan for `tunica synthesize`: besides these keys, a `specimen` map (as in a data file) and a "
      "`material` map (as in a deck's `materials`, with its `type`).",
      {text("comment", "text put at the top of the CSV as `#` comments"),
       with_default(at_least(integer("seed", "seed of the noise generator"), 0), "1"),
       required(numbers("axial_stretches", Dimension::dimensionless, 0, "axial stretch levels λz")),
       with_default(number("pressure_min", Dimension::pressure, "first pressure of every level"), "0"),
       required(number("pressure_max", Dimension::pressure, "last pressure of every level")),
       required(positive(number("pressure_step", Dimension::pressure, "pressure increment"))),
       with_default(at_least(number("noise_pressure", Dimension::dimensionless,
                                    "noise standard deviation of the pressure, fraction of its full scale"),
                             0.0),
                    "0"),
       with_default(at_least(number("noise_axial_force", Dimension::dimensionless,
                                    "noise standard deviation of the axial force, fraction of its full scale"),
                             0.0),
                    "0"),
       with_default(at_least(number("noise_size", Dimension::dimensionless,
                                    "noise standard deviation of the diameter or radius, fraction of its full scale"),
                             0.0),
                    "0"),
       with_default(one_of(text("size", "what the data give"), {"outer_diameter", "radius"}), "outer_diameter"),
       with_default(text("pressure_unit", "unit of the pressure column"), "mmHg"),
       with_default(text("force_unit", "unit of the axial force column"), "N"),
       with_default(text("length_unit", "unit of the size column"), "mm")}};
  return s;
}

std::string synthesize_from_plan(const std::string& plan_path) {
  YAML::Node root;
  try {
    root = YAML::LoadFile(plan_path);
  } catch (const YAML::BadFile&) {
    throw InputError({plan_path, 0, 0, ""}, "cannot open the plan file");
  } catch (const YAML::Exception& e) {
    throw InputError({plan_path, e.mark.is_null() ? 0 : e.mark.line + 1, e.mark.is_null() ? 0 : e.mark.column + 1, ""},
                     "YAML syntax error: " + e.msg);
  }
  const DeckNode plan(root, plan_path, "", {plan_path, 1, 1, ""});
  const UnitSystem units("mm", "N");
  const Params p = read_params(plan, synthesis_plan_spec(), units, {"specimen", "material"});
  const Specimen specimen = read_specimen(plan.required("specimen"));

  const DeckNode mat = plan.required("material");
  if (!mat.is_map()) mat.fail("expected a material map with `type` and the model's constants");
  const std::string type = mat.required("type").as_string();
  const auto t = material_types().find(type);
  if (t == material_types().end()) mat["type"].fail("unknown material type '" + type + "'");
  const auto material = t->second.make(read_params(mat, t->second.spec, units, {"type"}));

  for (const char* key : {"pressure_unit", "force_unit", "length_unit"}) {
    const Dimension d = key[0] == 'p' ? Dimension::pressure : key[0] == 'f' ? Dimension::force : Dimension::length;
    try {
      units.check_unit(p.text(key), d);
    } catch (const std::invalid_argument& e) {
      p.fail(key, e.what());
    }
  }
  std::vector<double> pressures;
  const double p0 = p.number("pressure_min"), p1 = p.number("pressure_max"), dp = p.number("pressure_step");
  if (p1 < p0) p.fail("pressure_max", "pressure_max is below pressure_min");
  for (int i = 0; p0 + i * dp <= p1 * (1 + 1e-12) + 1e-300; ++i) pressures.push_back(p0 + i * dp);
  for (double lz : p.numbers("axial_stretches"))
    if (!(lz > 0)) p.fail("axial_stretches", fmt::format("axial stretch {:g} is not positive", lz));
  const NoiseLevels noise{p.number("noise_pressure"), p.number("noise_axial_force"), p.number("noise_size")};
  const InflationData data =
      synthesize_inflation_data(*material, specimen, p.numbers("axial_stretches"), pressures,
                                p.text("size") == "radius" ? SizeMeasure::mid_radius : SizeMeasure::outer_diameter,
                                noise, static_cast<std::uint64_t>(p.integer("seed")));
  std::string constants;
  for (const auto& [key, value] : mat.entries())
    if (key != "type") constants += (constants.empty() ? "" : ", ") + key + " = " + value.as_string();
  std::string comment = p.has("comment") ? p.text("comment") + "\n" : std::string();
  comment += fmt::format(
      "made by `tunica synthesize {}`\ntrue material: {} with {}\nnoise (standard deviation, "
      "fraction of full scale): pressure {:g}, axial force {:g}, size {:g}; seed {}",
      plan_path, type, constants, noise.pressure, noise.axial_force, noise.size, p.integer("seed"));
  return inflation_data_csv(data, comment, p.text("pressure_unit"), p.text("force_unit"), p.text("length_unit"));
}

}  // namespace tunica
