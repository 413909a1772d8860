#pragma once
// Newton–Raphson and increment control (theory manual §7): the settings, their defaults (the
// member initializers below, the only place they are written) and their declaration for
// decks and the deck reference (`solver` at the top level and inside a step).
#include <string>

#include "params/param_spec.hpp"
#include "params/params.hpp"

namespace tunica {

struct SolverSettings {
  int max_iterations = 12;
  /// Newton goes on past max_iterations, up to this many, while each of its last three
  /// iterations at least halved ‖R‖, each by a tenth more than the one before (converging slowly but
  /// surely: no cut-back), (7.2).
  int max_iterations_contracting = 30;
  /// An attempt stops as stagnating (and is cut back) when ‖R‖ has stayed within 10 % over
  /// this many iterations; 0: never.
  int stagnation_iterations = 5;
  double residual_tolerance = 1e-9;  ///< on ‖R‖/‖R₀‖, (7.2)
  double energy_tolerance = 1e-12;   ///< on |Δu·R| relative to the first iteration, (7.2)
  /// ‖R‖ at or below this fraction of the force scale (the forces that cancel in R) is round-off:
  /// converged whatever the relative tests say.
  double roundoff_tolerance = 1e-14;
  /// When a correction is solved with the factorization of an earlier iteration of the attempt,
  /// (7.11): never; `last`, when that correction is predicted to converge (2ρ_k ‖R_k‖ ≤ tol_r ‖R₀‖, ρ_k
  /// the last ratio); `basin`, whenever ‖R_k‖ ≤ 10⁻⁴ ‖R₀‖ and ρ_k ≤ 0.1.
  enum class FactorizationReuse { never, last, basin };
  FactorizationReuse reuse_factorization = FactorizationReuse::last;
  double divergence_ratio = 1e8;     ///< ‖R‖ above this multiple of ‖R₀‖ stops the attempt as diverging
  int max_cutbacks = 5;
  bool line_search = true;           ///< halve a correction that raises ‖R‖, (7.4)
  int line_search_halvings = 8;      ///< at most this many halvings of one correction
  std::string linear_solver = "auto";  ///< a name of linalg/linear_solver.hpp's registry
  /// The follower-pressure load stiffness as derived (exact, quadratic Newton) or
  /// symmetrized, K ← (K + Kᵀ)/2, so that CHOLMOD can factorize it.
  bool symmetrize_pressure_stiffness = false;
  /// When prescribed displacements move: the first iteration linearizes their increment at the
  /// last converged state, (7.3), instead of starting from it with the new values.
  bool tangent_predictor = true;
  /// The first correction of an increment that starts at the stress-free reference state adds the
  /// normal-tension stiffness of a Laplace tension estimate to its tangent, (7.6)–(7.8).
  bool stiffen_stress_free_start = true;
};

/// The declaration of the `solver` keys, with the defaults of SolverSettings{}.
const ComponentSpec& solver_settings_spec();

/// Sets the member of `s` that the key `key` of `solver_settings_spec()` names from `p` (read
/// against that spec); std::logic_error for a key the spec does not declare.
void set_solver_setting(SolverSettings& s, const std::string& key, const Params& p);

}  // namespace tunica
