#include "solver/shell_fold_hint.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "model/node_label.hpp"

namespace tunica {

std::string shell_fold_hint(const System& system, const Eigen::VectorXd& u, int step, const std::string& failure) {
  const Model& m = system.model();
  const bool folded = failure.find("folded through its thickness") != std::string::npos;
  // The shell point bent furthest through its thickness at the last converged state.
  double worst = 0;
  int part = -1;
  Eigen::Vector3d where = Eigen::Vector3d::Zero(), where_now = where;
  for (int p = 0; p < static_cast<int>(m.parts.size()); ++p) {
    if (!m.parts[p].is_shell()) continue;
    const double H = m.parts[p].thickness;
    for (const MembranePoint& q : system.points(u, p, step)) {
      const double thickening = q.thickness * q.lambda(0) * q.lambda(1) / H;
      if (std::isfinite(thickening) && thickening > worst) worst = thickening, part = p, where = q.X, where_now = q.x;
    }
  }
  if (part < 0 || (!folded && worst < kFoldThickening)) return "";
  // The part's node nearest to it, and the nearest node a boundary holds a slope at (a clamp).
  const Part& shell = m.parts[part];
  int nearest = -1, clamp = -1, clamped = -1;
  double best = std::numeric_limits<double>::infinity(), best_clamp = best;
  for (int n : shell.nodes) {
    const double d = (m.X[n] - where).norm();
    if (d < best) best = d, nearest = n;
  }
  for (int b = 0; b < static_cast<int>(m.boundaries.size()); ++b) {
    const Boundary& bc = m.boundaries[b];
    bool slope = false;
    for (int d : bc.dofs) slope = slope || d >= 2;
    if (!slope) continue;
    for (int n : m.node_sets[bc.node_set].nodes) {
      const double d = (m.X[n] - where).norm();
      if (d < best_clamp) best_clamp = d, clamp = b, clamped = n;
    }
  }
  const std::string len = m.units.display_unit(Dimension::length);
  const auto in_len = [&](double x) { return m.units.from_internal(x, len, Dimension::length); };
  const std::string at = fmt::format("near {} (reference r = {:.4g} {}, z = {:.4g} {}; now r = {:.4g} {}, z = {:.4g} {})",
                                     node_label(m, nearest), in_len(where(0)), len, in_len(where(1)), len,
                                     in_len(where_now(0)), len, in_len(where_now(1)), len);
  std::string out =
      worst >= kFoldThickening
          ? fmt::format("{}at the last converged state part '{}' is bent through its thickness {}: the current "
                        "thickness there is {:.3g} times what its mid-surface's stretches give, 1 in a membrane state.",
                        folded ? "the failed attempt folded the shell through its thickness, and " : "", shell.name,
                        at, worst)
          : fmt::format("the failed attempt folded the shell through its thickness (the element named above); at the "
                        "last converged state part '{}' was bent most {}, where the current thickness is {:.3g} times "
                        "what its mid-surface's stretches give (1 in a membrane state).",
                        shell.name, at, worst);
  out += " A wall that bends over a length shorter than it is thick folds its concave layers, and a Kirchhoff–Love "
         "shell no longer describes it (theory manual §11); more iterations, smaller increments or a finer mesh "
         "(which folds earlier) do not pass it.";
  // A clamp within a few thicknesses of it: the slope it holds forces the bend.
  if (clamp >= 0 && best_clamp <= 5 * shell.thickness + best) {
    const Boundary& bc = m.boundaries[clamp];
    std::string held;
    static const char* names[] = {"r", "z", "slope_r", "slope_z"};
    for (int d : bc.dofs) held += std::string(held.empty() ? "" : ", ") + (d >= 0 && d < 4 ? names[d] : "?");
    out += fmt::format(
        " Boundary '{}' holds [{}] at {}: a clamped end under a membrane tension that is large against the bending "
        "stiffness turns the wall within a bending length √(D/N) shorter than its thickness. Hold only r and z there "
        "(a hinged end, as a membrane's), or model the end region with `element: axisymmetric_solid`, or raise the "
        "load only as far as the clamp allows.",
        bc.name, held, node_label(m, clamped));
  } else {
    out += " Refine the load path (a smaller pressure or a milder shape change there), or model that region with "
           "`element: axisymmetric_solid`.";
  }
  return out;
}

}  // namespace tunica
