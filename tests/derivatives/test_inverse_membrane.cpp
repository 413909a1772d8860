// Finite-difference checks of the inverse membrane elements (theory manual §13,
// elements/membrane3d_inverse.hpp, elements/axisym_membrane_inverse.hpp), over every registered
// membrane material and each of its samples (tests/support/material_registry.hpp):
//  - the residual is the forward element's at the same reference and imaged nodes (the same
//    discrete equations, bit for bit);
//  - the tangent KX = ∂f/∂X is the Jacobian of the internal force with respect to the reference
//    nodes, by central differences, for the 3-node triangle, the 4-node quadrilateral and the
//    6-node triangle, with each kind of material direction (fixed, about an axis, along the first
//    edge), and for the axisymmetric membrane;
// at random distorted reference elements and imaged states (stretches 0.8–1.6); and the same with
// an imaged thickness h (theory manual (13.12)–(13.13)): the residual is the forward element's with
// H_q = h λ₁λ₂ at each Gauss point, the imaged thickness λ₃H_q is h, and KX (with δw = 0) is the
// Jacobian, for every element kind.
#include <gtest/gtest.h>

#include <random>

#include "../support/fd.hpp"
#include "../support/material_registry.hpp"
#include "../support/six_node_triangle.hpp"
#include "elements/axisym_membrane_inverse.hpp"
#include "elements/membrane3d_inverse.hpp"

using namespace tunica;
using tunica::test::fd_jacobian;
using tunica::test::kFdTolerance;
using tunica::test::MaterialCase;
using tunica::test::relative_error;

namespace {

Eigen::Matrix3d random_rotation(std::mt19937& rng) {
  std::normal_distribution<double> g;
  return Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng)).normalized().toRotationMatrix();
}

/// A random distorted reference element (quad: warped; tri6: curved), rotated and translated.
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

/// An imaged state: a rotated, stretched (singular values 0.8–1.6), sheared copy, nodes perturbed.
template <int N>
SurfaceNodes<N> random_imaged(std::mt19937& rng, const SurfaceNodes<N>& X) {
  std::uniform_real_distribution<double> u(-1, 1), stretch(0.8, 1.6);
  const Eigen::Vector3d s(stretch(rng), stretch(rng), stretch(rng));
  const Eigen::Matrix3d A = random_rotation(rng) * s.asDiagonal() * random_rotation(rng);
  SurfaceNodes<N> x = random_rotation(rng) * A * X;
  x.colwise() += Eigen::Vector3d(u(rng), u(rng), u(rng));
  x += 0.05 * SurfaceNodes<N>::NullaryExpr([&] { return u(rng); });
  return x;
}

/// Material direction k: fixed and skew, about a skew axis through a point off the element, along the first edge.
FrameDirection frame_direction(int k) {
  FrameDirection d;
  d.kind = std::array{FrameDirection::Kind::fixed, FrameDirection::Kind::about_axis, FrameDirection::Kind::first_edge}[k % 3];
  d.vector = Eigen::Vector3d(0.3, 0.8, -0.5);
  d.axis = Eigen::Vector3d(0.2, -0.3, 1.0).normalized();
  d.point = Eigen::Vector3d(3.0, -2.0, 0.5);
  return d;
}

template <int N>
SurfaceNodes<N> nodes(const Eigen::VectorXd& v) {
  return Eigen::Map<const SurfaceNodes<N>>(v.data());
}
template <int N>
Eigen::VectorXd flat(const SurfaceNodes<N>& x) {
  return Eigen::Map<const Eigen::VectorXd>(x.data(), 3 * N);
}

/// The worst relative error of KX against central differences over random states and each kind of direction.
template <int N>
double check_surface(const MembraneMaterial& material, std::mt19937& rng, bool imaged = false) {
  double worst = 0;
  for (int k = 0; k < 6; ++k) {
    const FrameDirection dir = frame_direction(k);
    // A random reference element, drawn again while it is folded (a curved 6-node triangle can be).
    SurfaceNodes<N> X = random_reference<N>(rng);
    for (int tries = 0; tries < 100; ++tries) {
      try {
        membrane_reference<N>(X, 0.13, dir.rule<N>(X));
        break;
      } catch (const BadElement&) {
        X = random_reference<N>(rng);
      }
    }
    const SurfaceNodes<N> x = random_imaged<N>(rng, X);
    ElementVector<N> f, f_forward;
    ElementMatrix<N> KX;
    std::array<MembranePoint, SurfaceShapeTraits<N>::kPoints> pts;
    std::array<double, SurfaceShapeTraits<N>::kPoints> h;
    for (int q = 0; q < SurfaceShapeTraits<N>::kPoints; ++q) h[q] = 0.13 + 0.01 * q;  // a thickness map
    const auto* hq = imaged ? &h : nullptr;
    membrane3d_inverse<N>(X, x, 0.13, dir, material, f, &KX, hq, &pts);
    // The same discrete equations: the forward element at the same reference and current nodes,
    // with an imaged thickness h_q at H_q = h_q |g1 × g2|/|G1 × G2| (13.12).
    MembraneReference<N> ref = membrane_reference<N>(X, 0.13, dir.rule<N>(X));
    if (imaged) {
      for (int q = 0; q < SurfaceShapeTraits<N>::kPoints; ++q) {
        double xi, eta, wq;
        gauss_point<N>(q, xi, eta, wq);
        const Eigen::Matrix<double, N, 2> dN = shape_derivatives<N>(xi, eta);
        const Eigen::Matrix<double, 3, 2> G = X * dN, g = x * dN;
        const double Hq = h[q] * g.col(0).cross(g.col(1)).norm() / G.col(0).cross(G.col(1)).norm();
        EXPECT_NEAR(pts[q].reference_thickness, Hq, 1e-14 * Hq) << "N=" << N << " k=" << k << " q=" << q;
        EXPECT_NEAR(pts[q].thickness, h[q], 1e-12) << "N=" << N << " k=" << k << " q=" << q;  // λ₃ H_q = h_q
      }
      ElementVector<N> fq;
      f_forward.setZero();
      for (int q = 0; q < SurfaceShapeTraits<N>::kPoints; ++q) {
        MembraneReference<N> one = membrane_reference<N>(X, pts[q].reference_thickness, dir.rule<N>(X));
        for (int r = 0; r < SurfaceShapeTraits<N>::kPoints; ++r)
          if (r != q) one.weight[r] = 0;
        membrane3d<N>(one, x, material, fq, nullptr);
        f_forward += fq;
      }
      EXPECT_LT((f - f_forward).norm(), 1e-12 * f.norm()) << "N=" << N << " k=" << k;
    } else {
      membrane3d<N>(ref, x, material, f_forward, nullptr);
      EXPECT_EQ(f, f_forward) << "N=" << N << " k=" << k;
    }
    const auto force = [&](const Eigen::VectorXd& v) -> Eigen::VectorXd {
      ElementVector<N> g;
      membrane3d_inverse<N>(nodes<N>(v), x, 0.13, dir, material, g, nullptr, hq);
      return g;
    };
    const double e = relative_error(KX, fd_jacobian(force, flat<N>(X), 1e-6));
    EXPECT_LT(e, kFdTolerance) << "N=" << N << " direction kind " << k % 3 << " state " << k;
    worst = std::max(worst, e);
  }
  return worst;
}

class InverseMembraneFd : public ::testing::TestWithParam<MaterialCase> {
protected:
  void SetUp() override { m = tunica::test::make_membrane(GetParam()); }
  std::unique_ptr<MembraneMaterial> m;
};

INSTANTIATE_TEST_SUITE_P(Registry, InverseMembraneFd, ::testing::ValuesIn(tunica::test::membrane_cases()),
                         tunica::test::case_name);

}  // namespace

TEST_P(InverseMembraneFd, SurfaceTangentIsTheJacobianOfTheForceInTheReferenceNodes) {
  std::mt19937 rng(19);
  const double e3 = check_surface<3>(*m, rng), e4 = check_surface<4>(*m, rng), e6 = check_surface<6>(*m, rng);
  tunica::test::record_error("max_rel_err_tri3", e3);
  tunica::test::record_error("max_rel_err_quad4", e4);
  tunica::test::record_error("max_rel_err_tri6", e6);
  std::printf("inverse KX vs central differences, %s: tri3 %.2e, quad4 %.2e, tri6 %.2e\n",
              tunica::test::case_name({GetParam(), 0}).c_str(), e3, e4, e6);
}

TEST_P(InverseMembraneFd, ImagedThicknessSurfaceTangentIsTheJacobianOfTheForceInTheReferenceNodes) {
  std::mt19937 rng(19);
  const double e3 = check_surface<3>(*m, rng, true), e4 = check_surface<4>(*m, rng, true),
               e6 = check_surface<6>(*m, rng, true);
  tunica::test::record_error("max_rel_err_tri3", e3);
  tunica::test::record_error("max_rel_err_quad4", e4);
  tunica::test::record_error("max_rel_err_tri6", e6);
  std::printf("inverse KX with an imaged thickness vs central differences, %s: tri3 %.2e, quad4 %.2e, tri6 %.2e\n",
              tunica::test::case_name({GetParam(), 0}).c_str(), e3, e4, e6);
}

namespace {

/// The worst relative error of the axisymmetric KX against central differences over random states.
double check_axisymmetric(const MembraneMaterial& material, bool imaged) {
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> u(0, 1), s(-1, 1), stretch(0.8, 1.6);
  double worst = 0;
  for (int k = 0; k < 20; ++k) {
    // A reference segment (any tilt, radius 0.8–1.8) and an imaged one stretched 0.8–1.6 each way, turned and perturbed.
    const double phi = 6.2832 * u(rng), L = 0.3 + 0.4 * u(rng);
    AxisymNodes X, x;
    X.col(0) = Eigen::Vector2d(0.8 + u(rng), s(rng));
    X.col(1) = X.col(0) + L * Eigen::Vector2d(std::cos(phi), std::sin(phi));
    const double hoop = stretch(rng), meridian = stretch(rng), turn = 0.5 * s(rng);
    const Eigen::Vector2d t(std::cos(phi + turn), std::sin(phi + turn));
    const Eigen::Vector2d mid(hoop * 0.5 * (X(0, 0) + X(0, 1)), 0.5 * (X(1, 0) + X(1, 1)) + s(rng));
    x.col(0) = mid - 0.5 * meridian * L * t;
    x.col(1) = mid + 0.5 * meridian * L * t;
    x += 0.02 * AxisymNodes::NullaryExpr([&] { return s(rng); });
    Eigen::Vector4d f, f_forward;
    Eigen::Matrix4d KX;
    std::array<MembranePoint, 2> pts;
    const std::array<double, 2> h{0.11, 0.12};  // a thickness map
    const auto* hq = imaged ? &h : nullptr;
    axisym_membrane_inverse(X, x, 0.11, material, f, &KX, hq, &pts);
    if (imaged) {
      // H_q = h λ_s λ_θ (13.12), and the forward element with it; the imaged thickness λ₃H_q is h.
      const double g = 0.5 / std::sqrt(3.0);
      std::array<double, 2> Hq{};
      for (int q = 0; q < 2; ++q) {
        const double t = q == 0 ? 0.5 - g : 0.5 + g;
        Hq[q] = h[q] * ((x.col(1) - x.col(0)).norm() / (X.col(1) - X.col(0)).norm()) *
                (((1 - t) * x(0, 0) + t * x(0, 1)) / ((1 - t) * X(0, 0) + t * X(0, 1)));
        EXPECT_NEAR(pts[q].reference_thickness, Hq[q], 1e-14 * Hq[q]) << "state " << k;
        EXPECT_NEAR(pts[q].thickness, h[q], 1e-12) << "state " << k;
      }
      axisym_membrane(X, x, Hq, material, f_forward, nullptr);
      EXPECT_LT((f - f_forward).norm(), 1e-13 * f.norm()) << "state " << k;
    } else {
      axisym_membrane(X, x, 0.11, material, f_forward, nullptr);
      EXPECT_EQ(f, f_forward) << "state " << k;
    }
    const auto force = [&](const Eigen::VectorXd& v) -> Eigen::VectorXd {
      AxisymNodes Xv;
      Xv << v(0), v(2), v(1), v(3);
      Eigen::Vector4d g;
      axisym_membrane_inverse(Xv, x, 0.11, material, g, nullptr, hq);
      return g;
    };
    const double e = relative_error(KX, fd_jacobian(force, Eigen::Vector4d(X(0, 0), X(1, 0), X(0, 1), X(1, 1)), 1e-6));
    EXPECT_LT(e, kFdTolerance) << "state " << k;
    worst = std::max(worst, e);
  }
  return worst;
}

}  // namespace

TEST_P(InverseMembraneFd, AxisymmetricTangentIsTheJacobianOfTheForceInTheReferenceNodes) {
  const double worst = check_axisymmetric(*m, false);
  tunica::test::record_error("max_rel_err", worst);
  std::printf("inverse axisymmetric KX vs central differences, %s: %.2e\n", tunica::test::case_name({GetParam(), 0}).c_str(),
              worst);
}

TEST_P(InverseMembraneFd, ImagedThicknessAxisymmetricTangentIsTheJacobianOfTheForceInTheReferenceNodes) {
  const double worst = check_axisymmetric(*m, true);
  tunica::test::record_error("max_rel_err", worst);
  std::printf("inverse axisymmetric KX with an imaged thickness vs central differences, %s: %.2e\n",
              tunica::test::case_name({GetParam(), 0}).c_str(), worst);
}
