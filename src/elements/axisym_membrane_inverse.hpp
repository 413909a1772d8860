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
void axisym_membrane_inverse(const AxisymNodes& X, const AxisymNodes& x, double H, const MembraneMaterial& material,
                             Eigen::Vector4d& f, Eigen::Matrix4d* KX);

}  // namespace tunica
