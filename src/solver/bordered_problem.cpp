#include "solver/bordered_problem.hpp"

#include <algorithm>
#include <cmath>

namespace tunica {

namespace {
/// The pattern of K bordered by a full last column and row (index nf).
SparseMatrix bordered_pattern(const SparseMatrix& K) {
  const int nf = static_cast<int>(K.cols());
  SparseMatrix A(nf + 1, nf + 1);
  A.resizeNonZeros(K.nonZeros() + 2 * nf + 1);
  int* outer = A.outerIndexPtr();
  int* inner = A.innerIndexPtr();
  int k = 0;
  for (int j = 0; j < nf; ++j) {
    outer[j] = k;
    for (int q = K.outerIndexPtr()[j]; q < K.outerIndexPtr()[j + 1]; ++q) inner[k++] = K.innerIndexPtr()[q];
    inner[k++] = nf;
  }
  outer[nf] = k;
  for (int i = 0; i <= nf; ++i) inner[k++] = i;
  outer[nf + 1] = k;
  std::fill(A.valuePtr(), A.valuePtr() + k, 0.0);
  return A;
}

/// Fills the bordered matrix A (pattern of bordered_pattern) from K, the column −g and the row ∂V/∂u.
void fill_bordered(const SparseMatrix& K, const Eigen::VectorXd& g, const Eigen::VectorXd& dV, SparseMatrix& A) {
  const int nf = static_cast<int>(K.cols());
  double* a = A.valuePtr();
  int k = 0;
  for (int j = 0; j < nf; ++j) {
    for (int q = K.outerIndexPtr()[j]; q < K.outerIndexPtr()[j + 1]; ++q) a[k++] = K.valuePtr()[q];
    a[k++] = dV(j);
  }
  for (int i = 0; i < nf; ++i) a[k++] = -g(i);
  a[k++] = 0.0;
}
}  // namespace

BorderedProblem::BorderedProblem(MechanicalProblem& inner, LoadState& loads, int load, double target)
    : inner_(inner), loads_(loads), load_(load), target_(target), A_(bordered_pattern(inner.system().pattern())) {}

double BorderedProblem::evaluate(Eigen::VectorXd& r) {
  Eigen::VectorXd R;
  const double scale = inner_.evaluate(R);
  const System& system = inner_.system();
  Eigen::VectorXd dV;
  c_ = system.volume(inner_.state(), load_, &dV) - target_;
  dV_ = inner_.free_part(dV);
  g_ = inner_.free_part(system.pressure_load(inner_.state(), load_));
  const int nf = inner_.size();
  r.resize(nf + 1);
  r.head(nf) = R;
  r(nf) = c_;
  return scale;
}

double BorderedProblem::residual_norm(const Eigen::VectorXd& r) const { return r.head(inner_.size()).norm(); }

double BorderedProblem::work(const Eigen::VectorXd& dx, const Eigen::VectorXd& r) const {
  const int nf = inner_.size();
  return dx.head(nf).dot(r.head(nf)) + dx(nf) * r(nf);
}

bool BorderedProblem::side_conditions_hold(double tolerance) const {
  return std::abs(c_) <= tolerance * std::abs(target_);
}

const TangentMatrix& BorderedProblem::jacobian(int iteration) { return bordered(inner_.jacobian(iteration)); }

const TangentMatrix& BorderedProblem::bordered(const TangentMatrix& K) {
  K.expand(K_);
  fill_bordered(K_, g_, dV_, A_.general());
  return A_;
}

void BorderedProblem::step(const Eigen::VectorXd& dx, double factor) {
  const int nf = inner_.size();
  inner_.step(dx.head(nf), factor);
  loads_.pressure[load_] += factor * dx(nf);
}

}  // namespace tunica
