// The normal-tension stiffness of the stress-free start (elements/start_tension.hpp,
// System::add_start_stiffness):
//  - K₀ against the closed form T₀ ∫ ∇N_a·∇N_b dA (n nᵀ) on a flat right triangle (3 and 6
//    nodes) and a square;
//  - symmetric and positive semidefinite on warped (quad4) and curved (tri6), rotated elements,
//    with no stiffness against rigid translations; on flat elements (tri3, tri6) none against
//    uniform normal motion or in-plane motion;
//  - the vector System::add_start_stiffness returns, K₀ d, has K₀ as its finite-difference
//    Jacobian (it is the gradient of the quadratic ½ dᵀ K₀ d), on the free DOFs of a sphere octant.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <random>

#include "../support/fd.hpp"
#include "../support/six_node_triangle.hpp"
#include "../support/sphere_octant.hpp"
#include "assembly/system.hpp"
#include "elements/axisym_start_tension.hpp"
#include "elements/start_tension.hpp"
#include "io/deck.hpp"
#include "model/meridian_curvature.hpp"

using namespace tunica;

namespace {

const DirectionRule kAlongX = [](const Eigen::Vector3d&, const Eigen::Vector3d&) { return Eigen::Vector3d(1, 0, 0); };

/// K₀ of a flat element in z = 0 is T₀ L (L_ab = ∫ ∇N_a·∇N_b dA) on the z components, zero elsewhere.
template <int N>
void expect_normal_block(const ElementMatrix<N>& K, double T0, const Eigen::Matrix<double, N, N>& L) {
  for (int a = 0; a < N; ++a)
    for (int b = 0; b < N; ++b)
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          EXPECT_NEAR(K(3 * a + i, 3 * b + j), (i == 2 && j == 2) ? T0 * L(a, b) : 0.0, 1e-14) << a << b << i << j;
}

/// Symmetric, positive semidefinite, no stiffness against a rigid translation: 20 random rotated
/// elements near the unit square (quad4, warped) or the right triangle (tri6: curved).
template <int N>
void check_random_elements(std::mt19937& rng) {
  std::uniform_real_distribution<double> jitter(-0.15, 0.15);
  std::normal_distribution<double> g;
  for (int trial = 0; trial < 20; ++trial) {
    const Eigen::Matrix3d Q = Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng)).normalized().toRotationMatrix();
    SurfaceNodes<N> X;
    if constexpr (N == 4) {
      X << 0, 1, 1, 0, 0, 0, 1, 1, 0, 0, 0, 0;
      for (int a = 0; a < 4; ++a) X.col(a) += Eigen::Vector3d(jitter(rng), jitter(rng), jitter(rng));
    } else {
      SurfaceNodes<3> corners;
      corners << 0, 1, 0, 0, 0, 1, 0, 0, 0;
      for (int a = 0; a < 3; ++a) {
        // One draw per statement: the evaluation order of function arguments is unspecified.
        const double dx = jitter(rng);
        const double dy = jitter(rng);
        const double dz = jitter(rng);
        corners.col(a) += Eigen::Vector3d(dx, dy, dz);
      }
      X = test::six_node_triangle(corners, Eigen::Vector3d::Constant(0.1), rng);
    }
    X = Q * X;
    const MembraneReference<N> ref = membrane_reference<N>(X, 0.1, kAlongX);
    ElementMatrix<N> K;
    normal_tension_stiffness<N>(ref, 1.7, K);
    EXPECT_LT((K - K.transpose()).cwiseAbs().maxCoeff(), 1e-14 * K.cwiseAbs().maxCoeff());
    const Eigen::SelfAdjointEigenSolver<ElementMatrix<N>> eig(K);
    EXPECT_GT(eig.eigenvalues().minCoeff(), -1e-12 * eig.eigenvalues().maxCoeff());
    ElementVector<N> t;
    for (int a = 0; a < N; ++a) t.template segment<3>(3 * a) = Q.col(0) + 2 * Q.col(2);
    EXPECT_LT((K * t).norm(), 1e-12 * K.norm() * t.norm()) << "rigid translation";
  }
}

/// A flat element X in z = 0: no stiffness against a uniform normal motion or any in-plane
/// motion; node `bumped` moved out of the plane is resisted.
template <int N>
void check_flat_element(const SurfaceNodes<N>& X, int bumped) {
  const MembraneReference<N> ref = membrane_reference<N>(X, 0.1, kAlongX);
  ElementMatrix<N> K;
  normal_tension_stiffness<N>(ref, 3.0, K);
  ElementVector<N> w = ElementVector<N>::Zero(), inplane = ElementVector<N>::Zero();
  const double moves[6][2] = {{0.3, -0.2}, {1.1, 0.4}, {-0.7, 0.5}, {0.2, 0.9}, {-0.4, -0.6}, {0.8, 0.1}};
  for (int a = 0; a < N; ++a) {
    w(3 * a + 2) = 1;
    inplane.template segment<2>(3 * a) = Eigen::Vector2d(moves[a][0], moves[a][1]);
  }
  EXPECT_LT((K * w).norm(), 1e-14 * K.norm());
  EXPECT_LT((K * inplane).norm(), 1e-14 * K.norm());
  ElementVector<N> bump = ElementVector<N>::Zero();
  bump(3 * bumped + 2) = 1;
  EXPECT_GT(bump.dot(K * bump), 0.1 * K.norm());
}

}  // namespace

TEST(StartTension, FlatRightTriangleMatchesTheClosedForm) {
  // Nodes (0,0), (1,0), (0,1) in z = 0: ∇N = (−1,−1), (1,0), (0,1), area ½, so
  // ∫ ∇N_a·∇N_b dA = ½ [[2, −1, −1], [−1, 1, 0], [−1, 0, 1]]; K₀ = T₀ × that on the z components.
  SurfaceNodes<3> X;
  X << 0, 1, 0, 0, 0, 1, 0, 0, 0;
  const MembraneReference<3> ref = membrane_reference<3>(X, 0.3, kAlongX);
  const double T0 = 2.5;
  ElementMatrix<3> K;
  normal_tension_stiffness<3>(ref, T0, K);
  Eigen::Matrix3d L;
  L << 2, -1, -1, -1, 1, 0, -1, 0, 1;
  L *= 0.5;
  expect_normal_block<3>(K, T0, L);
}

TEST(StartTension, FlatRightSixNodeTriangleMatchesTheClosedForm) {
  // The same triangle with mid-edge nodes at the midpoints: the quadratic N (5.7) have
  // ∫ ∇N_a·∇N_b dA = ⅙ [[6, 1, 1, −4, 0, −4], [1, 3, 0, −4, 0, 0], [1, 0, 3, 0, 0, −4],
  // [−4, −4, 0, 16, −8, 0], [0, 0, 0, −8, 16, −8], [−4, 0, −4, 0, −8, 16]] (integrand of degree 2:
  // exact with the 6-point rule).
  SurfaceNodes<6> X;
  X << 0, 1, 0, 0.5, 0.5, 0, 0, 0, 1, 0, 0.5, 0.5, 0, 0, 0, 0, 0, 0;
  const MembraneReference<6> ref = membrane_reference<6>(X, 0.3, kAlongX);
  const double T0 = 2.5;
  ElementMatrix<6> K;
  normal_tension_stiffness<6>(ref, T0, K);
  Eigen::Matrix<double, 6, 6> L;
  L << 6, 1, 1, -4, 0, -4,  //
      1, 3, 0, -4, 0, 0,    //
      1, 0, 3, 0, 0, -4,    //
      -4, -4, 0, 16, -8, 0,  //
      0, 0, 0, -8, 16, -8,  //
      -4, 0, -4, 0, -8, 16;
  L /= 6;
  expect_normal_block<6>(K, T0, L);
}

TEST(StartTension, FlatUnitSquareMatchesTheClosedForm) {
  // Bilinear unit square: ∫ ∇N_a·∇N_b dA = 2/3 (a = b), −1/6 (neighbours), −1/3 (opposite),
  // exact with the 2 × 2 Gauss rule.
  SurfaceNodes<4> X;
  X << 0, 1, 1, 0, 0, 0, 1, 1, 0, 0, 0, 0;
  const MembraneReference<4> ref = membrane_reference<4>(X, 0.1, kAlongX);
  ElementMatrix<4> K;
  normal_tension_stiffness<4>(ref, 1.0, K);
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) {
      const int d = (b - a + 4) % 4;
      const double expected = d == 0 ? 2.0 / 3 : d == 2 ? -1.0 / 3 : -1.0 / 6;
      EXPECT_NEAR(K(3 * a + 2, 3 * b + 2), expected, 1e-14) << a << b;
    }
}

TEST(StartTension, SymmetricSemidefiniteAndBlindToRigidAndUniformNormalMotion) {
  std::mt19937 rng(7);
  check_random_elements<4>(rng);
  check_random_elements<6>(rng);
  SurfaceNodes<3> X;
  X << 0, 1.3, 0.2, 0, 0.1, 0.9, 0, 0, 0;
  check_flat_element<3>(X, 1);
  // The same triangle with 6 nodes, the mid-edge nodes off the midpoints in the plane.
  std::mt19937 rng6(8);
  check_flat_element<6>(test::six_node_triangle(X, Eigen::Vector3d(0.1, 0.1, 0), rng6), 3);
}

TEST(StartTension, SystemVectorIsTheGradientOfTheQuadraticWhoseHessianItAdds) {
  const Model model =
      read_deck_text(test::sphere_octant_deck("start tension FD", 3, "", 1), "start-tension-fd.yaml");
  const System system(model);
  LoadState loads;
  loads.boundary.assign(model.boundaries.size(), 0.0);
  loads.pressure.assign(model.loads.size(), test::sphere_octant_pressure());
  loads.volume.assign(model.loads.size(), 0.0);
  TangentMatrix K = system.tangent(true);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> U(-0.1, 0.1);
  Eigen::VectorXd d(system.num_dofs());
  for (int i = 0; i < d.size(); ++i) d(i) = system.equation(i) >= 0 ? U(rng) : 0.0;
  system.add_start_stiffness(loads, d, K);
  ASSERT_GT(K.max_abs(), 0.0);
  // Free part of K₀ d as a function of the free DOFs.
  const int nf = system.num_free();
  const auto free_map = [&](const Eigen::VectorXd& full) {
    Eigen::VectorXd f(nf);
    for (int i = 0; i < system.num_dofs(); ++i)
      if (system.equation(i) >= 0) f(system.equation(i)) = full(i);
    return f;
  };
  const auto gradient = [&](const Eigen::VectorXd& df) {
    Eigen::VectorXd full = Eigen::VectorXd::Zero(system.num_dofs());
    for (int i = 0; i < system.num_dofs(); ++i)
      if (system.equation(i) >= 0) full(i) = df(system.equation(i));
    TangentMatrix scratch = system.tangent(true);
    return free_map(system.add_start_stiffness(loads, full, scratch));
  };
  const Eigen::MatrixXd J = test::fd_jacobian(gradient, free_map(d), 1e-6);
  const Eigen::MatrixXd Kd = Eigen::MatrixXd(K.full());
  EXPECT_LT((J - Kd).norm(), 1e-8 * Kd.norm());
  EXPECT_LT((Kd - Kd.transpose()).norm(), 1e-14 * Kd.norm());
  // No pressure, no stiffening.
  loads.pressure.assign(model.loads.size(), 0.0);
  TangentMatrix K0 = system.tangent(true);
  EXPECT_EQ(system.add_start_stiffness(loads, d, K0).norm(), 0.0);
  EXPECT_EQ(K0.max_abs(), 0.0);
}

// ---------------------------------------------------------------------------------------------
// The axisymmetric segment (elements/axisym_start_tension.hpp) and the meridian's mean curvature
// (model/meridian_curvature.hpp) that sets its tension.

TEST(StartTension, AxisymSegmentResistsOnlyTheRelativeNormalMotionOfItsNodes) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.2, 3.0), a(-3.2, 3.2);
  for (int trial = 0; trial < 20; ++trial) {
    const Eigen::Vector2d Xa(u(rng), u(rng) - 1.5);
    const double phi = a(rng), length = 0.1 + 0.3 * u(rng);
    Eigen::Vector2d Xb = Xa + length * Eigen::Vector2d(std::cos(phi), std::sin(phi));
    if (Xb(0) <= 0) Xb(0) = 0.05;  // on the right of the axis
    const double L = (Xb - Xa).norm();
    const Eigen::Vector2d tt = (Xb - Xa) / L, nn(tt(1), -tt(0));
    const double T0 = 0.3;
    Eigen::Matrix4d K;
    axisym_normal_tension_stiffness(Xa, Xb, T0, K);
    EXPECT_LT((K - K.transpose()).norm(), 1e-15 * K.norm());
    const auto energy = [&](const Eigen::Vector2d& ua, const Eigen::Vector2d& ub) {
      Eigen::Vector4d d;
      d << ua, ub;
      return d.dot(K * d);
    };
    // Tangential motion and a uniform normal motion: nothing.
    EXPECT_NEAR(energy(0.7 * tt, 0.7 * tt), 0.0, 1e-14 * K.norm());
    EXPECT_NEAR(energy(0.7 * nn, 0.7 * nn), 0.0, 1e-14 * K.norm());
    EXPECT_NEAR(energy(0.3 * tt, -0.5 * tt), 0.0, 1e-14 * K.norm());
    // A relative normal motion δ: dᵀK₀d = T₀ ∫(∂w/∂s)² dA₀ = T₀ (δ/L)² 2π R_mid L.
    const double delta = 0.01, r_mid = 0.5 * (Xa(0) + Xb(0));
    EXPECT_NEAR(energy(Eigen::Vector2d::Zero(), delta * nn), T0 * delta * delta / L * 2 * M_PI * r_mid,
                1e-12 * T0 * delta * delta / L * 2 * M_PI * r_mid);
  }
}

namespace {

Model meridian(const std::string& mesh) {
  return read_deck_text(R"(title: meridian
units: {length: mm, force: N}
materials:
  m: {type: neo_hookean, mu: 1 kPa}
parts:
  wall:
    element: axisymmetric_membrane
    material: m
    thickness: 0.1 mm
    mesh: )" + mesh + R"(
boundary:
  fix: {node_set: wall.start, dofs: [r, z]}
steps:
  - {name: s, increments: 1, set: {}}
)",
                        "meridian.yaml");
}

}  // namespace

TEST(StartTension, MeridianMeanCurvatureIsOneOverRadiusOnASphereAndHalfOnATube) {
  for (const char* sense : {"start_angle: -90 deg, end_angle: 90 deg", "start_angle: 90 deg, end_angle: -90 deg"}) {
    const Model m =
        meridian(std::string("{type: arc, center: [0 mm, 0 mm], radius: 4 mm, ") + sense + ", elements: 60}");
    const std::vector<double> H = meridian_mean_curvature(m, m.parts[0])[0];
    ASSERT_EQ(H.size(), 60u);
    for (std::size_t e = 0; e < H.size(); ++e) EXPECT_NEAR(std::abs(H[e]), 0.25, 2e-3) << sense << " element " << e;
  }
  const Model tube = meridian("{type: line, from: [3 mm, 0 mm], to: [3 mm, 6 mm], elements: 12}");
  const std::vector<std::vector<double>> H = meridian_mean_curvature(tube, tube.parts[0]);
  ASSERT_EQ(H[0].size(), 12u);
  for (double h : H[0]) EXPECT_NEAR(std::abs(h), 1.0 / 6.0, 1e-14);
}
