#include "io/meridian_checks.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

namespace tunica {

namespace {

/// A generated meridian that is wrong in a way an angle written without a unit explains
/// (`end_angle: 90` is 90 rad): if the mesh has such angles, the error stands at the first one's
/// key, says `what` it did and proposes the fix: the angle where the arc meets the axis if the
/// value lies within kNearAxisAngle of it and the meridian then stays at r ≥ 0; else degrees,
/// saying whether the meridian would then stay at r ≥ 0. Else it returns.
void fail_at_bare_angle(const DeckNode& mesh, const MeridianType& type, const Params& mp, const std::string& what) {
  std::vector<std::string> bare;  // angle keys given as plain numbers other than 0
  for (const ParamSpec& spec : type.spec.params) {
    double value = 0;
    std::string unit;
    if (spec.dim == Dimension::angle && mesh.has(spec.name) && mesh[spec.name].is_scalar() &&
        split_quantity(mesh[spec.name].as_string(), value, unit) && unit.empty() && value != 0)
      bare.push_back(spec.name);
  }
  if (bare.empty()) return;
  // Read in degrees instead, would the meridian stay at r ≥ 0?
  Params degrees = mp;
  for (const std::string& k : bare) {
    Params::Value v;
    v.nums = {mp.number(k) * std::numbers::pi / 180};
    v.written = mp.written(k);
    v.loc = mp.where(k);
    degrees.set(k, std::move(v));
  }
  bool fits = true;
  try {
    for (const Eigen::Vector2d& x : type.make(degrees)) fits = fits && x(0) >= 0;
  } catch (const std::exception&) {
    fits = false;
  }
  const std::string& key = bare.front();
  const std::string w = mp.written(key);
  // Read in radians, does the angle fall just short of or past one where the arc meets the axis
  // (1.571 for π/2)? Then the fix is that angle, not the number in degrees.
  std::string axis;
  if (mp.has("center") && mp.has("radius") && std::abs(mp.numbers("center")[0]) <= mp.number("radius")) {
    const double a = std::acos(-mp.numbers("center")[0] / mp.number("radius")), v = mp.number(key);
    const double on_axis = std::abs(v - a) <= std::abs(v + a) ? a : -a;
    Params snapped = mp;
    Params::Value x;
    x.nums = {on_axis};
    x.written = w;
    x.loc = mp.where(key);
    snapped.set(key, std::move(x));
    bool valid = std::abs(v - on_axis) <= kNearAxisAngle;
    try {
      for (const Eigen::Vector2d& p : type.make(snapped)) valid = valid && p(0) >= 0;
    } catch (const std::exception&) {
      valid = false;
    }
    if (valid)
      axis = fmt::format("to end on the axis write `{:.6g} deg` (or the angle in radians to more digits, `{:.10g}`)",
                         on_axis * 180 / std::numbers::pi, on_axis);
  }
  std::string others;
  for (std::size_t k = 1; k < bare.size(); ++k)
    others += fmt::format("{}`{} deg` for `{}`", others.empty() ? " (and " : ", ", mp.written(bare[k]), bare[k]);
  if (!others.empty()) others += ", also without a unit)";
  mesh[key].fail(fmt::format(
      "{} has no unit and is read in radians ({} rad = {:.4g} deg), which {}: a plain number is radians; {}{}", w, w,
      mp.number(key) * 180 / std::numbers::pi, what,
      !axis.empty() ? axis
      : fits        ? fmt::format("for degrees write `{} deg`", w)
                    : fmt::format("write the unit, e.g. `{} deg` (in degrees the meridian would still reach r < 0: check "
                         "`center` and `radius` too)",
                         w),
      others));
}

}  // namespace

void check_meridian(const DeckNode& mesh, const MeridianType& type, const Params& mp, const Meridian& points,
                    const UnitSystem& units) {
  if (mp.has("start_angle") && mp.has("end_angle")) {
    const double span = std::abs(mp.number("end_angle") - mp.number("start_angle")) * 180 / std::numbers::pi;
    if (span > 360 * (1 + 1e-9)) {
      fail_at_bare_angle(mesh, type, mp, fmt::format("makes the arc span {:.6g} deg, more than a full turn", span));
      mesh["end_angle"].fail(fmt::format("the arc spans {:.6g} deg, more than a full turn: its nodes would overlap "
                                         "(an arc from `start_angle` to `end_angle` covers at most 360 deg)",
                                         span));
    }
  }
  for (std::size_t i = 0; i < points.size(); ++i)
    if (points[i](0) < 0) {
      const std::string at =
          fmt::format("node {} at a negative radius r = {:g} {}", i, points[i](0), units.display_unit(Dimension::length));
      fail_at_bare_angle(mesh, type, mp, "puts " + at);
      mesh.fail(fmt::format("the meridian has {}: an axisymmetric meridian stays at r ≥ 0 (check `center`, `radius` "
                            "and the angles, or `from` and `to`)",
                            at));
    }
}


}  // namespace tunica
