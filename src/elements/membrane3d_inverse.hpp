#pragma once
// The 3-D membrane elements of the inverse problem (theory manual §13): the imaged (current)
// nodes x are known, the reference nodes X are the unknowns. The residual is the forward
// element's (membrane3d.hpp, (5.5)–(5.6)), evaluated at the reference data of X:
//     f(X, x) = membrane3d(membrane_reference(X, H, rule(X)), x),
// so that forward and inverse solve the same discrete equations; the tangent is its exact
// derivative ∂f/∂X (13.3)–(13.6), by forward-mode differentiation along each of the 3N reference
// coordinates, through the reference geometry (G_α, dA₀, the material frame, ∂N/∂s) and the
// material (dS = D dE).
#include "elements/membrane3d.hpp"

namespace tunica {

/// Material direction 1 of an element as a function of its reference nodes X (the frame rules of
/// a part, model/model.hpp: FrameRule), so that the inverse element can differentiate it:
///   fixed:      d = vector                    (a vector rule, or a direction from the mesh);
///   about_axis: d = axis × (X_q − point)      (the cylindrical rule, circumferential);
///   first_edge: d = X_1 − X_0                 (the default edge rule: any frame does for isotropic materials).
struct FrameDirection {
  enum class Kind { fixed, about_axis, first_edge } kind = Kind::fixed;
  Eigen::Vector3d vector = Eigen::Vector3d::UnitX();
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  /// The forward element's DirectionRule of an element with reference nodes X (N of them).
  template <int N>
  DirectionRule rule(const SurfaceNodes<N>& X) const {
    switch (kind) {
      case Kind::about_axis:
        return [a = axis, p = point](const Eigen::Vector3d& Xq, const Eigen::Vector3d&) -> Eigen::Vector3d {
          return a.cross(Xq - p);
        };
      case Kind::first_edge: {
        const Eigen::Vector3d v = X.col(1) - X.col(0);
        return [v](const Eigen::Vector3d&, const Eigen::Vector3d&) -> Eigen::Vector3d { return v; };
      }
      case Kind::fixed: break;
    }
    return [v = vector](const Eigen::Vector3d&, const Eigen::Vector3d&) -> Eigen::Vector3d { return v; };
  }
};

/// Internal force f(X, x) (3N) of the element with reference nodes X, imaged nodes x and reference
/// thickness H: exactly membrane3d() at membrane_reference(X, H, direction.rule(X)). If KX is given,
/// KX = ∂f/∂X (3N × 3N, node-major like f; not symmetric). Throws BadElement for a bad reference
/// element (membrane_reference) and std::domain_error where membrane3d() does.
/// With `imaged` (the wall thickness h_q of the imaged state x at each Gauss point; H unused), each
/// Gauss point's reference thickness is H_q = h_q λ₁λ₂ = h_q |g₁ × g₂|/|G₁ × G₂| (theory manual
/// (13.12)): the weight w_q H_q |G₁ × G₂| = w_q h_q |g₁ × g₂| then does not depend on X, (13.13).
/// `points`, if given, receives the Gauss-point states (Q of them).
/// Defined in membrane3d_inverse_impl.hpp, instantiated for N = 3, 4, 6 (membrane3d_inverse.cpp).
template <int N>
void membrane3d_inverse(const SurfaceNodes<N>& X, const SurfaceNodes<N>& x, double H, const FrameDirection& direction,
                        const MembraneMaterial& material, ElementVector<N>& f, ElementMatrix<N>* KX,
                        const std::array<double, SurfaceShapeTraits<N>::kPoints>* imaged = nullptr,
                        std::array<MembranePoint, SurfaceShapeTraits<N>::kPoints>* points = nullptr);

}  // namespace tunica
