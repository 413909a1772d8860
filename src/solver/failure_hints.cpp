#include "solver/failure_hints.hpp"

#include <fmt/format.h>

#include <cmath>

namespace tunica {

std::string failure_hints(const Model& model, const Step& step, const NewtonResult& last,
                          const std::vector<LoadState>& converged) {
  std::string hints;
  const auto add = [&](const std::string& h) { hints += " Hint: " + h; };
  if (last.failure.rfind("no convergence in", 0) == 0 && last.last_relative_residual < 1e-3)
    add(fmt::format("Newton was still converging when it reached the iteration limit (relative residual {:.1e}): "
                    "raise `max_iterations` in `solver` (now {}).",
                    last.last_relative_residual, step.solver.max_iterations));
  // A pressure the step raises, under pressure control, whose p–V curve flattens: theory manual §7.1.
  if (step.volume_control.load < 0 && converged.size() >= 3) {
    for (std::size_t l = 0; l < model.loads.size(); ++l) {
      const auto target = step.targets.find(model.loads[l].name);
      const LoadState& a = converged.front();
      if (target == step.targets.end() || std::abs(target->second) <= std::abs(a.pressure[l])) continue;
      const auto slope = [&](const LoadState& x, const LoadState& y) {
        const double dV = y.volume[l] - x.volume[l];
        return dV != 0 ? (y.pressure[l] - x.pressure[l]) / dV : 0.0;
      };
      const double first = slope(converged[0], converged[1]);
      const double now = slope(converged[converged.size() - 2], converged.back());
      if (first != 0 && now / first < 0.2)
        add(fmt::format("the pressure–volume curve of load '{}' has flattened over this step (dp/dV down to {:.0f} % of "
                        "its value at the step's start, at {:.4g} kPa = {:.4g} mmHg): the pressure is likely at a "
                        "maximum (a limit point), beyond which no state carries a higher pressure. A step with "
                        "`volume_control: {{load: {}, volume: <enclosed volume>}}` passes it, controlling the enclosed volume "
                        "instead (user guide §3.1, volume control).",
                        model.loads[l].name, 100 * now / first,
                        model.units.from_internal(converged.back().pressure[l], "kPa", Dimension::pressure),
                        model.units.from_internal(converged.back().pressure[l], "mmHg", Dimension::pressure),
                        model.loads[l].name));
    }
  }
  return hints;
}

}  // namespace tunica
