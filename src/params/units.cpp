#include "params/units.hpp"

#include <udunits2.h>

#include "core/article.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>

namespace tunica {

namespace {

/// The UDUNITS-2 unit database, read once per process.
ut_system* unit_database() {
  static ut_system* sys = [] {
    ut_set_error_message_handler(ut_ignore);
    ut_system* s = ut_read_xml(nullptr);
    if (!s) throw std::runtime_error("cannot read the UDUNITS-2 unit database (package libudunits2-data)");
    // "deg" is the usual abbreviation of the arc degree, which UDUNITS-2 spells "degree" or "°".
    if (ut_unit* degree = ut_parse(s, "degree", UT_ASCII)) {
      ut_map_symbol_to_unit("deg", UT_ASCII, degree);
      ut_free(degree);
    }
    return s;
  }();
  return sys;
}

struct UnitDeleter {
  void operator()(ut_unit* u) const { ut_free(u); }
};
using UnitPtr = std::unique_ptr<ut_unit, UnitDeleter>;

UnitPtr parse_unit(const std::string& text) {
  static std::mutex m;
  std::lock_guard<std::mutex> lock(m);
  UnitPtr u(ut_parse(unit_database(), text.c_str(), UT_UTF8));
  if (!u) throw std::invalid_argument("unknown unit '" + text + "'");
  return u;
}

/// Converts `value` from unit `from` to unit `to`. The converters of the pairs met are kept
/// (at most kMaxCachedConverters), so that the units of the history columns, converted after
/// every increment, are parsed once per run and not once per value.
double convert(double value, const std::string& from, const std::string& to, const char* what) {
  constexpr std::size_t kMaxCachedConverters = 256;
  struct Cache {
    std::map<std::pair<std::string, std::string>, cv_converter*> converters;
    ~Cache() {
      for (auto& [key, cv] : converters) cv_free(cv);
    }
  };
  static std::mutex m;
  static Cache cache_store;
  auto& cache = cache_store.converters;
  const auto key = std::make_pair(from, to);
  {
    std::lock_guard<std::mutex> lock(m);
    if (auto it = cache.find(key); it != cache.end()) return cv_convert_double(it->second, value);
  }
  UnitPtr a = parse_unit(from), b = parse_unit(to);
  cv_converter* cv = ut_get_converter(a.get(), b.get());
  if (!cv) throw std::invalid_argument("unit '" + from + "' is not " + with_article(what));
  const double r = cv_convert_double(cv, value);
  {
    std::lock_guard<std::mutex> lock(m);
    if (cache.size() < kMaxCachedConverters && cache.emplace(key, cv).second) return r;
  }
  cv_free(cv);
  return r;
}

}  // namespace

const char* dimension_name(Dimension d) {
  switch (d) {
    case Dimension::dimensionless: return "dimensionless number";
    case Dimension::length: return "length";
    case Dimension::force: return "force";
    case Dimension::pressure: return "pressure (stress)";
    case Dimension::angle: return "angle";
    case Dimension::volume: return "volume";
    case Dimension::penalty: return "pressure per length";
    case Dimension::moment: return "moment (force × length)";
  }
  return "?";
}

UnitSystem::UnitSystem(const std::string& length, const std::string& force) : length_(length), force_(force) {
  check_unit(length_, Dimension::length);
  check_unit(force_, Dimension::force);
}

std::string UnitSystem::display_unit(Dimension d) const {
  switch (d) {
    case Dimension::length: return length_;
    case Dimension::force: return force_;
    case Dimension::pressure: return force_ + "/" + length_ + "²";
    case Dimension::angle: return "rad";
    case Dimension::volume: return length_ + "³";
    case Dimension::penalty: return force_ + "/" + length_ + "³";
    case Dimension::moment: return force_ + "·" + length_;
    case Dimension::dimensionless: return "";
  }
  return "";
}

std::string UnitSystem::internal_unit(Dimension d) const {
  switch (d) {
    case Dimension::dimensionless: return "1";
    case Dimension::length: return length_;
    case Dimension::force: return force_;
    case Dimension::pressure: return "(" + force_ + ")/(" + length_ + ")^2";
    case Dimension::angle: return "rad";
    case Dimension::volume: return "(" + length_ + ")^3";
    case Dimension::penalty: return "(" + force_ + ")/(" + length_ + ")^3";
    case Dimension::moment: return "(" + force_ + ")*(" + length_ + ")";
  }
  return "1";
}

void UnitSystem::check_unit(const std::string& unit, Dimension d) const {
  const char* reference = d == Dimension::length ? "m"
                          : d == Dimension::force ? "N"
                          : d == Dimension::pressure ? "Pa"
                          : d == Dimension::angle ? "rad"
                          : d == Dimension::volume ? "m^3"
                          : d == Dimension::penalty ? "Pa/m"
                          : d == Dimension::moment ? "N*m"
                                                  : "1";
  convert(1.0, unit, reference, dimension_name(d));
}

double UnitSystem::to_internal(double value, const std::string& unit, Dimension d) const {
  if (unit.empty()) return value;
  return convert(value, unit, internal_unit(d), dimension_name(d));
}

double UnitSystem::from_internal(double value, const std::string& unit, Dimension d) const {
  if (unit.empty()) return value;
  return convert(value, internal_unit(d), unit, dimension_name(d));
}

bool is_unit(const std::string& text) {
  try {
    parse_unit(text);
    return true;
  } catch (const std::invalid_argument&) {
    return false;
  }
}

std::string unit_suffix(const UnitSystem& units, Dimension d, const std::string& unit) {
  if (d == Dimension::dimensionless) return "";
  std::string u = unit;
  if (u.empty())
    u = d == Dimension::pressure ? units.force_unit() + "_per_" + units.length_unit() + "2"
        : d == Dimension::volume ? units.length_unit() + "3"
        : d == Dimension::penalty ? units.force_unit() + "_per_" + units.length_unit() + "3"
        : d == Dimension::moment ? units.force_unit() + "_" + units.length_unit()
                                 : units.internal_unit(d);
  std::string out;
  for (char c : u) {
    if (c == '^') continue;  // mm^3 → mm3
    out += (c == '/' || c == ' ' || c == '(' || c == ')' || c == '*' || c == '.') ? '_' : c;
  }
  return "_" + out;
}

bool split_quantity(const std::string& text, double& value, std::string& unit) {
  const char* begin = text.c_str();
  while (*begin == ' ' || *begin == '\t') ++begin;
  char* end = nullptr;
  errno = 0;
  value = std::strtod(begin, &end);
  if (end == begin || errno == ERANGE || !std::isfinite(value)) return false;
  std::string rest(end);
  auto first = rest.find_first_not_of(" \t");
  auto last = rest.find_last_not_of(" \t");
  unit = first == std::string::npos ? std::string() : rest.substr(first, last - first + 1);
  return true;
}

}  // namespace tunica
