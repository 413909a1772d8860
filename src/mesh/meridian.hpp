#pragma once
// Generated meridian meshes for axisymmetric parts: a straight line (a tube)
// and a circular arc (a balloon or a sphere). Points are (r, z).
#include <Eigen/Dense>
#include <map>
#include <string>
#include <vector>

#include "params/param_spec.hpp"
#include "params/params.hpp"

namespace tunica {

/// Node positions along a meridian, in order; element i joins nodes i and i+1.
using Meridian = std::vector<Eigen::Vector2d>;

/// A meridian generator a deck can name (`mesh: {type: line, ...}`).
struct MeridianType {
  ComponentSpec spec;
  Meridian (*make)(const Params&);
};

/// All meridian generators by deck name.
const std::map<std::string, MeridianType>& meridian_types();

/// Straight line from `a` to `b` in n equal elements.
Meridian line_meridian(const Eigen::Vector2d& a, const Eigen::Vector2d& b, int n);
/// A node of a generated arc at most this fraction of an element beyond the axis (r < 0) is put
/// on it (r = 0).
constexpr double kOnAxisFraction = 1e-3;

/// Circular arc about `center` with radius ρ from angle φ0 to φ1 (radians,
/// measured from the +r axis towards +z) in n equal elements; a node at most kOnAxisFraction of
/// an element beyond the axis lies on it.
Meridian arc_meridian(const Eigen::Vector2d& center, double rho, double phi0, double phi1, int n);

}  // namespace tunica
