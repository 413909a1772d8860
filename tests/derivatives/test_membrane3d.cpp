// Finite-difference and invariance checks of the 3-D membrane elements
// (membrane3d.hpp), tri3, quad4 and tri6, over every registered material, each of its samples
// and each of the sample's orientations (tests/support/material_registry.hpp):
//  - the internal force (5.6) is the gradient of the stored energy Σ_q weight·Ŵ;
//  - the tangent (5.6) is the Jacobian of the internal force, and is symmetric;
// at random distorted, rotated, sheared current states of random distorted reference
// elements (quad: warped; tri6: curved), with material directions not aligned with the
// edges, turned by the sample's orientation; rigid rotations of reference, current state and
// direction rule leave W, S, E, λ unchanged and rotate f and K; the Gauss-point
// output is consistent (σ = F S Fᵀ tangent to the surface, its in-plane
// principal values); bad reference elements throw BadElement (degenerate, folded, a
// direction normal to the surface).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>
#include <string>

#include "../support/fd.hpp"
#include "../support/material_registry.hpp"
#include "../support/six_node_triangle.hpp"
#include "elements/membrane3d.hpp"

using namespace tunica;
using tunica::test::fd_gradient;
using tunica::test::fd_jacobian;
using tunica::test::kFdTolerance;
using tunica::test::MaterialCase;
using tunica::test::material_from_yaml;
using tunica::test::relative_error;

namespace {

// Fung with every term, for the output checks below (any anisotropic material would do).
const char* kFung3d = "{type: fung, c: 0.05, a1: 1.1, a2: 0.7, a3: 0.9, a4: 0.2, a5: 0.15, a6: -0.1, a7: 0.4}";

Eigen::Matrix3d random_rotation(std::mt19937& rng) {
  std::normal_distribution<double> g;
  return Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng)).normalized().toRotationMatrix();
}

/// A random reference element: a distorted (quad: warped, non-planar; tri6: curved, its
/// mid-edge nodes off the chords, in and out of the plane) element, randomly rotated and translated.
template <int N>
SurfaceNodes<N> random_reference(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  SurfaceNodes<N> X;
  if constexpr (N == 6) {
    return tunica::test::six_node_triangle(random_reference<3>(rng), Eigen::Vector3d::Constant(0.12), rng);
  } else if constexpr (N == 3) {
    X << 0, 1.0, 0.3, 0, 0.1, 0.9, 0, 0, 0;
  } else {
    X << 0, 1.0, 1.1, -0.1, 0, 0, 0.9, 1.0, 0, 0, 0, 0;
  }
  X.topRows(2) += 0.12 * Eigen::Matrix<double, 2, N>::NullaryExpr([&] { return u(rng); });
  if constexpr (N == 4) X.row(2) += 0.15 * Eigen::Matrix<double, 1, N>::NullaryExpr([&] { return u(rng); });
  const Eigen::Matrix3d Q = random_rotation(rng);
  const Eigen::Vector3d c(u(rng), u(rng), u(rng));
  return (Q * X).colwise() + c;
}

/// A distorted current state: rigid rotation and translation of a stretched,
/// sheared element (a linear map Q₁ diag(s) Q₂ of singular values s ∈ [0.8, 1.6], so that
/// every stretch of the element lies in [0.8, 1.6]), plus random nodal perturbations.
template <int N>
SurfaceNodes<N> random_current(std::mt19937& rng, const SurfaceNodes<N>& X) {
  std::uniform_real_distribution<double> u(-1, 1), stretch(0.8, 1.6);
  const Eigen::Vector3d s(stretch(rng), stretch(rng), stretch(rng));
  const Eigen::Matrix3d A = random_rotation(rng) * s.asDiagonal() * random_rotation(rng);
  const Eigen::Matrix3d Q = random_rotation(rng);
  SurfaceNodes<N> x = Q * A * X;
  x.colwise() += Eigen::Vector3d(u(rng), u(rng), u(rng));
  x += 0.05 * SurfaceNodes<N>::NullaryExpr([&] { return u(rng); });
  return x;
}

/// Material direction rules: a fixed skew direction, and one varying in space.
DirectionRule direction_rule(int k) {
  if (k % 2 == 0) return [](const Eigen::Vector3d&, const Eigen::Vector3d&) { return Eigen::Vector3d(0.3, 0.8, -0.5); };
  return [](const Eigen::Vector3d& X, const Eigen::Vector3d& n) -> Eigen::Vector3d {
    return Eigen::Vector3d(0.4 + X.y(), 0.7 - X.x(), 0.2) + 0.3 * n;
  };
}

/// The direction rule k turned by `angle` about the surface normal, in the tangent plane.
DirectionRule direction_rule(int k, double angle) {
  const DirectionRule base = direction_rule(k);
  return [base, angle](const Eigen::Vector3d& X, const Eigen::Vector3d& n) -> Eigen::Vector3d {
    Eigen::Vector3d d = base(X, n);
    d = (d - d.dot(n) * n).normalized();
    return std::cos(angle) * d + std::sin(angle) * n.cross(d);
  };
}

template <int N>
SurfaceNodes<N> nodes(const Eigen::VectorXd& v) {
  return Eigen::Map<const SurfaceNodes<N>>(v.data());
}
template <int N>
Eigen::VectorXd flat(const SurfaceNodes<N>& x) {
  return Eigen::Map<const Eigen::VectorXd>(x.data(), 3 * N);
}

template <int N>
void check_derivatives(const MembraneMaterial& material, double angle, std::mt19937& rng, double& max_grad_err,
                       double& max_tan_err, double& max_asym) {
  constexpr int Q = SurfaceShapeTraits<N>::kPoints;
  for (int k = 0; k < 6; ++k) {
    const SurfaceNodes<N> X = random_reference<N>(rng);
    auto ref = membrane_reference<N>(X, 0.13, direction_rule(k, angle));
    // Every other state with a prestretch P per Gauss point (a prestress step, theory manual (13.20)):
    // stretches 0.7–1.5 and shear up to ±0.3, P not symmetric.
    if (k % 2 == 1) {
      std::uniform_real_distribution<double> stretch(0.7, 1.5), shear(-0.3, 0.3);
      for (int q = 0; q < Q; ++q) {
        Eigen::Matrix2d P;
        P << stretch(rng), shear(rng), shear(rng), stretch(rng);
        prestretch_reference<N>(ref, q, P);
      }
    }
    const SurfaceNodes<N> x = random_current<N>(rng, X);
    ElementVector<N> f;
    ElementMatrix<N> K;
    membrane3d<N>(ref, x, material, f, &K);
    const auto energy = [&](const Eigen::VectorXd& v) {
      ElementVector<N> g;
      std::array<MembranePoint, Q> pts;
      membrane3d<N>(ref, nodes<N>(v), material, g, nullptr, &pts);
      double U = 0;
      for (const auto& p : pts) U += p.W * p.weight;
      return U;
    };
    const auto force = [&](const Eigen::VectorXd& v) -> Eigen::VectorXd {
      ElementVector<N> g;
      membrane3d<N>(ref, nodes<N>(v), material, g, nullptr);
      return g;
    };
    const double eg = relative_error(f, fd_gradient(energy, flat<N>(x), 1e-6));
    const double ek = relative_error(K, fd_jacobian(force, flat<N>(x), 1e-6));
    const double ea = (K - K.transpose()).norm() / K.norm();
    EXPECT_LT(eg, kFdTolerance) << "N=" << N << " k=" << k;
    EXPECT_LT(ek, kFdTolerance) << "N=" << N << " k=" << k;
    EXPECT_LT(ea, 1e-13) << "N=" << N << " k=" << k;
    max_grad_err = std::max(max_grad_err, eg);
    max_tan_err = std::max(max_tan_err, ek);
    max_asym = std::max(max_asym, ea);
  }
}

template <int N>
Eigen::Matrix<double, 3 * N, 3 * N> block_rotation(const Eigen::Matrix3d& Q) {
  Eigen::Matrix<double, 3 * N, 3 * N> R = Eigen::Matrix<double, 3 * N, 3 * N>::Zero();
  for (int a = 0; a < N; ++a) R.template block<3, 3>(3 * a, 3 * a) = Q;
  return R;
}

template <int N>
void check_rotation_invariance(const MembraneMaterial& material, double angle, std::mt19937& rng) {
  constexpr int Q = SurfaceShapeTraits<N>::kPoints;
  for (int k = 0; k < 3; ++k) {
    const SurfaceNodes<N> X = random_reference<N>(rng);
    const SurfaceNodes<N> x = random_current<N>(rng, X);
    const DirectionRule rule = direction_rule(k, angle);
    const Eigen::Matrix3d R = random_rotation(rng);
    const DirectionRule rotated = [&](const Eigen::Vector3d& Xr, const Eigen::Vector3d& n) -> Eigen::Vector3d {
      return R * rule(R.transpose() * Xr, R.transpose() * n);
    };
    const auto ref = membrane_reference<N>(X, 0.1, rule);
    const auto refR = membrane_reference<N>(R * X, 0.1, rotated);
    ElementVector<N> f, fR;
    ElementMatrix<N> K, KR;
    std::array<MembranePoint, Q> p, pR;
    membrane3d<N>(ref, x, material, f, &K, &p);
    membrane3d<N>(refR, R * x, material, fR, &KR, &pR);
    const auto Rb = block_rotation<N>(R);
    EXPECT_LT(relative_error(fR, Rb * f), 1e-12);
    EXPECT_LT(relative_error(KR, Rb * K * Rb.transpose()), 1e-12);
    for (int q = 0; q < Q; ++q) {
      EXPECT_NEAR(pR[q].W, p[q].W, 1e-12 * std::abs(p[q].W) + 1e-15);
      EXPECT_NEAR(pR[q].weight, p[q].weight, 1e-13);
      EXPECT_LT(relative_error(pR[q].S, p[q].S), 1e-12);
      EXPECT_LT(relative_error(pR[q].E, p[q].E), 1e-12);
      EXPECT_LT(relative_error(pR[q].lambda, p[q].lambda), 1e-13);
      EXPECT_LT(relative_error(pR[q].e1, R * p[q].e1), 1e-13);
      EXPECT_LT(relative_error(pR[q].e2, R * p[q].e2), 1e-13);
      EXPECT_LT(relative_error(pR[q].cauchy, R * p[q].cauchy * R.transpose()), 1e-12);
      EXPECT_LT(relative_error(pR[q].sigma_principal, p[q].sigma_principal), 1e-12);
    }
  }
}

/// The elements over every registered material × sample × orientation of the material frame.
class Membrane3dFd : public ::testing::TestWithParam<MaterialCase> {
protected:
  void SetUp() override { m = tunica::test::make_membrane(GetParam()); }
  std::unique_ptr<MembraneMaterial> m;
};

INSTANTIATE_TEST_SUITE_P(Registry, Membrane3dFd,
                         ::testing::ValuesIn(tunica::test::membrane_cases(tunica::test::Orientations::each)),
                         tunica::test::case_name);

}  // namespace

TEST_P(Membrane3dFd, InternalForceIsEnergyGradientAndTangentIsItsJacobian) {
  std::mt19937 rng(11);
  double eg = 0, ek = 0, ea = 0;
  check_derivatives<3>(*m, GetParam().angle, rng, eg, ek, ea);
  check_derivatives<4>(*m, GetParam().angle, rng, eg, ek, ea);
  check_derivatives<6>(*m, GetParam().angle, rng, eg, ek, ea);
  tunica::test::record_error("worst_relative_error_force", eg);
  tunica::test::record_error("worst_relative_error_tangent", ek);
  tunica::test::record_error("worst_asymmetry", ea);
}

TEST_P(Membrane3dFd, RigidRotationOfReferenceCurrentAndDirectionRuleRotatesForceAndTangent) {
  std::mt19937 rng(12);
  check_rotation_invariance<3>(*m, GetParam().angle, rng);
  check_rotation_invariance<4>(*m, GetParam().angle, rng);
  check_rotation_invariance<6>(*m, GetParam().angle, rng);
}

namespace {

// σ = F S Fᵀ is symmetric and tangent to the current surface (σ n = 0); its
// nonzero eigenvalues are the in-plane principal stresses; σ_α = t_α·σ t_α;
// the material frame is orthonormal and tangent; x, X are the interpolated
// positions; E = ½(λ² − 1) on the diagonal; incompressibility λ3² det C = 1;
// h = λ3 H; weight = Gauss weight × |G1 × G2| × H.
template <int N>
void check_output(const MembraneMaterial& material, std::mt19937& rng) {
  constexpr int Q = SurfaceShapeTraits<N>::kPoints;
  for (int k = 0; k < 10; ++k) {
    const SurfaceNodes<N> X = random_reference<N>(rng);
    const SurfaceNodes<N> x = random_current<N>(rng, X);
    const double H = 0.2;
    const auto ref = membrane_reference<N>(X, H, direction_rule(k));
    ElementVector<N> f;
    std::array<MembranePoint, Q> pts;
    membrane3d<N>(ref, x, material, f, nullptr, &pts);
    for (int q = 0; q < Q; ++q) {
      const MembranePoint& p = pts[q];
      double xi, eta, w;
      gauss_point<N>(q, xi, eta, w);
      const Eigen::Matrix<double, N, 1> Nq = shape_values<N>(xi, eta);
      const Eigen::Matrix<double, N, 2> dN = shape_derivatives<N>(xi, eta);
      EXPECT_LT((p.X - X * Nq).norm(), 1e-14);
      EXPECT_LT((p.x - x * Nq).norm(), 1e-14);
      EXPECT_DOUBLE_EQ(p.R, std::hypot(p.X(0), p.X(1)));
      EXPECT_DOUBLE_EQ(p.r, std::hypot(p.x(0), p.x(1)));
      EXPECT_DOUBLE_EQ(p.z, p.x(2));
      const Eigen::Vector3d N0 = (X * dN).col(0).cross((X * dN).col(1)).normalized();
      EXPECT_NEAR(p.e1.norm(), 1, 1e-14);
      EXPECT_NEAR(p.e2.norm(), 1, 1e-14);
      EXPECT_NEAR(p.e1.dot(p.e2), 0, 1e-14);
      // N0 is recomputed here in another order of operations than the element's normal: their
      // difference is round-off amplified by the random element's distortion (a few hundred ε).
      EXPECT_NEAR(p.e1.dot(N0), 0, 1e-12);
      EXPECT_LT((p.e1.cross(p.e2) - N0).norm(), 1e-12);
      EXPECT_NEAR(p.weight, w * (X * dN).col(0).cross((X * dN).col(1)).norm() * H, 1e-14);
      // Stretches and strains.
      for (int i = 0; i < 2; ++i) EXPECT_NEAR(p.E(i), 0.5 * (p.lambda(i) * p.lambda(i) - 1), 1e-13);
      const double detC = (1 + 2 * p.E(0)) * (1 + 2 * p.E(1)) - 4 * p.E(2) * p.E(2);
      EXPECT_NEAR(p.lambda(2) * p.lambda(2) * detC, 1, 1e-12);
      EXPECT_NEAR(p.thickness, p.lambda(2) * H, 1e-15);
      // Cauchy stress.
      const Eigen::Matrix<double, 3, 2> g = x * dN;
      const Eigen::Vector3d n = g.col(0).cross(g.col(1)).normalized();
      EXPECT_LT((p.cauchy - p.cauchy.transpose()).norm(), 1e-13 * p.cauchy.norm());
      EXPECT_LT((p.cauchy * n).norm(), 1e-12 * p.cauchy.norm());
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(p.cauchy);
      Eigen::Vector3d ev = es.eigenvalues();  // ascending; one is 0
      int zero = 0;
      for (int i = 1; i < 3; ++i)
        if (std::abs(ev(i)) < std::abs(ev(zero))) zero = i;
      std::vector<double> nz;
      for (int i = 0; i < 3; ++i)
        if (i != zero) nz.push_back(ev(i));
      EXPECT_NEAR(p.sigma_principal(0), std::max(nz[0], nz[1]), 1e-12 * p.cauchy.norm());
      EXPECT_NEAR(p.sigma_principal(1), std::min(nz[0], nz[1]), 1e-12 * p.cauchy.norm());
      // σ_α along the convected directions f_α = F e_α: recompute F from the material frame.
      const Eigen::Matrix<double, N, 2> dNds = ref.dNds[q];
      for (int a = 0; a < 2; ++a) {
        const Eigen::Vector3d t = (x * dNds.col(a)).normalized();
        EXPECT_NEAR(p.sigma(a), t.dot(p.cauchy * t), 1e-12 * p.cauchy.norm());
        EXPECT_NEAR((x * dNds.col(a)).norm(), p.lambda(a), 1e-13);
      }
    }
  }
}

}  // namespace

TEST(Membrane3d, GaussPointOutputIsConsistent) {
  std::mt19937 rng(13);
  const auto m = material_from_yaml(kFung3d);
  check_output<4>(*m, rng);
  check_output<6>(*m, rng);
}

TEST(Membrane3d, EquibiaxialStretchOfANeoHookeanPatch) {
  // W = μ/2 (C11 + C22 + C33 − 3), C33 = 1/det C: S_αα = 2 ∂Ŵ/∂C_αα = μ(1 − C33/C_αα).
  // Equibiaxial λ: C11 = C22 = λ², C33 = λ⁻⁴: S = μ(1 − λ⁻⁶), σ = λ² S = μ(λ² − λ⁻⁴),
  // h = H λ⁻², Ŵ = μ/2 (2λ² + λ⁻⁴ − 3). The material frame is skew to the edges.
  const double mu = 0.3, lam = 1.37, H = 0.05;
  const auto m = material_from_yaml("{type: neo_hookean, mu: 0.3}");
  const DirectionRule rule = [](const Eigen::Vector3d&, const Eigen::Vector3d&) { return Eigen::Vector3d(1, 2, 0); };
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.6, Eigen::Vector3d(1, -2, 0.5).normalized()).toRotationMatrix();
  SurfaceNodes<4> X;
  X << 0, 1.2, 1.3, -0.2, 0, 0.1, 1.0, 0.8, 0, 0, 0, 0;
  const SurfaceNodes<4> x = lam * (R * X);  // stretched and rotated
  const auto ref = membrane_reference<4>(X, H, rule);
  ElementVector<4> f;
  std::array<MembranePoint, 4> pts;
  membrane3d<4>(ref, x, *m, f, nullptr, &pts);
  const double S = mu * (1 - std::pow(lam, -6)), sigma = mu * (lam * lam - std::pow(lam, -4));
  for (const auto& p : pts) {
    EXPECT_NEAR(p.S(0), S, 1e-14);
    EXPECT_NEAR(p.S(1), S, 1e-14);
    EXPECT_NEAR(p.S(2), 0, 1e-14);
    EXPECT_NEAR(p.sigma(0), sigma, 1e-14);
    EXPECT_NEAR(p.sigma(1), sigma, 1e-14);
    EXPECT_NEAR(p.sigma_principal(0), sigma, 1e-14);
    EXPECT_NEAR(p.sigma_principal(1), sigma, 1e-14);
    EXPECT_NEAR(p.lambda(0), lam, 1e-14);
    EXPECT_NEAR(p.lambda(2), 1 / (lam * lam), 1e-14);
    EXPECT_NEAR(p.thickness, H / (lam * lam), 1e-15);
    EXPECT_NEAR(p.W, 0.5 * mu * (2 * lam * lam + std::pow(lam, -4) - 3), 1e-14);
    EXPECT_NEAR(p.E(0), 0.5 * (lam * lam - 1), 1e-14);
    EXPECT_LT((p.e1 - Eigen::Vector3d(1, 2, 0).normalized()).norm(), 1e-15);
  }
  // The same with a triangle, and the numbers for λ = 1.37, μ = 0.3: S = 0.254627, σ = 0.477909.
  SurfaceNodes<3> Xt;
  Xt << 0, 1, 0.3, 0, 0.2, 0.9, 0, 0, 0;
  const auto reft = membrane_reference<3>(Xt, H, rule);
  ElementVector<3> ft;
  std::array<MembranePoint, 1> pt;
  membrane3d<3>(reft, lam * (R * Xt), *m, ft, nullptr, &pt);
  EXPECT_NEAR(pt[0].S(0), S, 1e-14);
  EXPECT_NEAR(pt[0].sigma_principal(1), sigma, 1e-14);
  EXPECT_NEAR(S, 0.2546269627, 1e-10);      // λ⁶ = 1.37⁶ = 6.61185625...
  EXPECT_NEAR(sigma, 0.4779093464, 1e-10);  // λ² = 1.8769, λ⁴ = 3.52275361
}

TEST(Membrane3d, BadElementsThrow) {
  const DirectionRule rule = [](const Eigen::Vector3d&, const Eigen::Vector3d&) { return Eigen::Vector3d(1, 0.2, 0); };
  const auto expect_bad = [](auto&& make, const std::string& what) {
    try {
      make();
      ADD_FAILURE() << "no BadElement: expected \"" << what << "\"";
    } catch (const BadElement& e) {
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  };
  SurfaceNodes<3> collinear;
  collinear << 0, 1, 2.5, 0, 1, 2.5, 0, 1, 2.5;
  expect_bad([&] { membrane_reference<3>(collinear, 0.1, rule); }, "degenerate element (zero area)");
  SurfaceNodes<3> point = SurfaceNodes<3>::Constant(0.7);
  expect_bad([&] { membrane_reference<3>(point, 0.1, rule); }, "degenerate element (zero area)");
  SurfaceNodes<3> sliver;  // area 1e-14 of edge² 1
  sliver << 0, 1, 0.5, 0, 0, 1e-14, 0, 0, 0;
  expect_bad([&] { membrane_reference<3>(sliver, 0.1, rule); }, "degenerate element (zero area)");
  SurfaceNodes<4> flat_quad;  // all four nodes on one line
  flat_quad << 0, 1, 2, 3, 0, 0, 0, 0, 0, 0, 0, 0;
  expect_bad([&] { membrane_reference<4>(flat_quad, 0.1, rule); }, "degenerate element (zero area)");
  SurfaceNodes<4> bowtie;
  bowtie << 0, 1, 1, 0, 0, 1, 0, 1, 0, 0, 0, 0;
  expect_bad([&] { membrane_reference<4>(bowtie, 0.1, rule); }, "folded quadrilateral");
  SurfaceNodes<3> tri;
  tri << 0, 1, 0, 0, 0, 1, 0, 0, 0;
  SurfaceNodes<4> quad;
  quad << 0, 1, 1, 0, 0, 0, 1, 1, 0, 0, 0, 0;
  // 6-node triangles: all six nodes on one line; mid-edge node 4 moved from (½, ½) to (−0.2, −0.2),
  // so that det ∂X/∂ξ = 1 − 2.8(ξ + η) is positive at the Gauss points near corner 0 and negative
  // at those near the mid-edge nodes.
  const auto six = [](const SurfaceNodes<3>& c) {
    SurfaceNodes<6> X;
    X << c, 0.5 * (c.col(0) + c.col(1)), 0.5 * (c.col(1) + c.col(2)), 0.5 * (c.col(2) + c.col(0));
    return X;
  };
  expect_bad([&] { membrane_reference<6>(six(collinear), 0.1, rule); }, "degenerate element (zero area)");
  SurfaceNodes<6> folded6 = six(tri);
  folded6.col(4) << -0.2, -0.2, 0;
  expect_bad([&] { membrane_reference<6>(folded6, 0.1, rule); }, "folded 6-node triangle");
  EXPECT_NO_THROW(membrane_reference<6>(six(tri), 0.1, rule));
  // Mid-edge node 3 at (0.2, 0): along edge 0–1, ∂x/∂ξ = 2.4ξ − 0.2 is negative for ξ < 1/12 only, between
  // corner 0 and the nearest Gauss point (ξ = 0.0916): folded at node 0, not at a Gauss point.
  SurfaceNodes<6> corner_fold = six(tri);
  corner_fold.col(3) << 0.2, 0, 0;
  expect_bad([&] { membrane_reference<6>(corner_fold, 0.1, rule); }, "folded 6-node triangle: its surface turns over at its corner node, the 1st in its list");
  corner_fold.col(3) << 0.26, 0, 0;  // beyond the quarter point: ∂x/∂ξ = 1.92ξ + 0.04 > 0 everywhere on the edge
  EXPECT_NO_THROW(membrane_reference<6>(corner_fold, 0.1, rule));
  const DirectionRule normal = [](const Eigen::Vector3d&, const Eigen::Vector3d& n) { return Eigen::Vector3d(2 * n); };
  const DirectionRule nearly_normal = [](const Eigen::Vector3d&, const Eigen::Vector3d&) {
    return Eigen::Vector3d(1e-4, 0, 1);
  };
  const DirectionRule zero = [](const Eigen::Vector3d&, const Eigen::Vector3d&) { return Eigen::Vector3d::Zero(); };
  const DirectionRule nan = [](const Eigen::Vector3d&, const Eigen::Vector3d&) {
    return Eigen::Vector3d(std::nan(""), 1, 0);
  };
  const DirectionRule inf = [](const Eigen::Vector3d&, const Eigen::Vector3d&) {
    return Eigen::Vector3d(1, HUGE_VAL, 0);
  };
  const std::string dir = "material direction 1 is normal to the surface (or not finite)";
  for (const DirectionRule* r : {&normal, &nearly_normal, &zero, &nan, &inf}) {
    expect_bad([&] { membrane_reference<3>(tri, 0.1, *r); }, dir);
    expect_bad([&] { membrane_reference<4>(quad, 0.1, *r); }, dir);
    expect_bad([&] { membrane_reference<6>(six(tri), 0.1, *r); }, dir);
  }
  // Just outside the cone of kMinTangentFraction: accepted.
  const DirectionRule steep = [](const Eigen::Vector3d&, const Eigen::Vector3d&) { return Eigen::Vector3d(2e-3, 0, 1); };
  EXPECT_NO_THROW(membrane_reference<4>(quad, 0.1, steep));
  // BadElement is a std::domain_error; a collapsed current state is a std::domain_error too.
  const auto ref = membrane_reference<3>(tri, 0.1, rule);
  const auto m = material_from_yaml("{type: neo_hookean, mu: 0.3}");
  ElementVector<3> f;
  EXPECT_THROW(membrane3d<3>(ref, collinear, *m, f, nullptr), std::domain_error);
}
