// Assembly of the axisymmetric shell blocks (System::assemble_shell, system.hpp):
// per element the internal force and tangent of elements/axisym_shell.hpp minus
// the follower pressure's force and load stiffness on the Hermite mid-surface
// (loads/axisym_shell_pressure.hpp), R += f_int − f_p, K += K_int − ∂f_p/∂u,
// scattered through the DOF map (positions and slopes, assembly/shell_nodes.hpp).
#include "assembly/shell_nodes.hpp"
#include "assembly/system.hpp"
#include "assembly/system_coloured.hpp"
#include "elements/axisym_shell.hpp"
#include "loads/axisym_shell_pressure.hpp"

namespace tunica {

void System::assemble_shell(int p, int b, const Eigen::VectorXd& u, double pressure, Eigen::VectorXd& R,
                            SparseMatrix* K, double& scale2) const {
  const Part& part = model_.parts[p];
  const ElementBlock& block = part.blocks[b];
  const int* scatter_pos = blocks_[p][b].scatter.data();
  const ShellQuadrature quadrature = shell_quadrature(part);
  std::vector<double> scale_e(block.size());  // per element: summed in element order, whatever the threads
  for_each_coloured(blocks_[p][b], [&](int e) {
    ShellVector f, fp;
    ShellMatrix Ke, dfp;
    ShellNodes X, x;
    const int* en = block.element(e);
    shell_nodes(model_, en, u, X, x);
    axisym_shell(X, x, part.thickness, *part.material, f, K ? &Ke : nullptr, quadrature);
    double s2 = f.squaredNorm();
    if (pressure != 0.0) {
      axisym_shell_pressure(X, x, pressure, fp, K ? &dfp : nullptr);
      s2 += fp.squaredNorm();
      f -= fp;
      if (K) Ke -= dfp;
    }
    // Stiffness × element size bounds the round-off of stresses near zero strain.
    if (K) s2 += Ke.squaredNorm() * (X.block<2, 1>(0, 1) - X.block<2, 1>(0, 0)).squaredNorm();
    scale_e[e] = s2;
    const int* pos = scatter_pos + 64 * e;
    for (int a = 0; a < 8; ++a) R(shell_dof(model_, en, a)) += f(a);
    if (!K) return;
    double* values = K->valuePtr();
    for (int a = 0; a < 8; ++a)
      for (int c = 0; c < 8; ++c)
        if (const int k = pos[a * 8 + c]; k >= 0) values[k] += Ke(a, c);
  });
  for (double s2 : scale_e) scale2 += s2;
}

}  // namespace tunica
