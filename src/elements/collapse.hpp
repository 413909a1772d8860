#pragma once
// The area stretch below which a membrane element counts as collapsed (theory manual §2: the wall
// thickness is h = H/(λ₁λ₂) for an incompressible wall): λ₁λ₂ < 10⁻³, a wall over a thousand times
// its reference thickness. A membrane carries no compression; under a pressure that pushes it
// inward (a pressure from outside, `flip: true`) it shrinks, and its follower pressure vanishes with
// its radius, so r → 0 would be a converged state of no physical meaning. The element kernels
// throw std::domain_error there: Newton backtracks, an increment that cannot avoid it is cut back.
#include <string>

namespace tunica {

inline constexpr double kCollapsedAreaStretch = 1e-3;

/// The message of a collapsed membrane element, `what` naming the element kind and the stretch.
inline std::string collapse_message(const std::string& what) {
  return what +
         ": the membrane collapsed (area stretch λ₁λ₂ below 1e-3, a wall over 1000 times its reference thickness). A "
         "membrane carries no compression: under a pressure that pushes it inward (from outside, or with `flip: "
         "true`) it shrinks towards the axis or a line, which is no state of the real wall (it would buckle or "
         "wrinkle)";
}

}  // namespace tunica
