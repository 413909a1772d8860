#pragma once
// The discrete system of a model: DOF numbering with prescribed DOFs removed,
// the sparsity pattern of the free-DOF tangent computed once, each element's
// scatter positions into it, and the assembly of the residual
// R = f_int − f_ext (all DOFs, so reactions can be read) and of K = ∂R/∂u
// (free DOFs only) from the element and load kernels.
#include <Eigen/Sparse>
#include <array>
#include <vector>

#include "elements/axisym_membrane.hpp"
#include "model/model.hpp"

namespace tunica {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

/// Current values of the boundary and load amplitudes.
struct LoadState {
  std::vector<double> boundary;  ///< per Model::boundaries
  std::vector<double> pressure;  ///< per Model::loads
};

class System {
public:
  explicit System(const Model& model);

  int num_dofs() const { return model_.num_dofs(); }
  int num_free() const { return num_free_; }
  /// Equation number of a DOF, −1 if prescribed.
  int equation(int dof) const { return eq_[dof]; }
  const std::vector<int>& prescribed_dofs() const { return prescribed_; }

  /// Sets the prescribed DOFs of u to the boundary values of `loads`.
  void apply_boundary(const LoadState& loads, Eigen::VectorXd& u) const;
  /// Full residual R (num_dofs) and, if K is given, the free-DOF tangent with the fixed pattern.
  /// `force_scale`, if given, receives a yardstick for round-off in R: sqrt(Σ_e ‖f_int,e‖² +
  /// ‖f_ext,e‖² + (‖K_e‖ L_e)²), the forces that cancel in R and, when K is assembled, the
  /// stiffness × element size that bounds round-off of stresses computed near zero strain.
  void assemble(const Eigen::VectorXd& u, const LoadState& loads, Eigen::VectorXd& R, SparseMatrix* K,
                double* force_scale = nullptr) const;
  /// A zero matrix with the tangent's pattern.
  const SparseMatrix& pattern() const { return pattern_; }
  /// Gauss-point states of every element of a part (2 per element).
  std::vector<MembranePoint> points(const Eigen::VectorXd& u, int part) const;

private:
  AxisymNodes reference(const std::array<int, 2>& e) const;
  AxisymNodes current(const std::array<int, 2>& e, const Eigen::VectorXd& u) const;

  const Model& model_;
  std::vector<int> eq_;
  std::vector<int> prescribed_;
  int num_free_ = 0;
  SparseMatrix pattern_;
  /// Per part, per element: the 16 positions in K's value array (−1 = not a free-free entry).
  std::vector<std::vector<std::array<int, 16>>> scatter_;
};

}  // namespace tunica
