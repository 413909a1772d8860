#include "assembly/volume_control_checks.hpp"

#include <fmt/format.h>

#include "assembly/pressure_load_checks.hpp"
#include "core/errors.hpp"

namespace tunica {

void check_volume_control_sides(const System& system) {
  const Model& m = system.model();
  const Eigen::VectorXd u0 = Eigen::VectorXd::Zero(system.num_dofs());
  const std::string unit = m.units.display_unit(Dimension::volume);
  for (std::size_t s = 0; s < m.steps.size(); ++s) {
    const VolumeControl& vc = m.steps[s].volume_control;
    if (vc.load < 0) continue;
    const PressureLoad& load = m.loads[vc.load];
    const Part& part = m.parts[load.part];
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
    for (int n : part.nodes) {
      lo = lo.cwiseMin(m.X[n]);
      hi = hi.cwiseMax(m.X[n]);
    }
    const double size = (hi - lo).norm();
    double V = 0;
    try {
      V = system.volume(u0, vc.load);
    } catch (const std::exception&) {
      continue;  // the mesh checks speak of an element that cannot be measured
    }
    if (!(V < -1e-9 * size * size * size)) continue;
    throw InputError(
        vc.where,
        fmt::format("step {} '{}' controls the volume of load '{}', which is {:.6g} {} at the reference state "
                    "(the volume on the side its pressure pushes away from), negative: {}. A volume target is "
                    "positive ({:.6g} {} here), so the run would take the enclosed volume through zero, turning "
                    "part '{}' inside out through itself. If the pressure acts from inside, {}: the volume is then "
                    "{:.6g} {}. A pressure from outside (pushing the surface in) cannot be volume-controlled.",
                    s + 1, m.steps[s].name, load.name, V, unit, inward_load_cause(load), vc.target, unit, part.name,
                    inward_load_fix(m, load), -V, unit));
  }
}

std::vector<std::string> volume_control_warnings(const System& system) {
  std::vector<std::string> out;
  const Model& m = system.model();
  const Eigen::VectorXd u0 = Eigen::VectorXd::Zero(system.num_dofs());
  const std::string unit = m.units.display_unit(Dimension::volume);
  const auto vol = [&](double v) { return m.units.from_internal(v, unit, Dimension::volume); };
  for (std::size_t s = 0; s < m.steps.size(); ++s) {
    const VolumeControl& vc = m.steps[s].volume_control;
    if (vc.load < 0) continue;
    double V0 = 0;
    try {
      V0 = system.volume(u0, vc.load);
    } catch (const std::exception&) {
      continue;
    }
    // A negative V₀ is check_volume_control_sides's error; a target within round-off of V₀ is none.
    if (!(V0 > 0) || !(vc.target < V0 * (1 - 1e-9))) continue;
    const PressureLoad& load = m.loads[vc.load];
    out.push_back(format_location(
        vc.where,
        fmt::format("step {} '{}' controls the volume of load '{}' to {:.6g} {}, below its stress-free volume, "
                    "{:.6g} {} (its enclosed volume at the reference state, as `volume` in history.csv reports it): "
                    "deflating a membrane below its rest volume needs a negative pressure (a suction) and "
                    "compresses it, and a real membrane wrinkles or buckles there, which Tunica does not model "
                    "(user guide §5, compression). To inflate, give `volume_control.volume` a value above {:.6g} {}",
                    s + 1, m.steps[s].name, load.name, vol(vc.target), unit, vol(V0), unit, vol(V0), unit)));
  }
  return out;
}

}  // namespace tunica
