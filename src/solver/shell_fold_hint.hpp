#pragma once
// The hint of a failure in an axisymmetric shell bent through its thickness: a bending layer
// shorter than the wall is thick (theory manual §11), typically at a clamped end under a membrane
// tension large against the bending stiffness, where the concave layers fold.
#include <string>

#include <Eigen/Dense>

#include "assembly/system.hpp"

namespace tunica {

/// A shell Gauss point counts as bent through its thickness when its current thickness
/// h = ∫ dζ / (λ_θ(ζ) λ_s(ζ)) (elements/shell_output.hpp) exceeds that of its mid-surface's
/// stretches, H / (λ_θ λ_s), by this factor: 1 in a membrane state, growing without bound as a
/// layer's stretch goes to zero (1.5 when the concave surface's stretch is about a fifth of the
/// mid-surface's).
constexpr double kFoldThickening = 1.5;

/// Empty, or the hint for a failure of step `step` (0-based) whose message `failure` says a shell
/// folded through its thickness, or whose last converged state `u` has an axisymmetric shell
/// point bent through its thickness (kFoldThickening): where (the part, the nearest node, r and z),
/// how far, the boundary holding a slope nearest to it if one does (a clamp), and the fixes:
/// release the slope (a hinge) or model the region as a solid; more iterations, smaller
/// increments or a finer mesh do not pass it.
std::string shell_fold_hint(const System& system, const Eigen::VectorXd& u, int step, const std::string& failure);

}  // namespace tunica
