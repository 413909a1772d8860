#pragma once
// Output quantities of an axisymmetric shell at a meridian Gauss point
// (elements/axisym_shell.hpp), as a MembranePoint so that histories and ParaView
// treat shells like membranes. Through the current thickness, with
// dη = dζ / (λ_θ(ζ) λ_s(ζ)) (incompressible layers, exact in the kernel's
// kinematics) and the thickness Gauss points ζ_k, w_k:
//   h   = ∫ dη                     (current thickness),
//   N_α = ∫ σ_α dη                 (stress resultants, force per current length),
//   M_α = ∫ σ_α η dη               (bending moments about the mid-surface, η along n:
//                                   positive when the outer side (n) is in tension),
//   σ_α = N_α / h                  (the membrane-equivalent mean Cauchy stress),
// α = hoop (1), meridian (2). λ, E and S are the mid-surface's: S_α = σ_α / λ_α²,
// so that a shell without bending reports what a membrane would. σ± = N/h ± 6M/h²
// are the linearized outer (+, side n) and inner surface stresses.
#include "elements/axisym_shell.hpp"
#include "elements/membrane_point.hpp"

namespace tunica {

/// The MembranePoint of shell Gauss point `p` of reference thickness H.
MembranePoint shell_membrane_point(const ShellPoint& p, double H);

}  // namespace tunica
