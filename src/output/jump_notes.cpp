#include "output/jump_notes.hpp"

#include <fmt/format.h>

#include <cmath>

namespace tunica {

std::string volume_jump_note(const Model& m, int load, int step, const StepTrace& trace, const std::string& when) {
  if (trace.count() < 3 || step < 0 || step >= static_cast<int>(m.steps.size())) return "";
  if (m.steps[step].volume_control.load >= 0) return "";  // the step controls the volume
  const auto l = static_cast<std::size_t>(load);
  const LoadState &a = trace.last(2), &b = trace.last(1), &c = trace.last(0);
  if (l >= c.volume.size() || l >= c.pressure.size()) return "";
  const double dp1 = b.pressure[l] - a.pressure[l], dp2 = c.pressure[l] - b.pressure[l];
  const double dv1 = b.volume[l] - a.volume[l], dv2 = c.volume[l] - b.volume[l];
  if (!(dp1 * dp2 > 0) || !(b.volume[l] > 0) || !(c.volume[l] >= kVolumeJumpRatio * b.volume[l])) return "";
  const double before = dv1 / dp1, now = dv2 / dp2;
  if (!(now > 0) || !(now >= kComplianceJump * std::abs(before))) return "";
  const std::string vol = m.units.display_unit(Dimension::volume);
  const auto v = [&](double x) { return m.units.from_internal(x, vol, Dimension::volume); };
  const auto kpa = [&](double p) { return m.units.from_internal(p, "kPa", Dimension::pressure); };
  const std::string& name = m.loads[l].name;
  return fmt::format(
      "{}, the enclosed volume of load '{}' grew {:.3g}-fold in one increment ({:.4g} to {:.4g} {}) while the pressure "
      "went from {:.4g} to {:.4g} kPa, {:.3g} times the volume per pressure of the increment before: the increment "
      "either jumped across a maximum of the pressure onto a far branch of the pressure–volume curve (a snap-through "
      "of a material that stiffens, skipping the states between, as a membrane under pressure control does) or "
      "climbed the steep end of a curve that approaches an asymptote (a tube at fixed length). Volume control "
      "(`volume_control: {{load: {}, volume: ...}}`, user guide §3.1) follows the curve through either and shows "
      "which; if no such growth was expected, check the load's value and unit",
      when, name, c.volume[l] / b.volume[l], v(b.volume[l]), v(c.volume[l]), vol, kpa(b.pressure[l]),
      kpa(c.pressure[l]), now / std::abs(before), name);
}

std::string extreme_stretch_note(const Model& m, int part, const std::vector<MembranePoint>& points,
                                 const std::string& when) {
  double largest = 0, thickest = 0;
  int along = 0;  // the direction of the largest stretch: 0, e1; 1, e2
  const MembranePoint* at = nullptr;
  const MembranePoint* crushed = nullptr;
  for (const MembranePoint& p : points) {
    const int k = p.lambda(1) > p.lambda(0) ? 1 : 0;
    const double s = p.lambda(k);
    if (std::isfinite(s) && s > largest) largest = s, at = &p, along = k;
    if (std::isfinite(p.lambda(2)) && p.lambda(2) > thickest) thickest = p.lambda(2), crushed = &p;
  }
  const std::string len = m.units.display_unit(Dimension::length);
  const bool axisymmetric = m.dofs_per_node() != 3;
  const auto where = [&](const MembranePoint& p) {
    const auto l = [&](double x) { return m.units.from_internal(x, len, Dimension::length); };
    return axisymmetric ? fmt::format("at r = {:.4g} {}, z = {:.4g} {} (reference r = {:.4g} {})", l(p.x(0)), len,
                                      l(p.x(1)), len, l(p.X(0)), len)
                        : fmt::format("at ({:.4g}, {:.4g}, {:.4g}) {}", l(p.x(0)), l(p.x(1)), l(p.x(2)), len);
  };
  const std::string& name = m.parts[part].name;
  // Axisymmetric points: λ1 = r/R around the circumference, λ2 along the meridian.
  const auto direction = [&](const MembranePoint& p) {
    if (axisymmetric) return std::string(along == 0 ? "around the circumference (hoop)" : "along the meridian");
    const Eigen::Vector3d& e = along == 0 ? p.e1 : p.e2;
    return fmt::format("along its material direction {} (reference ({:.3g}, {:.3g}, {:.3g}))", along + 1, e(0), e(1),
                       e(2));
  };
  if (at && largest > kExtremeStretch)
    return fmt::format(
        "{}, part '{}' is stretched {:.3g}-fold {} {}, where arteries reach 2 to 3 and balloons rarely 6: a load or a "
        "boundary value (or its unit) is likely off, or an increment jumped across a maximum of the pressure onto a "
        "far branch of the curve (`volume_control` follows it, user guide §3.1). Check the step's values; results at "
        "such a stretch are those of the strain energy far outside where it was fitted",
        when, name, largest, direction(*at), where(*at));
  if (crushed && thickest > kExtremeStretch)
    return fmt::format(
        "{}, part '{}' is crushed {}: its thickness grew {:.3g}-fold, so its area shrank to 1/{:.3g} of the reference, "
        "which no membrane reaches (it would wrinkle or fold first). A boundary value likely moves nodes too far "
        "toward each other: check its size, sign and unit (a boundary value is the displacement from the reference, "
        "user guide §3.1)",
        when, name, where(*crushed), thickest, thickest);
  return "";
}

}  // namespace tunica
