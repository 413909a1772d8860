#pragma once
// Definitions of the 3-D membrane element templates (membrane3d.hpp; theory manual §5.1, (5.5)–(5.6);
// §2 for the material response). Equations, per Gauss point q with Gauss weight w_q:
//   reference:  G_α = Σ_a X_a ∂N_a/∂ξ^α,  n = G1 × G2 / |G1 × G2|,
//               dA₀ = |G1 × G2| dξ dη,
//               e1 = t/|t|, t = d − (d·n) n, d = DirectionRule(X_q, n);  e2 = n × e1,
//               A_iα = e_i·G_α,  ∂N_a/∂s_i = Σ_α ∂N_a/∂ξ^α (A⁻¹)_αi,
//               weight = w_q |G1 × G2| H;
//   current:    f_i = Σ_a x_a ∂N_a/∂s_i,  C_ij = f_i·f_j,  E = ½(C − I),
//               (S, D) = membrane_response(material, (C11, C22, C12)),
//               B_a = [∂N_a/∂s_1 f1ᵀ; ∂N_a/∂s_2 f2ᵀ; ∂N_a/∂s_2 f1ᵀ + ∂N_a/∂s_1 f2ᵀ]
//                     (δx_a ↦ (δE11, δE22, 2δE12)),
//               f_a += weight B_aᵀ S                (= Σ_ij S_ij f_i ∂N_a/∂s_j),
//               K_ab += weight [B_aᵀ D B_b + (Σ_ij S_ij ∂N_a/∂s_i ∂N_b/∂s_j) I₃];
//               computed for the nodes a, b ≥ 1, K_ab for b ≥ a only (K is symmetric); node 0's
//               from the others' (the partition of unity, Σ_a ∂N_a/∂s_i = 0):
//               f_0 = −Σ_{a≥1} f_a,  K_0b = −Σ_{a≥1} K_ab,  K_00 = −Σ_{b≥1} K_0bᵀ;
//   output:     σ = Σ_ij S_ij f_i f_jᵀ = F S Fᵀ (J = 1), σ_α = t_α·σ t_α with
//               t_α = f_α/|f_α|, principal values of σ restricted to the
//               current tangent plane, λ_α = √C_αα, λ₃ = √C33, h = λ₃ H.
//
// Included only by the files that instantiate them for a shape (membrane3d.cpp: tri3 and
// quad4; a new shape: its own file); every other file includes membrane3d.hpp.
#include "elements/membrane3d.hpp"
#include "elements/collapse.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include <stdexcept>
#include <string>

namespace tunica {

template <int N>
MembraneReference<N> membrane_reference(const SurfaceNodes<N>& X, double H, const DirectionRule& direction1) {
  constexpr int Q = SurfaceShapeTraits<N>::kPoints;
  MembraneReference<N> ref;
  ref.thickness.fill(H);

  // Square of the longest edge, corner to corner (the scale of the degeneracy test).
  constexpr int kCorners = SurfaceShapeTraits<N>::kCorners;
  double L2 = 0;
  for (int a = 0; a < kCorners; ++a) L2 = std::max(L2, (X.col((a + 1) % kCorners) - X.col(a)).squaredNorm());

  std::array<Eigen::Vector3d, Q> normal;  // G1 × G2 at each Gauss point
  for (int q = 0; q < Q; ++q) {
    double xi, eta, wq;
    gauss_point<N>(q, xi, eta, wq);
    const Eigen::Matrix<double, N, 2> dN = shape_derivatives<N>(xi, eta);
    const Eigen::Matrix<double, 3, 2> G = X * dN;  // G_α = ∂X/∂ξ^α
    normal[q] = G.col(0).cross(G.col(1));
    const double area = normal[q].norm();  // dA₀/(dξ dη)
    // Degenerate: |G1 × G2| ≤ 1e-12 × (longest edge)² (the area element per unit
    // parametric area: twice the area of a triangle, about a quarter of a
    // quadrilateral's); the negated test also catches non-finite X.
    if (!(area > 1e-12 * L2)) throw BadElement("degenerate element (zero area)");
    const Eigen::Vector3d n = normal[q] / area;

    ref.shape[q] = shape_values<N>(xi, eta);
    ref.X[q] = X * ref.shape[q];

    // Material frame: e1 = tangent projection of the wanted direction 1, normalized; e2 = n × e1.
    const Eigen::Vector3d d = direction1(ref.X[q], n);
    const Eigen::Vector3d t = d - d.dot(n) * n;
    const double tn = t.norm();
    if (!d.allFinite() || !(tn > kMinTangentFraction * d.norm()))
      throw BadElement("material direction 1 is normal to the surface (or not finite)");
    ref.e1[q] = t / tn;
    ref.e2[q] = n.cross(ref.e1[q]);

    // A_iα = e_i·G_α; ∂N/∂s = ∂N/∂ξ A⁻¹ (det A = |G1 × G2| > 0: (e1, e2, n) is right-handed).
    Eigen::Matrix2d A;
    A << ref.e1[q].dot(G.col(0)), ref.e1[q].dot(G.col(1)),  //
        ref.e2[q].dot(G.col(0)), ref.e2[q].dot(G.col(1));
    ref.dNds[q] = dN * A.inverse();
    ref.weight[q] = wq * area * H;
  }
  // Folded element (of more than one Gauss point): the normal G1 × G2 reverses between Gauss points.
  for (int q = 1; q < Q; ++q)
    if (!(normal[q].dot(normal[0]) > 0))
      throw BadElement(std::string("folded ") + SurfaceShapeTraits<N>::kName +
                       ": its normal reverses between its Gauss points (a node on the wrong side of the element?)");
  // A shape with nodes besides its corners (mid-edge nodes) can fold between its Gauss points, near a
  // corner: the normal is also checked at every node (SurfaceShapeTraits::node, where it declares it).
  if constexpr (requires(double xi, double eta) { SurfaceShapeTraits<N>::node(0, xi, eta); }) {
    for (int a = 0; a < N; ++a) {
      double xi, eta;
      SurfaceShapeTraits<N>::node(a, xi, eta);
      const Eigen::Matrix<double, 3, 2> G = X * shape_derivatives<N>(xi, eta);
      if (!(G.col(0).cross(G.col(1)).dot(normal[0]) > 0))
        throw BadElement(fmt::format("folded {}: its surface turns over at its {} node, the {} in its list (a mid-edge "
                                     "node too far from the middle of its edge?)",
                                     SurfaceShapeTraits<N>::kName,
                                     a < SurfaceShapeTraits<N>::kCorners ? "corner" : "mid-edge",
                                     std::array{"1st", "2nd", "3rd", "4th", "5th", "6th", "7th", "8th", "9th"}[std::min(a, 8)]));
    }
  }
  return ref;
}

template <int N>
void membrane3d(const MembraneReference<N>& ref, const SurfaceNodes<N>& x, const MembraneMaterial& material,
                ElementVector<N>& f, ElementMatrix<N>* K,
                std::array<MembranePoint, SurfaceShapeTraits<N>::kPoints>* points) {
  constexpr int Q = SurfaceShapeTraits<N>::kPoints;
  // Nodes 1 … N−1: f_a and K_ab are linear in ∂N_a/∂s (and K_ab in ∂N_b/∂s), and Σ_a ∂N_a/∂s = 0
  // (Σ_a N_a = 1), so Σ_a f_a = 0 and Σ_a K_ab = 0: node 0's force and blocks follow from the others'
  // after the Gauss loop.
  constexpr int M = N - 1;
  Eigen::Matrix<double, 3, M> fr = Eigen::Matrix<double, 3, M>::Zero();  // column a − 1 is f_a
  for (int q = 0; q < Q; ++q) {
    const Eigen::Matrix<double, N, 2>& dN = ref.dNds[q];
    const Eigen::Matrix<double, 3, 2> F = x * dN;  // columns f_i = ∂x/∂s_i
    const Eigen::Vector3d f1 = F.col(0), f2 = F.col(1);
    const Eigen::Vector3d C(f1.squaredNorm(), f2.squaredNorm(), f1.dot(f2));
    if (!(C(0) * C(1) - C(2) * C(2) > 0))
      throw std::domain_error("3-D membrane: in-plane det C is not positive at a Gauss point (element collapsed)");
    if (!(C(0) * C(1) - C(2) * C(2) > kCollapsedAreaStretch * kCollapsedAreaStretch))  // det C = (λ₁λ₂)²
      throw std::domain_error(collapse_message("3-D membrane: at a Gauss point"));
    const MembraneResponse m = membrane_response(material, C);
    const double w = ref.weight[q];
    Eigen::Matrix2d S2;  // S as a 2 × 2 tensor
    S2 << m.S(0), m.S(2), m.S(2), m.S(1);
    const Eigen::Matrix2d wS2 = w * S2;
    const auto dNr = dN.template bottomRows<M>();  // ∂N_a/∂s of nodes 1 … N−1

    // (5.6): f_a += w B_aᵀ S = w Σ_ij S_ij f_i ∂N_a/∂s_j, i.e. (f_1 … f_{N−1}) += (F w S₂) ∂N/∂sᵀ.
    fr.noalias() += (F * wS2) * dNr.transpose();
    if (K) {
      // (5.6) with B_a = β_a1 f1ᵀ + β_a2 f2ᵀ, β_a1 = (∂N_a/∂s_1, 0, ∂N_a/∂s_2), β_a2 = (0, ∂N_a/∂s_2, ∂N_a/∂s_1):
      //   K_ab = w B_aᵀ D B_b + G_ab I₃ = Σ_ij M_ij f_i f_jᵀ + G_ab I₃ = f1 uᵀ + f2 vᵀ + G_ab I₃,
      //   M_ij = w β_aiᵀ D β_bj,  u = M_11 f1 + M_12 f2,  v = M_21 f1 + M_22 f2,  G_ab = w ∂N_a/∂s · S ∂N_b/∂s,
      // for 1 ≤ a ≤ b (D and S are symmetric: K_ba = K_abᵀ).
      const Eigen::Matrix3d wD = w * m.D;
      for (int b = 1; b < N; ++b) {
        const double n1 = dN(b, 0), n2 = dN(b, 1);
        const Eigen::Vector3d Dbeta1 = n1 * wD.col(0) + n2 * wD.col(2), Dbeta2 = n2 * wD.col(1) + n1 * wD.col(2);
        const Eigen::Vector2d Sb = wS2 * dN.row(b).transpose();
        for (int a = 1; a <= b; ++a) {
          const double m1 = dN(a, 0), m2 = dN(a, 1);
          const double M11 = m1 * Dbeta1(0) + m2 * Dbeta1(2), M21 = m2 * Dbeta1(1) + m1 * Dbeta1(2);
          const double M12 = m1 * Dbeta2(0) + m2 * Dbeta2(2), M22 = m2 * Dbeta2(1) + m1 * Dbeta2(2);
          const Eigen::Vector3d u = M11 * f1 + M12 * f2, v = M21 * f1 + M22 * f2;
          Eigen::Matrix3d Kab = f1 * u.transpose() + f2 * v.transpose();
          Kab.diagonal().array() += m1 * Sb(0) + m2 * Sb(1);
          auto out = K->template block<3, 3>(3 * a, 3 * b);
          if (q == 0) out = Kab;  // every one of these blocks is set at the first Gauss point
          else out += Kab;
        }
      }
    }
    if (points) {
      MembranePoint& p = (*points)[q];
      p.X = ref.X[q];
      p.x = x * ref.shape[q];
      p.R = std::hypot(p.X.x(), p.X.y());
      p.r = std::hypot(p.x.x(), p.x.y());
      p.z = p.x.z();
      p.lambda = Eigen::Vector3d(std::sqrt(C(0)), std::sqrt(C(1)), std::sqrt(m.C33));
      p.E = Eigen::Vector3d(0.5 * (C(0) - 1.0), 0.5 * (C(1) - 1.0), 0.5 * C(2));
      p.S = m.S;
      p.cauchy = F * S2 * F.transpose();  // σ = F S Fᵀ / J, J = 1
      // σ_α = t_α·σ t_α = (f_α·σ f_α)/C_αα.
      p.sigma = Eigen::Vector2d(f1.dot(p.cauchy * f1) / C(0), f2.dot(p.cauchy * f2) / C(1));
      // Principal values in the current tangent plane: σ in the orthonormal basis (t1, t2').
      const Eigen::Vector3d t1 = f1 / std::sqrt(C(0));
      const Eigen::Vector3d t2 = (f2 - f2.dot(t1) * t1).normalized();
      const double s11 = t1.dot(p.cauchy * t1), s22 = t2.dot(p.cauchy * t2), s12 = t1.dot(p.cauchy * t2);
      const double mean = 0.5 * (s11 + s22), rad = std::hypot(0.5 * (s11 - s22), s12);
      p.sigma_principal = Eigen::Vector2d(mean + rad, mean - rad);
      p.e1 = ref.e1[q];
      p.e2 = ref.e2[q];
      p.thickness = p.lambda(2) * ref.thickness[q];
      p.reference_thickness = ref.thickness[q];
      p.W = m.W;
      p.weight = w;
    }
  }
  // Node 0: f_0 = −Σ_{a≥1} f_a.
  f.template head<3>() = -fr.rowwise().sum();
  f.template tail<3 * M>() = fr.reshaped();
  if (K) {
    const auto block = [&](int a, int b) { return K->template block<3, 3>(3 * a, 3 * b); };
    // Below the diagonal, nodes 1 … N−1: K_ba = K_abᵀ.
    for (int b = 1; b < N; ++b)
      for (int a = 1; a < b; ++a) block(b, a) = block(a, b).transpose();
    // K_0b = −Σ_{a≥1} K_ab and K_b0 = K_0bᵀ (b ≥ 1).
    for (int b = 1; b < N; ++b) {
      Eigen::Matrix3d k0b = -block(1, b);
      for (int a = 2; a < N; ++a) k0b -= block(a, b);
      block(0, b) = k0b;
      block(b, 0) = k0b.transpose();
    }
    // K_00 = −Σ_{b≥1} K_b0, symmetric: its upper triangle, mirrored.
    Eigen::Matrix3d k00 = -block(1, 0);
    for (int b = 2; b < N; ++b) k00 -= block(b, 0);
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i <= j; ++i) (*K)(i, j) = (*K)(j, i) = k00(i, j);
  }
}

}  // namespace tunica
