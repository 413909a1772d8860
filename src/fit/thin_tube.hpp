#pragma once
// The thin-walled (membrane) tube of an inflation–extension test (theory manual §8, §12.1),
// evaluated through the same material code as the finite element solver
// (membrane_response: exact incompressible plane stress).
//
// Mid-surface kinematics: λθ = r/R, λz given; the thickness follows from
// incompressibility, h = H/(λθ λz). In the material frame 1 = θ, 2 = z:
//     S = membrane_response(W, C = (λθ², λz², 0)).S,   σθ = λθ² S1,  σz = λz² S2,
//     hoop equilibrium     p = σθ h / r               (Laplace, p r = σθ h),
//     axial membrane force N = 2π r h σz.
// What a force transducer reads depends on how the specimen is loaded:
// open ends (no end caps; the FE model and its reaction) F = N; closed ends
// (pressure also acts on the caps) F = N − π r² p.
#include <optional>
#include <string>

#include "materials/membrane_material.hpp"

namespace tunica {

/// How the measured axial force relates to the membrane force N (see the file comment).
enum class TubeEnds { open, closed };

/// "open" / "closed".
const char* tube_ends_name(TubeEnds ends);

/// Load-free geometry of the specimen: mid-surface radius R and wall thickness H.
struct TubeGeometry {
  double R = 0;  ///< load-free mid-surface radius, R = (D − H)/2 for outer diameter D
  double H = 0;  ///< load-free wall thickness
  TubeEnds ends = TubeEnds::open;
};

/// The thin tube at one deformation (λθ, λz): kinematics, stresses and loads.
struct TubeState {
  double lambda_theta = 1, lambda_z = 1;
  double E_theta = 0, E_z = 0;          ///< Green strains E = ½(λ² − 1)
  double S_theta = 0, S_z = 0;          ///< 2nd Piola–Kirchhoff stresses
  double sigma_theta = 0, sigma_z = 0;  ///< Cauchy stresses σ = λ² S
  double r = 0, h = 0;                  ///< current mid-surface radius r = λθ R and thickness h = H/(λθ λz)
  double outer_diameter = 0;            ///< 2r + h
  double pressure = 0;                  ///< p = σθ h / r
  double membrane_force = 0;            ///< N = 2π r h σz
  double axial_force = 0;               ///< transducer force: N (open ends) or N − π r² p (closed ends)
};

/// The tube relations above at (λθ, λz). Requires λθ, λz > 0.
TubeState tube_state(const MembraneMaterial& material, const TubeGeometry& geometry, double lambda_theta,
                     double lambda_z);

/// Current mid-surface radius from a measured outer diameter D: r + h/2 = D/2 with
/// h = H/(λθ λz) = H R/(r λz), i.e. r² − (D/2) r + H R/(2 λz) = 0, the larger root
///     r = D/4 + sqrt(D²/16 − H R/(2 λz)).
/// Empty if there is no real root (D too small for the wall).
std::optional<double> mid_radius_from_outer_diameter(const TubeGeometry& geometry, double outer_diameter,
                                                     double lambda_z);

/// The hoop stretch at which the tube carries pressure p at axial stretch λz:
/// the root of S1(λθ, λz) = p R λz / H (theory manual (8.1); p r = σθ h),
/// by bracketing and safeguarded Newton (dS1/dλθ = D11 λθ). Throws SolveError
/// if no root exists for 1e-3 ≤ λθ ≤ 50 (e.g. beyond a neo-Hookean tube's pressure maximum).
double hoop_stretch_at_pressure(const MembraneMaterial& material, const TubeGeometry& geometry, double pressure,
                                double lambda_z);

}  // namespace tunica
