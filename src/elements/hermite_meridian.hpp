#pragma once
// Cubic Hermite interpolation of an axisymmetric shell meridian (the
// discretization of elements/axisym_shell.hpp), shared by the shell element,
// its follower pressure (loads/axisym_shell_pressure.hpp) and output:
//     x(ξ) = h₀₀(ξ) x₁ + L h₁₀(ξ) x′₁ + h₀₁(ξ) x₂ + L h₁₁(ξ) x′₂,   ξ ∈ [0, 1],
//     h₀₀ = 2ξ³ − 3ξ² + 1, h₁₀ = ξ³ − 2ξ² + ξ, h₀₁ = −2ξ³ + 3ξ², h₁₁ = ξ³ − ξ²,
// with L = 2c / (1 + cos β̄) the element's Hermite length (c the reference chord,
// cos β̄ the mean cosine between the reference unit tangents and the chord).
#include <Eigen/Dense>

namespace tunica {

/// Nodal state of a 2-node axisymmetric shell element: column a = (r_a, z_a, r′_a, z′_a),
/// position and slope (∂/∂S, reference arc length). Reference slopes must be unit vectors.
using ShellNodes = Eigen::Matrix<double, 4, 2>;
using ShellVector = Eigen::Matrix<double, 8, 1>;
using ShellMatrix = Eigen::Matrix<double, 8, 8>;

/// The four Hermite functions at ξ, multiplying (x₁, x′₁, x₂, x′₂) (L included), and their
/// first and second ξ-derivatives.
struct HermiteBasis {
  double h[4], dh[4], d2h[4];
};

inline HermiteBasis hermite_basis(double xi, double L) {
  const double x2 = xi * xi, x3 = x2 * xi;
  return {{2 * x3 - 3 * x2 + 1, L * (x3 - 2 * x2 + xi), -2 * x3 + 3 * x2, L * (x3 - x2)},
          {6 * x2 - 6 * xi, L * (3 * x2 - 4 * xi + 1), -6 * x2 + 6 * xi, L * (3 * x2 - 2 * xi)},
          {12 * xi - 6, L * (6 * xi - 4), -12 * xi + 6, L * (6 * xi - 2)}};
}

/// Element unknown (0 … 7, column-major in ShellNodes) multiplied by Hermite function j
/// for component c (0 = r, 1 = z): node a = j/2, slope if j is odd.
constexpr int hermite_index(int j, int c) { return 4 * (j / 2) + 2 * (j % 2) + c; }

/// The Hermite length L of a reference element. Throws std::invalid_argument for a zero
/// chord, non-unit reference slopes or slopes pointing against the element.
double hermite_length(const ShellNodes& X);

}  // namespace tunica
