// The 2-node axisymmetric membrane (elements/axisym_membrane.hpp, theory manual §3) with the
// follower pressure on its meridian segment (loads/axisym_pressure.hpp, §6) and the enclosed
// volume V_e = π ∫ r² dz = π Δz (r₁² + r₁r₂ + r₂²)/3 of a straight segment ((6.7)); its inverse
// element (elements/axisym_membrane_inverse.hpp, §13) moves the reference nodes, X = x̂ + u.
#include <algorithm>
#include <numbers>

#include "contributions/element_loop.hpp"
#include "contributions/kinematics.hpp"
#include "elements/axisym_membrane.hpp"
#include "elements/axisym_membrane_inverse.hpp"
#include "elements/axisym_start_tension.hpp"
#include "loads/axisym_pressure.hpp"

namespace tunica {

namespace {

struct AxisymMembraneKernel : PlaneKinematics<2> {
  static constexpr bool kPressure = true, kStartStiffness = true, kSolid = false;
  using Vector = Eigen::Vector4d;
  using Matrix = Eigen::Matrix4d;
  const Part& part;
  const Model& model;
  const ElementBlock& block;
  const int first_element;
  explicit AxisymMembraneKernel(const BlockContext& ctx)
      : part(ctx.part), model(ctx.model), block(ctx.block), first_element(ctx.first_element) {}

  /// The reference thickness at the Gauss points of element e: the part's, or the one an inverse
  /// step computed from an imaged thickness (13.14).
  std::array<double, 2> thickness(int e) const {
    if (part.point_thickness.empty()) return {part.thickness, part.thickness};
    const std::size_t i = 2 * static_cast<std::size_t>(first_element + e);
    return {part.point_thickness.at(i), part.point_thickness.at(i + 1)};
  }
  /// The prestretch (P_θ, P_s) at the Gauss points of element e: the one a prestress step left (13.23),
  /// else none.
  AxisymPrestretch prestretch(int e) const {
    if (part.point_prestretch.empty()) return {Eigen::Vector2d::Ones(), Eigen::Vector2d::Ones()};
    const std::size_t i = 2 * static_cast<std::size_t>(first_element + e);
    const Eigen::Matrix2d &P0 = part.point_prestretch.at(i), &P1 = part.point_prestretch.at(i + 1);
    return {P0.diagonal(), P1.diagonal()};
  }
  void internal(int e, const State& s, Vector& f, Matrix* K) const {
    axisym_membrane(s.X, s.x, thickness(e), prestretch(e), *part.material, f, K);
  }
  double length2(const Model&, const int*, const State& s) const {
    return std::max((s.X.col(1) - s.X.col(0)).squaredNorm(), s.x.colwise().squaredNorm().maxCoeff());
  }
  void pressure(const State& s, double p, Vector& f, Matrix* K) const { axisym_pressure(s.x, p, f, K); }
  double volume(const State& s, const VolumeMeasure&, Vector* grad) const {
    const double r1 = s.x(0, 0), r2 = s.x(0, 1), dz = s.x(1, 1) - s.x(1, 0);
    const double q = (r1 * r1 + r1 * r2 + r2 * r2) / 3.0;
    if (grad) {
      (*grad)(0) = std::numbers::pi * dz * (2 * r1 + r2) / 3.0;
      (*grad)(1) = -(std::numbers::pi * q);
      (*grad)(2) = std::numbers::pi * dz * (r1 + 2 * r2) / 3.0;
      (*grad)(3) = std::numbers::pi * q;
    }
    return std::numbers::pi * dz * q;
  }
  void start(int e, double T0, Matrix& K) const {
    const int* en = block.element(e);
    axisym_normal_tension_stiffness(model.X[en[0]].head<2>(), model.X[en[1]].head<2>(), T0, K);
  }
  /// The imaged thickness h at the Gauss points of element e (theory manual (13.12)).
  std::array<double, 2> imaged(int e) const {
    if (part.imaged_point_thickness.empty()) return {part.thickness, part.thickness};
    const std::size_t i = 2 * static_cast<std::size_t>(first_element + e);
    return {part.imaged_point_thickness.at(i), part.imaged_point_thickness.at(i + 1)};
  }
  void inverse(int e, const State& s, const Vector& ue, Vector& f, Matrix* K) const {
    const std::array<double, 2> h = imaged(e);
    axisym_membrane_inverse(s.x + Eigen::Map<const AxisymNodes>(ue.data()), s.x, part.thickness, *part.material, f, K,
                            part.imaged_thickness ? &h : nullptr);
  }
  void inverse_points(int e, const State& s, const Vector& ue, std::vector<MembranePoint>& out) const {
    Vector f;
    std::array<MembranePoint, 2> pts;
    const std::array<double, 2> h = imaged(e);
    axisym_membrane_inverse(s.x + Eigen::Map<const AxisymNodes>(ue.data()), s.x, part.thickness, *part.material, f,
                            nullptr, part.imaged_thickness ? &h : nullptr, &pts);
    out.insert(out.end(), pts.begin(), pts.end());
  }
  void points(int e, const State& s, std::vector<MembranePoint>& out) const {
    Vector f;
    std::array<MembranePoint, 2> pts;
    axisym_membrane(s.X, s.x, thickness(e), prestretch(e), *part.material, f, nullptr, &pts);
    out.insert(out.end(), pts.begin(), pts.end());
  }
};

const bool registered = [] {
  register_element_type({.kind = ElementKind::axisym2,
                         .name = "axisymmetric membrane (2 nodes)",
                         .nodes = 2,
                         .unknowns_per_node = 2,
                         .solid = false,
                         .pressure = true,
                         .inverse = true,
                         .vtk_cell = 3,           // VTK_LINE
                         .vtk_revolved_cell = 9,  // VTK_QUAD
                         .points_per_element = [](const Part&) { return 2; },
                         .make = make_kernel_block<AxisymMembraneKernel>,
                         .check = {}});
  return true;
}();

}  // namespace

}  // namespace tunica
