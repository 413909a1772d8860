// The 6-node quadratic triangle (elements/tri6_shape.hpp, theory manual (5.7)):
//  - its shape functions are a partition of unity, 1 at their own node and 0 at the other five,
//    and their derivatives are the finite-difference derivatives of the values;
//  - its 6-point rule integrates every monomial ξ^a η^b, a + b ≤ 4, exactly;
//  - a curved 6-node mesh of a sphere octant has an area and an enclosed volume (about the
//    centre: the octant is closed by the symmetry planes through it, (6.6)) converging to
//    πR²/2 and πR³/6 at a rate of h⁴ (from n = 4 elements along an edge of the octant on);
//  - a flat element with straight edges reproduces a homogeneous deformation exactly: the
//    uniform stress of the 3-node triangle on its corners at every Gauss point, and forces that
//    do the same virtual work as the 3-node triangle's on every affine virtual displacement;
//  - a rigid motion of a curved element gives no internal force;
// the last two for every registered material, each of its samples and orientations
// (tests/support/material_registry.hpp). The finite-difference tests of its residual, tangent,
// pressure, volume and start stiffness are those of every shape (test_membrane3d.cpp,
// test_surface_pressure.cpp, test_start_tension.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>
#include <random>
#include <stdexcept>
#include <vector>

#include "../support/material_registry.hpp"
#include "../support/six_node_triangle.hpp"
#include "elements/membrane3d.hpp"
#include "elements/tri6_shape.hpp"
#include "loads/surface_pressure.hpp"

using namespace tunica;
using tunica::test::MaterialCase;

namespace {

using Shape = SurfaceShapeTraits<6>;

/// The nodes' parametric coordinates (Gmsh order).
constexpr double kNodeXi[6] = {0, 1, 0, 0.5, 0.5, 0};
constexpr double kNodeEta[6] = {0, 0, 1, 0, 0.5, 0.5};

/// Random points of the parametric triangle.
std::vector<Eigen::Vector2d> random_points(std::mt19937& rng, int n) {
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Eigen::Vector2d> p;
  while (static_cast<int>(p.size()) < n) {
    const double xi = u(rng);
    const double eta = u(rng);
    if (xi + eta <= 1) p.emplace_back(xi, eta);
  }
  return p;
}

}  // namespace

TEST(Tri6Shape, PartitionOfUnityAndKroneckerPropertyAtTheNodes) {
  for (int b = 0; b < 6; ++b) {
    const Eigen::Matrix<double, 6, 1> n = shape_values<6>(kNodeXi[b], kNodeEta[b]);
    for (int a = 0; a < 6; ++a) EXPECT_EQ(n(a), a == b ? 1.0 : 0.0) << "N_" << a << " at node " << b;
  }
  std::mt19937 rng(61);
  for (const Eigen::Vector2d& p : random_points(rng, 50)) {
    const Eigen::Matrix<double, 6, 1> n = shape_values<6>(p.x(), p.y());
    const Eigen::Matrix<double, 6, 2> d = shape_derivatives<6>(p.x(), p.y());
    EXPECT_NEAR(n.sum(), 1.0, 1e-15);
    EXPECT_NEAR(d.col(0).sum(), 0.0, 1e-14);
    EXPECT_NEAR(d.col(1).sum(), 0.0, 1e-14);
    // Linear completeness: Σ N_a ξ_a = ξ, Σ N_a η_a = η.
    const Eigen::Map<const Eigen::Matrix<double, 6, 1>> xi(kNodeXi), eta(kNodeEta);
    EXPECT_NEAR(n.dot(xi), p.x(), 1e-15);
    EXPECT_NEAR(n.dot(eta), p.y(), 1e-15);
  }
}

TEST(Tri6Shape, DerivativesAreTheFiniteDifferenceDerivativesOfTheValues) {
  std::mt19937 rng(62);
  const double h = 1e-6;
  for (const Eigen::Vector2d& p : random_points(rng, 50)) {
    const Eigen::Matrix<double, 6, 2> d = shape_derivatives<6>(p.x(), p.y());
    Eigen::Matrix<double, 6, 2> fd;
    fd.col(0) = (shape_values<6>(p.x() + h, p.y()) - shape_values<6>(p.x() - h, p.y())) / (2 * h);
    fd.col(1) = (shape_values<6>(p.x(), p.y() + h) - shape_values<6>(p.x(), p.y() - h)) / (2 * h);
    // Quadratic N: central differences are exact up to rounding (~1e-16/h).
    EXPECT_LT((d - fd).cwiseAbs().maxCoeff(), 1e-9);
  }
}

TEST(Tri6Shape, GaussRuleIntegratesEveryMonomialOfDegreeAtMostFourExactly) {
  // ∫ ξ^a η^b over the triangle = a! b! / (a + b + 2)!.
  double sum = 0;
  for (int q = 0; q < Shape::kPoints; ++q) {
    double xi, eta, w;
    gauss_point<6>(q, xi, eta, w);
    EXPECT_GT(w, 0);
    EXPECT_GT(xi, 0);
    EXPECT_GT(eta, 0);
    EXPECT_LT(xi + eta, 1);
    sum += w;
  }
  EXPECT_NEAR(sum, 0.5, 1e-16);
  for (int a = 0; a <= 4; ++a)
    for (int b = 0; a + b <= 4; ++b) {
      double integral = 0;
      for (int q = 0; q < Shape::kPoints; ++q) {
        double xi, eta, w;
        gauss_point<6>(q, xi, eta, w);
        integral += w * std::pow(xi, a) * std::pow(eta, b);
      }
      const auto factorial = [](int k) {
        double r = 1;
        for (int i = 2; i <= k; ++i) r *= i;
        return r;
      };
      const double exact = factorial(a) * factorial(b) / factorial(a + b + 2);
      EXPECT_NEAR(integral, exact, 1e-16) << "xi^" << a << " eta^" << b;
    }
  // Degree 4, not more: ξ⁵ is not integrated exactly.
  double i5 = 0;
  for (int q = 0; q < Shape::kPoints; ++q) {
    double xi, eta, w;
    gauss_point<6>(q, xi, eta, w);
    i5 += w * std::pow(xi, 5);
  }
  EXPECT_GT(std::abs(i5 - 1.0 / 42), 1e-5);
  double xi, eta, w;
  EXPECT_THROW(gauss_point<6>(6, xi, eta, w), std::out_of_range);
  EXPECT_THROW(gauss_point<6>(-1, xi, eta, w), std::out_of_range);
}

namespace {

/// The octant x, y, z ≥ 0 of the sphere of radius R about c in n² curved 6-node triangles:
/// the face of the octahedron split into n² triangles, every node (corners and mid-edge
/// nodes) projected radially onto the sphere; g1 × g2 points outward.
std::vector<SurfaceNodes<6>> sphere_octant(int n, double R, const Eigen::Vector3d& c) {
  const auto node = [&](int i, int j) {  // fine grid: steps of 1/(2n)
    const double s = i / (2.0 * n), t = j / (2.0 * n);
    const Eigen::Vector3d p(1 - s - t, s, t);
    return Eigen::Vector3d(c + R * p.normalized());
  };
  const auto element = [&](const std::array<std::array<int, 2>, 6>& ij) {
    SurfaceNodes<6> X;
    for (int a = 0; a < 6; ++a) X.col(a) = node(ij[a][0], ij[a][1]);
    return X;
  };
  std::vector<SurfaceNodes<6>> mesh;
  for (int i = 0; i < n; ++i)
    for (int j = 0; i + j < n; ++j) {
      const int I = 2 * i, J = 2 * j;
      mesh.push_back(element({{{I, J}, {I + 2, J}, {I, J + 2}, {I + 1, J}, {I + 1, J + 1}, {I, J + 1}}}));
      if (i + j + 2 <= n)
        mesh.push_back(element(
            {{{I + 2, J}, {I + 2, J + 2}, {I, J + 2}, {I + 2, J + 1}, {I + 1, J + 2}, {I + 1, J + 1}}}));
    }
  return mesh;
}

}  // namespace

TEST(Tri6Sphere, AreaAndEnclosedVolumeOfAnOctantConvergeAtTheRateOfHToTheFourth) {
  const double R = 1.7, H = 0.1;
  const Eigen::Vector3d c(0.3, -1.2, 0.8);
  const DirectionRule rule = [](const Eigen::Vector3d&, const Eigen::Vector3d&) {
    return Eigen::Vector3d(1, 0.3, 0.2);
  };
  VolumeMeasure how;
  how.point = c;
  const double area_exact = std::numbers::pi * R * R / 2, volume_exact = std::numbers::pi * R * R * R / 6;
  std::vector<double> ea, ev;
  for (int n : {4, 8, 16, 32}) {
    double area = 0, volume = 0;
    for (const SurfaceNodes<6>& X : sphere_octant(n, R, c)) {
      const MembraneReference<6> ref = membrane_reference<6>(X, H, rule);
      for (double w : ref.weight) area += w / H;
      volume += enclosed_volume<6>(X, how, nullptr);
    }
    ea.push_back(std::abs(area / area_exact - 1));
    ev.push_back(std::abs(volume / volume_exact - 1));
    std::cout << "tri6 sphere octant n = " << n << ": relative error of the area " << ea.back() << ", of the volume "
              << ev.back() << "\n";
  }
  for (std::size_t k = 0; k + 1 < ea.size(); ++k) {
    EXPECT_GT(std::log2(ea[k] / ea[k + 1]), 3.8) << "area, refinement " << k;
    EXPECT_GT(std::log2(ev[k] / ev[k + 1]), 3.8) << "volume, refinement " << k;
  }
  EXPECT_LT(ea.back(), 3e-7);
  EXPECT_LT(ev.back(), 5e-7);
}

namespace {

class Tri6Patch : public ::testing::TestWithParam<MaterialCase> {
protected:
  void SetUp() override { m = tunica::test::make_membrane(GetParam()); }
  std::unique_ptr<MembraneMaterial> m;
};

INSTANTIATE_TEST_SUITE_P(Registry, Tri6Patch,
                         ::testing::ValuesIn(tunica::test::membrane_cases(tunica::test::Orientations::each)),
                         tunica::test::case_name);

/// Material direction 1 at 0.4 rad from the X axis (+ the sample's orientation), in the plane z = 0.
DirectionRule in_plane_rule(double angle) {
  return [angle](const Eigen::Vector3d&, const Eigen::Vector3d&) {
    return Eigen::Vector3d(std::cos(0.4 + angle), std::sin(0.4 + angle), 0);
  };
}

}  // namespace

TEST_P(Tri6Patch, HomogeneousDeformationOfAStraightEdgedElementGivesTheUniformStressOfTheThreeNodeTriangle) {
  // x = c + Q [F (X, Y); 0]: a stretch, shear and tilt of the plane z = 0, linear in X, which the
  // isoparametric quadratic interpolation reproduces exactly whatever the mid-edge nodes'
  // places on the (straight) edges.
  Eigen::Matrix2d F;
  F << 1.3, 0.2, 0, 0.9;
  const Eigen::Matrix3d Q = (Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ()) *
                             Eigen::AngleAxisd(0.35, Eigen::Vector3d::UnitX()))
                                .toRotationMatrix();
  const Eigen::Vector3d c(0.3, -0.2, 0.5);
  const auto phi = [&](const Eigen::Vector3d& X) -> Eigen::Vector3d {
    const Eigen::Vector2d y = F * X.head<2>();
    return c + Q * Eigen::Vector3d(y.x(), y.y(), 0);
  };
  SurfaceNodes<3> X3;
  X3 << 0, 1.2, 0.3, 0, 0.1, 0.9, 0, 0, 0;
  const DirectionRule rule = in_plane_rule(GetParam().angle);
  const MembraneReference<3> ref3 = membrane_reference<3>(X3, 0.1, rule);
  SurfaceNodes<3> x3;
  for (int a = 0; a < 3; ++a) x3.col(a) = phi(X3.col(a));
  ElementVector<3> f3;
  std::array<MembranePoint, 1> p3;
  membrane3d<3>(ref3, x3, *m, f3, nullptr, &p3);
  const Eigen::Vector3d S3 = p3[0].S;
  ASSERT_GT(S3.norm(), 0);
  // Mid-edge nodes at the midpoints, then at other places along the edges.
  for (const Eigen::Vector3d& t : {Eigen::Vector3d(0.5, 0.5, 0.5), Eigen::Vector3d(0.4, 0.57, 0.62)}) {
    SurfaceNodes<6> X6;
    X6.leftCols<3>() = X3;
    for (int k = 0; k < 3; ++k) X6.col(3 + k) = (1 - t(k)) * X3.col(k) + t(k) * X3.col((k + 1) % 3);
    const MembraneReference<6> ref6 = membrane_reference<6>(X6, 0.1, rule);
    SurfaceNodes<6> x6;
    for (int a = 0; a < 6; ++a) x6.col(a) = phi(X6.col(a));
    ElementVector<6> f6;
    std::array<MembranePoint, 6> p6;
    membrane3d<6>(ref6, x6, *m, f6, nullptr, &p6);
    for (const MembranePoint& p : p6) {
      EXPECT_LT((p.S - S3).norm(), 1e-12 * S3.norm());
      EXPECT_LT((p.cauchy - p3[0].cauchy).norm(), 1e-12 * p3[0].cauchy.norm());
    }
    // Virtual work on affine virtual displacements δu(X) = a + B X: Σ_a f_a·δu(X_a) is
    // ∫ S:δE dA, the same for both elements (constant stress, the same area).
    const double scale = f3.norm() * X3.norm();
    std::mt19937 rng(63);
    std::normal_distribution<double> g;
    for (int k = 0; k < 5; ++k) {
      const Eigen::Vector3d a(g(rng), g(rng), g(rng));
      Eigen::Matrix3d B;
      for (int i = 0; i < 9; ++i) B(i) = g(rng);
      double w3 = 0, w6 = 0;
      for (int n = 0; n < 3; ++n) w3 += f3.segment<3>(3 * n).dot(a + B * X3.col(n));
      for (int n = 0; n < 6; ++n) w6 += f6.segment<3>(3 * n).dot(a + B * X6.col(n));
      EXPECT_NEAR(w6, w3, 1e-12 * scale);
    }
    // No net force (a translation does no work).
    Eigen::Vector3d total = Eigen::Vector3d::Zero();
    for (int n = 0; n < 6; ++n) total += f6.segment<3>(3 * n);
    EXPECT_LT(total.norm(), 1e-13 * f6.norm());
  }
}

TEST_P(Tri6Patch, RigidMotionOfACurvedElementGivesNoInternalForce) {
  std::mt19937 rng(64);
  std::normal_distribution<double> g;
  SurfaceNodes<3> corners;
  corners << 0, 1.2, 0.3, 0, 0.1, 0.9, 0, 0, 0;
  const DirectionRule rule = in_plane_rule(GetParam().angle);
  for (int k = 0; k < 5; ++k) {
    const SurfaceNodes<6> X = tunica::test::six_node_triangle(corners, Eigen::Vector3d(0.08, 0.08, 0.2), rng);
    const MembraneReference<6> ref = membrane_reference<6>(X, 0.1, rule);
    const Eigen::Matrix3d R = Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng)).normalized().toRotationMatrix();
    const Eigen::Vector3d c(g(rng), g(rng), g(rng));
    ElementVector<6> f, fs;
    std::array<MembranePoint, 6> pts;
    membrane3d<6>(ref, (R * X).colwise() + c, *m, f, nullptr, &pts);
    membrane3d<6>(ref, 1.1 * X, *m, fs, nullptr);  // the force scale of a 10 % stretch
    ASSERT_GT(fs.norm(), 0);
    EXPECT_LT(f.norm(), 1e-12 * fs.norm()) << "k = " << k;
    for (const MembranePoint& p : pts) {
      EXPECT_LT(p.E.norm(), 1e-14);
      EXPECT_LT((p.lambda - Eigen::Vector3d::Ones()).norm(), 1e-14);
    }
  }
}
