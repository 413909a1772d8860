#pragma once
// The 2-node axisymmetric membrane of the inverse problem (theory manual §13): the imaged
// (current) nodes x are known, the reference nodes X the unknowns. The residual is the forward
// element's (axisym_membrane.hpp, (5.1)–(5.4)), so that forward and inverse solve the same
// discrete equations; the tangent is its exact derivative ∂f/∂X, (13.7).
#include "elements/axisym_membrane.hpp"

namespace tunica {

/// Internal force f(X, x) (4) = axisym_membrane(X, x, H) and, if KX is given, KX = ∂f/∂X (4×4,
/// columns (R₁, Z₁, R₂, Z₂); not symmetric). Throws std::domain_error where axisym_membrane() does,
/// and for a reference element of zero length or a non-positive reference radius.
/// With `imaged` (the wall thickness h_q of the imaged state x at each Gauss point; H unused), each
/// Gauss point's reference thickness is H_q = h_q λ_s λ_θ = h_q (ℓ/L)(r_q/R_q) (theory manual
/// (13.12)): the weight H_q dA₀ = h_q da then does not depend on X, (13.13). `points`, if given,
/// receives the Gauss-point states.
void axisym_membrane_inverse(const AxisymNodes& X, const AxisymNodes& x, double H, const MembraneMaterial& material,
                             Eigen::Vector4d& f, Eigen::Matrix4d* KX, const std::array<double, 2>* imaged = nullptr,
                             std::array<MembranePoint, 2>* points = nullptr);

}  // namespace tunica
