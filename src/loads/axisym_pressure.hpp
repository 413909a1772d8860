#pragma once
// Follower pressure on a two-node axisymmetric membrane segment (theory manual §6,
// (6.1)–(6.2)).
// The pressure p acts on the current surface along n ds = (Δz, −Δr) dξ (the
// meridian direction turned clockwise: outward for a meridian that runs in +z
// or from the lower pole to the upper pole), on the revolved area 2πr ds:
//   f_a = 2π p (Δz, −Δr) ∫₀¹ N_a r dξ = 2π p (Δz, −Δr) m_a,
//   m_1 = r₁/3 + r₂/6,  m_2 = r₁/6 + r₂/3.
// Its derivative with respect to the nodal positions is the load stiffness,
// which is not symmetric.
#include <Eigen/Dense>

#include "elements/axisym_membrane.hpp"

namespace tunica {

/// External nodal force f (4) of pressure p on the current segment x and, if
/// dfdu is given, its derivative ∂f/∂u (4×4; the tangent gets −∂f/∂u).
void axisym_pressure(const AxisymNodes& x, double p, Eigen::Vector4d& f, Eigen::Matrix4d* dfdu);

}  // namespace tunica
