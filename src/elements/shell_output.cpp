// Shell Gauss point → MembranePoint (equations in shell_output.hpp).
#include "elements/shell_output.hpp"

namespace tunica {

MembranePoint shell_membrane_point(const ShellPoint& p, double H) {
  MembranePoint q;
  double h = 0;
  Eigen::Vector2d N = Eigen::Vector2d::Zero(), M = Eigen::Vector2d::Zero();
  for (std::size_t k = 0; k < p.zeta.size(); ++k) {
    const Eigen::Index i = static_cast<Eigen::Index>(k);
    const double deta = p.weight_zeta[k] / (p.stretch(0, i) * p.stretch(1, i));  // w_k dη/dζ
    h += deta;
    N += deta * p.sigma.col(i);
    M += deta * p.eta[k] * p.sigma.col(i);
  }
  q.X = Eigen::Vector3d(p.R, p.Z, 0.0);
  q.x = Eigen::Vector3d(p.r, p.z, 0.0);
  q.R = p.R;
  q.r = p.r;
  q.z = p.z;
  q.lambda = p.lambda;
  q.E = Eigen::Vector3d(0.5 * (p.lambda(0) * p.lambda(0) - 1.0), 0.5 * (p.lambda(1) * p.lambda(1) - 1.0), 0.0);
  q.sigma = N / h;
  q.S = Eigen::Vector3d(q.sigma(0) / (p.lambda(0) * p.lambda(0)), q.sigma(1) / (p.lambda(1) * p.lambda(1)), 0.0);
  q.sigma_principal = Eigen::Vector2d(q.sigma.maxCoeff(), q.sigma.minCoeff());
  q.e1 = Eigen::Vector3d::UnitY();
  q.e2 = Eigen::Vector3d(p.T(0), 0.0, p.T(1));
  const Eigen::Vector3d t(p.t(0), 0.0, p.t(1));
  q.cauchy = q.sigma(0) * q.e1 * q.e1.transpose() + q.sigma(1) * t * t.transpose();
  q.thickness = h;
  q.moment = M;
  q.sigma_outer = q.sigma + 6.0 * M / (h * h);
  q.sigma_inner = q.sigma - 6.0 * M / (h * h);
  q.W = p.W / H;
  q.weight = p.weight * H;
  return q;
}

}  // namespace tunica
