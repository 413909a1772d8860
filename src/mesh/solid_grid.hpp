#pragma once
// Structured grid of 4-node quadrilaterals in the (r, z) meridian plane for
// axisymmetric solid parts (theory manual §12.2: the plaque, an idealized centric stenosis).
//
// The solid lies between an inner and an outer meridian profile r_in(z) < r_out(z)
// over z ∈ [z0, z1]. Node (i, j), i = 0 … n_r (inner to outer), j = 0 … n_z
// (bottom to top), sits at
//   z_j = z0 + (z1 − z0) j/n_z,   r_ij = r_in(z_j) + (r_out(z_j) − r_in(z_j)) i/n_r,
// and has the number j (n_r + 1) + i. Element (i, j) joins the nodes (i, j),
// (i+1, j), (i+1, j+1), (i, j+1): counter-clockwise in the (r, z) plane.
#include <Eigen/Dense>
#include <string>
#include <vector>

namespace tunica {

/// A meridian profile r(z) over [z0, z1].
struct RadiusProfile {
  enum class Type {
    constant,  ///< r = radius
    polyline,  ///< piecewise linear through `points` (r, z), z strictly increasing, covering [z0, z1]
    cosine,    ///< r = r_e + (r_c − r_e) ½ (1 + cos(2π (z − z_c)/L)),  z_c = (z0 + z1)/2, L = z1 − z0
    circular,  ///< the circular arc through (r_e, z0), (r_c, z_c), (r_e, z1)
  } type = Type::constant;
  double radius = 0;                     ///< constant
  std::vector<Eigen::Vector2d> points;   ///< polyline, (r, z)
  double radius_ends = 0;                ///< r_e: cosine and circular, at z0 and z1
  double radius_centre = 0;              ///< r_c: cosine and circular, at z_c
};

/// r(z) of a profile over [z0, z1]. Throws std::invalid_argument if a polyline does not
/// cover z or a circular arc cannot be a function of z (|r_e − r_c| > (z1 − z0)/2).
double profile_radius(const RadiusProfile& profile, double z, double z0, double z1);

struct SolidGridSpec {
  double z0 = 0, z1 = 1;
  RadiusProfile inner, outer;
  int elements_r = 1, elements_z = 1;
};

struct SolidGrid {
  std::vector<Eigen::Vector2d> nodes;  ///< (r, z), numbered as above
  std::vector<int> quads;              ///< 4 local node numbers per element, counter-clockwise
  std::vector<int> inner, outer;       ///< surface chains, increasing z
  std::vector<int> bottom, top;        ///< end chains, increasing r
};

/// The grid. Throws std::invalid_argument with a readable reason if z1 ≤ z0, a count is
/// below 1, a radius is not positive, r_in ≥ r_out at a node row, or an element is
/// degenerate or inverted (a corner with det(∂X/∂ξ) ≤ 1e-12 × its longest edge²).
SolidGrid solid_grid(const SolidGridSpec& spec);

}  // namespace tunica
