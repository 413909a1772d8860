#pragma once
// Stiffness of a fictitious membrane tension acting on the normal displacement only,
// used for the first Newton correction from a stress-free state (theory manual §7.2,
// (7.6)–(7.7); solver/tangent_hooks.hpp). With w = u·n the displacement along the reference normal n and T₀
// a tension (force per length), the quadratic
//     Q(u) = ½ T₀ ∫ ∇ₛw · ∇ₛw dA₀
// has the Hessian, per Gauss point q of the element,
//     K₀_ab = T₀ (w_q / H) (∂N_a/∂s · ∂N_b/∂s) n_q n_qᵀ              (3×3 block of nodes a, b),
// w_q / H the reference area weight (membrane3d.hpp stores Gauss weight × dA₀ × H).
// It is symmetric, positive semidefinite, zero for any rigid translation and for an in-plane
// displacement of a flat element, and zero for a uniform normal displacement of the element:
// it resists only the relative normal motion of the nodes (faceting, dimples), which a
// stress-free membrane resists with nothing but its facets' in-plane stiffness.
#include "elements/membrane3d.hpp"

namespace tunica {

/// K₀ of the element (3N × 3N, node-major DOFs), overwritten. Defined in start_tension_impl.hpp,
/// instantiated per shape (start_tension.cpp: N = 3, 4).
template <int N>
void normal_tension_stiffness(const MembraneReference<N>& ref, double T0, ElementMatrix<N>& K);

}  // namespace tunica
