#include "model/solver_settings.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "linalg/linear_solver.hpp"

namespace tunica {

namespace {

/// A default as a deck would write it: 1e-09 → 1e-9, 1e+08 → 1e8.
std::string deck_number(double v) {
  std::string s = fmt::format("{:g}", v);
  for (const char* from : {"e-0", "e+0"}) {
    const auto at = s.find(from);
    if (at != std::string::npos) s.replace(at, 3, from[1] == '-' ? "e-" : "e");
  }
  return s;
}
std::string deck_bool(bool b) { return b ? "true" : "false"; }
std::string reuse_name(SolverSettings::FactorizationReuse r) {
  switch (r) {
    case SolverSettings::FactorizationReuse::never: return "never";
    case SolverSettings::FactorizationReuse::basin: return "basin";
    default: return "last";
  }
}

}  // namespace

const ComponentSpec& solver_settings_spec() {
  static const ComponentSpec spec = [] {
    const SolverSettings d;
    return ComponentSpec{
        "solver", "",
        "Newton–Raphson and increment control; at the top level for all steps, or inside a step for that step.",
        {with_default(at_least(integer("max_iterations", "Newton iterations allowed per increment"), 1),
                      std::to_string(d.max_iterations)),
         with_default(at_least(integer("max_iterations_contracting",
                                       "Newton goes on past `max_iterations`, up to this many iterations, while each of "
                                       "its last three iterations at least halved ‖R‖, each by a tenth more than the one before "
                                       "(converging slowly but surely is not cut back); at or below `max_iterations`: never"),
                               1),
                      std::to_string(d.max_iterations_contracting)),
         with_default(at_least(integer("stagnation_iterations",
                                       "an attempt stops as stagnating, and is cut back, when ‖R‖ has stayed within 10 % (neither "
                                       "falling nor climbing) over this many iterations; 0: never"),
                               0),
                      std::to_string(d.stagnation_iterations)),
         with_default(positive(number("residual_tolerance", Dimension::dimensionless,
                                      "convergence when ‖R‖ ≤ tol · ‖R₀‖ (R₀: residual at the start of the increment)")),
                      deck_number(d.residual_tolerance)),
         with_default(positive(number("energy_tolerance", Dimension::dimensionless,
                                      "and |Δu_k·R_k| ≤ tol · |Δu₁·R₀| (energy norm of the last correction against the residual it left; it scales as the cube of the correction, so 1e-12 leaves an error near 1e-8 of the increment)")),
                      deck_number(d.energy_tolerance)),
         with_default(at_most(positive(number("roundoff_tolerance", Dimension::dimensionless,
                                              "converged as well when ‖R‖ ≤ tol × the forces that cancel in R (the "
                                              "residual is then round-off, whatever ‖R₀‖ was)")),
                              1e-6),
                      deck_number(d.roundoff_tolerance)),
         with_default(one_of(text("reuse_factorization",
                                  "when a Newton correction is solved with the factorization of an earlier iteration "
                                  "of the increment instead of a new one (a modified Newton step): last = when that "
                                  "correction is predicted to converge (twice the last ratio ‖R_k‖/‖R_k−1‖ times "
                                  "‖R_k‖ within `residual_tolerance`), which saves a factorization, mostly without adding an "
                                  "iteration (when the prediction misses, the next iteration factorizes); basin = whenever ‖R‖ ≤ 1e-4 ‖R₀‖ and the last correction cut ‖R‖ "
                                  "tenfold, fewer factorizations for an iteration or two more (large models, where "
                                  "the factorization is the iteration); never = a new factorization every iteration "
                                  "(the plain Newton method, quadratic to the end). No correction that leads to the last "
                                  "iteration `max_iterations` allows is solved with an earlier factorization"),
                             {"last", "basin", "never"}),
                      reuse_name(d.reuse_factorization)),
         with_default(at_least(number("divergence_ratio", Dimension::dimensionless,
                                      "an attempt stops as diverging when ‖R‖ exceeds this multiple of ‖R₀‖ (and is cut back)"),
                               1.0),
                      deck_number(d.divergence_ratio)),
         with_default(at_most(at_least(integer("max_cutbacks", "times an increment may be halved and retried"), 0), 30),
                      std::to_string(d.max_cutbacks)),
         with_default(boolean("line_search", "halve a Newton correction that raises ‖R‖ or inverts an element, up to "
                                             "`line_search_halvings` times (never under volume control)"),
                      deck_bool(d.line_search)),
         with_default(at_most(at_least(integer("line_search_halvings", "most halvings of one Newton correction by the line search"), 1), 50),
                      std::to_string(d.line_search_halvings)),
         with_default(one_of(text("linear_solver", "the linear solver of each Newton correction: " + linear_solver_docs()), linear_solver_names()),
                      d.linear_solver),
         with_default(one_of(text("predictor",
                                  "first iteration of an increment whose prescribed displacements move: tangent = "
                                  "solve K(u_n) Δu = −R(u_n) − K_fp Δu_p at the last converged state (the prescribed "
                                  "increment applied linearly, Newton then as usual); none = start from u_n with the "
                                  "new prescribed values"),
                             {"tangent", "none"}),
                      d.tangent_predictor ? "tangent" : "none"),
         with_default(one_of(text("stress_free_start",
                                  "first correction of an increment that starts at the stress-free reference state "
                                  "under pressure or volume control: stiffened = its tangent gets the normal-tension "
                                  "stiffness of the Laplace estimate T0 = |p|/|H| on every pressurized membrane "
                                  "element, p under volume control the pressure the stiffened correction finds (the "
                                  "Newton direction changes, not the solution); exact = the plain tangent"),
                             {"stiffened", "exact"}),
                      d.stiffen_stress_free_start ? "stiffened" : "exact"),
         with_default(one_of(text("pressure_stiffness",
                                  "follower-pressure load stiffness: exact (consistent, quadratic Newton) or "
                                  "symmetrized, (K + Kᵀ)/2, which CHOLMOD can factorize (ignored under volume control)"),
                             {"exact", "symmetrized"}),
                      d.symmetrize_pressure_stiffness ? "symmetrized" : "exact")}};
  }();
  return spec;
}

void set_solver_setting(SolverSettings& s, const std::string& key, const Params& p) {
  if (key == "max_iterations") s.max_iterations = static_cast<int>(p.integer(key));
  else if (key == "max_iterations_contracting") s.max_iterations_contracting = static_cast<int>(p.integer(key));
  else if (key == "stagnation_iterations") s.stagnation_iterations = static_cast<int>(p.integer(key));
  else if (key == "residual_tolerance") s.residual_tolerance = p.number(key);
  else if (key == "energy_tolerance") s.energy_tolerance = p.number(key);
  else if (key == "roundoff_tolerance") s.roundoff_tolerance = p.number(key);
  else if (key == "reuse_factorization") {
    const std::string v = p.text(key);
    s.reuse_factorization = v == "never"   ? SolverSettings::FactorizationReuse::never
                            : v == "basin" ? SolverSettings::FactorizationReuse::basin
                                           : SolverSettings::FactorizationReuse::last;
  }
  else if (key == "divergence_ratio") s.divergence_ratio = p.number(key);
  else if (key == "max_cutbacks") s.max_cutbacks = static_cast<int>(p.integer(key));
  else if (key == "line_search") s.line_search = p.boolean(key);
  else if (key == "line_search_halvings") s.line_search_halvings = static_cast<int>(p.integer(key));
  else if (key == "linear_solver") s.linear_solver = p.text(key);
  else if (key == "predictor") s.tangent_predictor = p.text(key) == "tangent";
  else if (key == "stress_free_start") s.stiffen_stress_free_start = p.text(key) == "stiffened";
  else if (key == "pressure_stiffness") s.symmetrize_pressure_stiffness = p.text(key) == "symmetrized";
  else throw std::logic_error("solver setting '" + key + "' is not declared");
}

}  // namespace tunica
