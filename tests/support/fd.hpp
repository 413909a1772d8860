#pragma once
// Central finite differences for the derivative tests, and a relative error
// measure: ‖a − b‖ / max(‖b‖, floor).
#include <Eigen/Dense>
#include <algorithm>
#include <functional>

namespace tunica::test {

/// Tolerance of the relative error of a derivative against central differences with h = 1e-6 on
/// arguments of order 1, as the tests over the material registry use it. Those differences are
/// accurate to about 1e-9 (rounding ~1e-16/h of the function's scale, truncation ~h²; 1e-8 at
/// worst over thousands of random states per material and element); a term of a material's
/// tangent that is wrong by 0.1 % shows as an error of 1e-4 to 1e-3.
constexpr double kFdTolerance = 1e-7;

/// Central-difference gradient of a scalar function.
inline Eigen::VectorXd fd_gradient(const std::function<double(const Eigen::VectorXd&)>& f, const Eigen::VectorXd& x,
                                   double h) {
  Eigen::VectorXd g(x.size());
  for (int i = 0; i < x.size(); ++i) {
    Eigen::VectorXd xp = x, xm = x;
    xp(i) += h;
    xm(i) -= h;
    g(i) = (f(xp) - f(xm)) / (2 * h);
  }
  return g;
}

/// Central-difference Jacobian of a vector function (column j = ∂f/∂x_j).
inline Eigen::MatrixXd fd_jacobian(const std::function<Eigen::VectorXd(const Eigen::VectorXd&)>& f,
                                   const Eigen::VectorXd& x, double h) {
  const Eigen::VectorXd f0 = f(x);
  Eigen::MatrixXd J(f0.size(), x.size());
  for (int j = 0; j < x.size(); ++j) {
    Eigen::VectorXd xp = x, xm = x;
    xp(j) += h;
    xm(j) -= h;
    J.col(j) = (f(xp) - f(xm)) / (2 * h);
  }
  return J;
}

inline double relative_error(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b, double floor = 1e-12) {
  return (a - b).norm() / std::max(b.norm(), floor);
}

}  // namespace tunica::test
