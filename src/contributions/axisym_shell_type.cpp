// The 2-node axisymmetric Kirchhoff–Love shell (elements/axisym_shell.hpp, theory manual §11)
// with the follower pressure and enclosed volume on its Hermite mid-surface
// (loads/axisym_shell_pressure.hpp, (11.5)); 4 unknowns per node (positions and slopes).
#include "contributions/element_loop.hpp"
#include "contributions/kinematics.hpp"
#include "elements/axisym_shell.hpp"
#include "elements/shell_output.hpp"
#include "loads/axisym_shell_pressure.hpp"

namespace tunica {

namespace {

struct AxisymShellKernel : ShellKinematics {
  static constexpr bool kPressure = true, kStartStiffness = false, kSolid = false;
  using Vector = ShellVector;
  using Matrix = ShellMatrix;
  const Part& part;
  ShellQuadrature quadrature;
  explicit AxisymShellKernel(const BlockContext& ctx)
      : part(ctx.part), quadrature{ctx.part.shell_meridian_points, ctx.part.shell_thickness_points} {}

  void internal(int, const State& s, Vector& f, Matrix* K) const {
    axisym_shell(s.X, s.x, part.thickness, *part.material, f, K, quadrature);
  }
  double length2(const Model&, const int*, const State& s) const {
    return std::max((s.X.block<2, 1>(0, 1) - s.X.block<2, 1>(0, 0)).squaredNorm(),
                    s.x.topRows<2>().colwise().squaredNorm().maxCoeff());
  }
  void pressure(const State& s, double p, Vector& f, Matrix* K) const { axisym_shell_pressure(s.X, s.x, p, f, K); }
  double volume(const State& s, const VolumeMeasure&, Vector* grad) const { return axisym_shell_volume(s.X, s.x, grad); }
  void points(int, const State& s, std::vector<MembranePoint>& out) const {
    Vector f;
    std::vector<ShellPoint> pts;
    axisym_shell(s.X, s.x, part.thickness, *part.material, f, nullptr, quadrature, &pts);
    for (const auto& pt : pts) out.push_back(shell_membrane_point(pt, part.thickness));
  }
};

const bool registered = [] {
  register_element_type({.kind = ElementKind::shell2,
                         .name = "axisymmetric shell (2 nodes)",
                         .nodes = 2,
                         .unknowns_per_node = 4,
                         .solid = false,
                         .pressure = true,
                         .vtk_cell = 3,           // VTK_LINE
                         .vtk_revolved_cell = 9,  // VTK_QUAD
                         .points_per_element = [](const Part& part) { return part.shell_meridian_points; },
                         .make = make_kernel_block<AxisymShellKernel>,
                         .check = {}});
  return true;
}();

}  // namespace

}  // namespace tunica
