#pragma once
// Two-node axisymmetric membrane element (theory manual §5, (5.1)–(5.4); the paper's element).
// Nodes carry (r, z); DOFs per element are (u_r1, u_z1, u_r2, u_z2).
// Direction 1 is the hoop direction, direction 2 the meridian. At each of the
// two Gauss points: λ_s = ℓ/L, λ_θ = r/R,
//   internal work  ∫ (S_s δE_s + S_θ δE_θ) H 2πR dS,
//   δE_s = Δx·Δη / L²,  δE_θ = r η_r / R².
#include <Eigen/Dense>
#include <array>

#include "elements/membrane_point.hpp"
#include "materials/membrane_material.hpp"

namespace tunica {

/// Nodal coordinates of a 2-node axisymmetric element: column a = (r_a, z_a).
using AxisymNodes = Eigen::Matrix2d;

/// Internal force f (4) and, if K is given, the tangent K = ∂f/∂u (4×4, material
/// + geometric) of one element with reference nodes X, current nodes x and
/// reference thickness H. `points`, if given, receives the Gauss-point states.
/// Throws std::domain_error if a stretch is not positive.
void axisym_membrane(const AxisymNodes& X, const AxisymNodes& x, double H, const MembraneMaterial& material,
                     Eigen::Vector4d& f, Eigen::Matrix4d* K, std::array<MembranePoint, 2>* points = nullptr);
/// The same with a reference thickness H[q] of its own at each Gauss point q (a reference computed
/// by an inverse step from an imaged thickness, theory manual (13.14)).
void axisym_membrane(const AxisymNodes& X, const AxisymNodes& x, const std::array<double, 2>& H,
                     const MembraneMaterial& material, Eigen::Vector4d& f, Eigen::Matrix4d* K,
                     std::array<MembranePoint, 2>* points = nullptr);
/// The hoop and meridian prestretch (P_θ, P_s) of a Gauss point (a prestress step, theory manual
/// (13.23)): the stress-free radius and length element are R/P_θ and dS/P_s.
using AxisymPrestretch = std::array<Eigen::Vector2d, 2>;
/// The same with a prestretch at each Gauss point q: λ_θ = P_θ r/R, λ_s = P_s ℓ/L, and the reference
/// volume element H[q] 2π (R/P_θ)(dS/P_s) (theory manual (13.23)).
void axisym_membrane(const AxisymNodes& X, const AxisymNodes& x, const std::array<double, 2>& H,
                     const AxisymPrestretch& prestretch, const MembraneMaterial& material, Eigen::Vector4d& f,
                     Eigen::Matrix4d* K, std::array<MembranePoint, 2>* points = nullptr);

}  // namespace tunica
