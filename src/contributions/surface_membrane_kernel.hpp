#pragma once
// The kernel of the 3-D membrane elements (elements/membrane3d.hpp, theory manual §5) of any
// surface shape with N nodes, with the follower pressure and enclosed volume on the element's
// surface (loads/surface_pressure.hpp, §6) and the stress-free start's normal-tension stiffness
// (elements/start_tension.hpp, (7.6)–(7.8)). A surface element type is this kernel and its
// registration (surface_membrane_types.cpp; a new shape: its own file, docs/architecture.md).
// Its inverse element (elements/membrane3d_inverse.hpp, §13) moves the reference nodes, X = x̂ + u.
#include "contributions/element_loop.hpp"
#include "contributions/kinematics.hpp"
#include "contributions/surface_references.hpp"
#include "elements/membrane3d.hpp"
#include "elements/membrane3d_inverse.hpp"
#include "elements/start_tension.hpp"
#include "loads/surface_pressure.hpp"

namespace tunica {

template <int N>
struct SurfaceMembraneKernel : SpaceKinematics<N> {
  static constexpr bool kPressure = true, kStartStiffness = true, kSolid = false;
  using State = typename SpaceKinematics<N>::State;
  using Vector = ElementVector<N>;
  using Matrix = ElementMatrix<N>;
  const Part& part;
  const Model& model;
  const ElementBlock& block;
  const int first_element;
  std::vector<MembraneReference<N>> refs;
  explicit SurfaceMembraneKernel(const BlockContext& ctx)
      : part(ctx.part), model(ctx.model), block(ctx.block), first_element(ctx.first_element),
        refs(block_references<N>(ctx.model, ctx.part, ctx.block, ctx.first_element)) {}

  void internal(int e, const State& s, Vector& f, Matrix* K) const { membrane3d<N>(refs[e], s.x, *part.material, f, K); }
  double length2(const Model& m, const int* en, const State& s) const {
    return std::max((m.X[en[1]] - m.X[en[0]]).squaredNorm(), s.x.colwise().squaredNorm().maxCoeff());
  }
  void pressure(const State& s, double p, Vector& f, Matrix* K) const { surface_pressure<N>(s.x, p, f, K); }
  double subtract_pressure(const State& s, double p, Vector& f, Matrix* K) const {
    return subtract_surface_pressure<N>(s.x, p, f, K);
  }
  double volume(const State& s, const VolumeMeasure& how, Vector* grad) const { return enclosed_volume<N>(s.x, how, grad); }
  void start(int e, double T0, Matrix& K) const { normal_tension_stiffness<N>(refs[e], T0, K); }
  void inverse(int e, const State& s, const Vector& ue, Vector& f, Matrix* K) const {
    const SurfaceNodes<N> X = s.x + Eigen::Map<const SurfaceNodes<N>>(ue.data());
    const auto h = imaged(e);
    membrane3d_inverse<N>(X, s.x, part.thickness, frame_direction(model, part.frame, block, e), *part.material, f, K,
                          part.imaged_thickness ? &h : nullptr);
  }
  /// The imaged thickness h at the Gauss points of element e (theory manual (13.12)).
  std::array<double, SurfaceShapeTraits<N>::kPoints> imaged(int e) const {
    std::array<double, SurfaceShapeTraits<N>::kPoints> h;
    h.fill(part.thickness);
    if (!part.imaged_point_thickness.empty())
      for (int q = 0; q < SurfaceShapeTraits<N>::kPoints; ++q)
        h[q] = part.imaged_point_thickness.at(first_point_of(part, block) + static_cast<std::size_t>(e) * h.size() + q);
    return h;
  }
  void inverse_points(int e, const State& s, const Vector& ue, std::vector<MembranePoint>& out) const {
    const SurfaceNodes<N> X = s.x + Eigen::Map<const SurfaceNodes<N>>(ue.data());
    Vector f;
    std::array<MembranePoint, SurfaceShapeTraits<N>::kPoints> pts;
    const auto h = imaged(e);
    membrane3d_inverse<N>(X, s.x, part.thickness, frame_direction(model, part.frame, block, e), *part.material, f,
                          nullptr, part.imaged_thickness ? &h : nullptr, &pts);
    out.insert(out.end(), pts.begin(), pts.end());
  }
  void points(int e, const State& s, std::vector<MembranePoint>& out) const {
    Vector f;
    std::array<MembranePoint, SurfaceShapeTraits<N>::kPoints> pts;
    membrane3d<N>(refs[e], s.x, *part.material, f, nullptr, &pts);
    out.insert(out.end(), pts.begin(), pts.end());
  }
};

/// The element type of the N-node surface membrane of kind `kind`.
template <int N>
ElementType surface_membrane_type(ElementKind kind, std::string name, std::uint8_t vtk_cell) {
  return {.kind = kind,
          .name = std::move(name),
          .nodes = N,
          .unknowns_per_node = 3,
          .solid = false,
          .pressure = true,
          .inverse = true,
          .vtk_cell = vtk_cell,
          .vtk_revolved_cell = 0,
          .points_per_element = [](const Part&) { return SurfaceShapeTraits<N>::kPoints; },
          .make = make_kernel_block<SurfaceMembraneKernel<N>>,
          .check = [](const Model& m, const Part& p, const ElementBlock& b, int first) {
            block_references<N>(m, p, b, first);
          }};
}

}  // namespace tunica
