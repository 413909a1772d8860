#pragma once
// Definition of membrane3d_inverse (membrane3d_inverse.hpp; theory manual §13, (13.3)–(13.6)).
// The residual is the forward element's; the tangent ∂f/∂X is its derivative along each reference
// coordinate X_k (node a = k / 3, component c = k % 3), per Gauss point q, by the chain rule
// (forward mode, one direction at a time; δ· is the derivative along X_k, e_c the unit vector):
//   δG_α = ∂N_a/∂ξ^α e_c,   ν = G1 × G2,  δν = δG1 × G2 + G1 × δG2,
//   dA₀ = |ν|: δ|ν| = n·δν,   n = ν/|ν|: δn = (δν − n (n·δν))/|ν|,
//   X_q = Σ_b N_b X_b: δX_q = N_a e_c,   d = direction(X): δd = 0, axis × δX_q, or δX_1 − δX_0,
//   t = d − (d·n) n: δt = δd − (δd·n + d·δn) n − (d·n) δn,
//   e1 = t/|t|: δe1 = (δt − e1 (e1·δt))/|t|,   e2 = n × e1: δe2 = δn × e1 + n × δe1,
//   A_iα = e_i·G_α: δA_iα = δe_i·G_α + e_i·δG_α,   δ(A⁻¹) = −A⁻¹ δA A⁻¹,
//   ∂N/∂s = ∂N/∂ξ A⁻¹: δ(∂N/∂s) = ∂N/∂ξ δ(A⁻¹),   weight w = w_q |ν| H: δw = w_q H δ|ν|,
//   F = x ∂N/∂s: δF = x δ(∂N/∂s),   δC = (2 f1·δf1, 2 f2·δf2, δf1·f2 + f1·δf2),
//   δS = D (½δC11, ½δC22, δC12)   (D maps (δE11, δE22, 2δE12), membrane_response),
//   f = F (w S) (∂N/∂s)ᵀ (column a = f_a, (5.6)):
//   δf = F (δw S + w δS) (∂N/∂s)ᵀ + δF (w S) (∂N/∂s)ᵀ + F (w S) δ(∂N/∂s)ᵀ,
// and column k of KX is δf. With an imaged thickness h_q (13.12), H_q = h_q |g1 × g2|/|G1 × G2|
// (g_α = Σ_a x_a ∂N_a/∂ξ^α) and w = w_q h_q |g1 × g2| depends on the imaged nodes alone: δw = 0
// (13.13), the δH_q = −H_q n·δν/|ν| of the area stretch cancelling δ|ν|.
// Included only by membrane3d_inverse.cpp.
#include "elements/membrane3d_inverse.hpp"

namespace tunica {

namespace detail {
/// (v0, v1, v2) as the symmetric 2 × 2 tensor [[v0, v2], [v2, v1]].
inline Eigen::Matrix2d symmetric2(const Eigen::Vector3d& v) {
  Eigen::Matrix2d m;
  m << v(0), v(2), v(2), v(1);
  return m;
}
}  // namespace detail

template <int N>
void membrane3d_inverse(const SurfaceNodes<N>& X, const SurfaceNodes<N>& x, double H, const FrameDirection& direction,
                        const MembraneMaterial& material, ElementVector<N>& f, ElementMatrix<N>* KX,
                        const std::array<double, SurfaceShapeTraits<N>::kPoints>* imaged,
                        std::array<MembranePoint, SurfaceShapeTraits<N>::kPoints>* points) {
  constexpr int Q = SurfaceShapeTraits<N>::kPoints;
  // The residual: the forward element at the reference data of X (the same discrete equations).
  MembraneReference<N> ref = membrane_reference<N>(X, H, direction.rule<N>(X));
  if (imaged)  // H_q = h_q λ₁λ₂ (13.12), the weight w_q H_q |G1 × G2| = w_q h_q |g1 × g2|
    for (int q = 0; q < Q; ++q) {
      double xi, eta, wq;
      gauss_point<N>(q, xi, eta, wq);
      const Eigen::Matrix<double, N, 2> dN = shape_derivatives<N>(xi, eta);
      const Eigen::Matrix<double, 3, 2> G = X * dN, g = x * dN;
      const double da = g.col(0).cross(g.col(1)).norm();
      ref.thickness[q] = (*imaged)[q] * da / G.col(0).cross(G.col(1)).norm();
      ref.weight[q] = wq * da * (*imaged)[q];
    }
  membrane3d<N>(ref, x, material, f, nullptr, points);
  if (!KX) return;
  KX->setZero();
  for (int q = 0; q < Q; ++q) {
    double xi, eta, wq;
    gauss_point<N>(q, xi, eta, wq);
    const Eigen::Matrix<double, N, 2> dN = shape_derivatives<N>(xi, eta);
    const Eigen::Matrix<double, N, 1> Nq = shape_values<N>(xi, eta);
    // Values at q, as membrane_reference() and membrane3d() compute them.
    const Eigen::Matrix<double, 3, 2> G = X * dN;
    const Eigen::Vector3d nu = G.col(0).cross(G.col(1));
    const double area = nu.norm();
    const Eigen::Vector3d n = nu / area;
    const Eigen::Vector3d Xq = X * Nq;
    const Eigen::Vector3d d = direction.rule<N>(X)(Xq, n);
    const Eigen::Vector3d t = d - d.dot(n) * n;
    const double tn = t.norm();
    const Eigen::Vector3d e1 = ref.e1[q], e2 = ref.e2[q];
    Eigen::Matrix<double, 3, 2> E;
    E << e1, e2;
    const Eigen::Matrix2d Ainv = (E.transpose() * G).inverse();
    const Eigen::Matrix<double, N, 2>& dNds = ref.dNds[q];
    const double w = ref.weight[q];
    const Eigen::Matrix<double, 3, 2> F = x * dNds;
    const Eigen::Vector3d f1 = F.col(0), f2 = F.col(1);
    const MembraneResponse m = membrane_response(material, Eigen::Vector3d(f1.squaredNorm(), f2.squaredNorm(), f1.dot(f2)));
    const Eigen::Matrix2d S2 = detail::symmetric2(m.S);

    for (int k = 0; k < 3 * N; ++k) {
      const int a = k / 3;
      const Eigen::Vector3d ec = Eigen::Vector3d::Unit(k % 3);
      const Eigen::Matrix<double, 3, 2> dG = ec * dN.row(a);
      const Eigen::Vector3d dnu = dG.col(0).cross(G.col(1)) + G.col(0).cross(dG.col(1));
      const double darea = n.dot(dnu);
      const Eigen::Vector3d dn = (dnu - n * darea) / area;
      Eigen::Vector3d dd = Eigen::Vector3d::Zero();
      switch (direction.kind) {
        case FrameDirection::Kind::about_axis: dd = direction.axis.cross(Nq(a) * ec); break;
        case FrameDirection::Kind::first_edge: dd = (a == 1 ? 1.0 : 0.0) * ec - (a == 0 ? 1.0 : 0.0) * ec; break;
        case FrameDirection::Kind::fixed: break;
      }
      const Eigen::Vector3d dt = dd - (dd.dot(n) + d.dot(dn)) * n - d.dot(n) * dn;
      const Eigen::Vector3d de1 = (dt - e1 * e1.dot(dt)) / tn;
      const Eigen::Vector3d de2 = dn.cross(e1) + n.cross(de1);
      Eigen::Matrix<double, 3, 2> dE;
      dE << de1, de2;
      const Eigen::Matrix2d dA = dE.transpose() * G + E.transpose() * dG;
      const Eigen::Matrix<double, N, 2> ddNds = dN * (-Ainv * dA * Ainv);
      const double dw = imaged ? 0.0 : wq * H * darea;  // (13.5), (13.13)
      const Eigen::Matrix<double, 3, 2> dF = x * ddNds;
      const Eigen::Vector3d df1 = dF.col(0), df2 = dF.col(1);
      const Eigen::Vector3d dE3(f1.dot(df1), f2.dot(df2), df1.dot(f2) + f1.dot(df2));  // (δE11, δE22, 2δE12)
      const Eigen::Matrix2d dS2 = detail::symmetric2(m.D * dE3);
      const Eigen::Matrix<double, 3, N> df = F * (dw * S2 + w * dS2) * dNds.transpose() +
                                             dF * (w * S2) * dNds.transpose() + F * (w * S2) * ddNds.transpose();
      KX->col(k) += df.reshaped();
    }
  }
}

}  // namespace tunica
