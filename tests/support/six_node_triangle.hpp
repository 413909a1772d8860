#pragma once
// A 6-node triangle (elements/tri6_shape.hpp) on the corners of a 3-node one, for the tests that
// run every surface shape: mid-edge nodes 3 (edge 0–1), 4 (edge 1–2), 5 (edge 2–0) at the edges'
// midpoints, each moved by a random vector whose components are uniform in [−s_k, s_k] (s = 0:
// straight edges; a component normal to a flat element's plane makes it curved).
#include <random>

#include "elements/membrane3d.hpp"
#include "elements/tri6_shape.hpp"

namespace tunica::test {

inline SurfaceNodes<6> six_node_triangle(const SurfaceNodes<3>& corners, const Eigen::Vector3d& s, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  SurfaceNodes<6> X;
  X.leftCols<3>() = corners;
  for (int m = 0; m < 3; ++m) {
    // One draw per statement: the evaluation order of function arguments is unspecified.
    const double a = u(rng);
    const double b = u(rng);
    const double c = u(rng);
    X.col(3 + m) = 0.5 * (corners.col(m) + corners.col((m + 1) % 3)) + s.cwiseProduct(Eigen::Vector3d(a, b, c));
  }
  return X;
}

}  // namespace tunica::test
