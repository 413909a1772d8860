// The 4-node axisymmetric solid (elements/axisym_solid.hpp, theory manual §10): Q1/P0 mean
// dilatation or displacement-based, nearly incompressible; no pressure on it.
#include "contributions/element_loop.hpp"
#include "contributions/kinematics.hpp"
#include "elements/axisym_solid.hpp"

namespace tunica {

namespace {

struct AxisymSolidKernel : PlaneKinematics<4> {
  static constexpr bool kPressure = false, kStartStiffness = false, kSolid = true;
  using Vector = SolidVector;
  using Matrix = SolidMatrix;
  const Part& part;
  explicit AxisymSolidKernel(const BlockContext& ctx) : part(ctx.part) {}

  void internal(int, const State& s, Vector& f, Matrix* K) const {
    axisym_solid(s.X, s.x, *part.solid_material, part.formulation, f, K);
  }
  // The element's diagonal.
  double length2(const Model&, const int*, const State& s) const {
    return std::max((s.X.col(2) - s.X.col(0)).squaredNorm(), s.x.colwise().squaredNorm().maxCoeff());
  }
  void points(int, const State& s, std::vector<SolidPoint>& out) const {
    Vector f;
    std::array<SolidPoint, 4> pts;
    axisym_solid(s.X, s.x, *part.solid_material, part.formulation, f, nullptr, &pts);
    out.insert(out.end(), pts.begin(), pts.end());
  }
  double energy(int, const State& s) const {
    Vector f;
    return axisym_solid(s.X, s.x, *part.solid_material, part.formulation, f, nullptr);
  }
};

const bool registered = [] {
  register_element_type({.kind = ElementKind::solid4,
                         .name = "axisymmetric solid (4 nodes)",
                         .nodes = 4,
                         .unknowns_per_node = 2,
                         .solid = true,
                         .pressure = false,
                         .vtk_cell = 9,            // VTK_QUAD
                         .vtk_revolved_cell = 12,  // VTK_HEXAHEDRON
                         .points_per_element = [](const Part&) { return 4; },
                         .make = make_kernel_block<AxisymSolidKernel>,
                         .check = {}});
  return true;
}();

}  // namespace

}  // namespace tunica
