// Patch test of the 3-D membrane elements (membrane3d.hpp): a flat square patch
// of distorted quadrilaterals and triangles, random interior nodes, deformed by
// a homogeneous in-plane map x = c + Q [F (X1, X2); 0] (Q: a rigid rotation with
// an out-of-plane tilt of the whole plane). Then
//  - the internal force vanishes at every interior node and every Gauss point
//    has the same S (the one of C = Fᵀ F in the material frame);
//  - Newton's method (a small dense assembly here) from perturbed interior
//    nodes converges quadratically back to the homogeneous state;
// for every registered material, each of its samples and orientations of the material frame
// (tests/support/material_registry.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>
#include <vector>

#include "../support/material_registry.hpp"
#include "elements/membrane3d.hpp"

using namespace tunica;
using tunica::test::MaterialCase;

namespace {

/// A patch mesh and its element reference data; DOFs node-major (x, y, z).
struct Patch {
  std::vector<Eigen::Vector3d> X;
  std::vector<bool> boundary;
  std::vector<std::array<int, 3>> tris;
  std::vector<std::array<int, 4>> quads;
  std::vector<MembraneReference<3>> tri_ref;
  std::vector<MembraneReference<4>> quad_ref;
};

constexpr double kMaterialAngle = 0.4;  // direction 1 at 0.4 rad from the X1 axis, + the sample's orientation

/// Square [0, 2]² of n × n cells, interior nodes moved randomly; a third of the
/// cells split into two triangles (alternating diagonals), the rest quadrilaterals;
/// material direction 1 at `angle` from the X1 axis.
Patch make_patch(int n, std::mt19937& rng, double H, double angle) {
  Patch p;
  std::uniform_real_distribution<double> u(-0.3, 0.3);
  const double h = 2.0 / n;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const bool b = i == 0 || j == 0 || i == n || j == n;
      Eigen::Vector3d X(i * h, j * h, 0);
      if (!b) {
        const double dx = u(rng);  // one draw per statement (see below)
        const double dy = u(rng);
        X += h * Eigen::Vector3d(dx, dy, 0);
      }
      p.X.push_back(X);
      p.boundary.push_back(b);
    }
  const auto id = [&](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if ((i + 2 * j) % 3 == 0) {
        if ((i + j) % 2 == 0) {
          p.tris.push_back({a, b, c});
          p.tris.push_back({a, c, d});
        } else {
          p.tris.push_back({a, b, d});
          p.tris.push_back({b, c, d});
        }
      } else {
        p.quads.push_back({a, b, c, d});
      }
    }
  const DirectionRule rule = [angle](const Eigen::Vector3d&, const Eigen::Vector3d&) {
    return Eigen::Vector3d(std::cos(angle), std::sin(angle), 0);
  };
  const auto ref = [&]<std::size_t M>(const std::array<int, M>& conn) {
    constexpr int N = static_cast<int>(M);
    SurfaceNodes<N> Xe;
    for (int a = 0; a < N; ++a) Xe.col(a) = p.X[conn[a]];
    return membrane_reference<N>(Xe, H, rule);
  };
  for (const auto& t : p.tris) p.tri_ref.push_back(ref(t));
  for (const auto& q : p.quads) p.quad_ref.push_back(ref(q));
  return p;
}

/// Dense assembly of the internal force and tangent; S of every Gauss point.
void assemble(const Patch& p, const Eigen::VectorXd& x, const MembraneMaterial& m, Eigen::VectorXd& f,
              Eigen::MatrixXd* K, std::vector<Eigen::Vector3d>* S = nullptr) {
  const int n = x.size();
  f.setZero(n);
  if (K) K->setZero(n, n);
  if (S) S->clear();
  const auto add = [&]<std::size_t M>(const std::array<int, M>& conn, const MembraneReference<static_cast<int>(M)>& ref) {
    constexpr int N = static_cast<int>(M);
    SurfaceNodes<N> xe;
    for (int a = 0; a < N; ++a) xe.col(a) = x.segment<3>(3 * conn[a]);
    ElementVector<N> fe;
    ElementMatrix<N> Ke;
    std::array<MembranePoint, SurfaceShapeTraits<N>::kPoints> pts;
    membrane3d<N>(ref, xe, m, fe, K ? &Ke : nullptr, &pts);
    for (int a = 0; a < N; ++a) {
      f.segment<3>(3 * conn[a]) += fe.template segment<3>(3 * a);
      if (K)
        for (int b = 0; b < N; ++b) K->block<3, 3>(3 * conn[a], 3 * conn[b]) += Ke.template block<3, 3>(3 * a, 3 * b);
    }
    if (S)
      for (const auto& pt : pts) S->push_back(pt.S);
  };
  for (std::size_t e = 0; e < p.tris.size(); ++e) add(p.tris[e], p.tri_ref[e]);
  for (std::size_t e = 0; e < p.quads.size(); ++e) add(p.quads[e], p.quad_ref[e]);
}

struct HomogeneousMap {
  Eigen::Matrix2d F;
  Eigen::Matrix3d Q;
  Eigen::Vector3d c;
  Eigen::Vector3d operator()(const Eigen::Vector3d& X) const {
    const Eigen::Vector2d y = F * X.head<2>();
    return c + Q * Eigen::Vector3d(y.x(), y.y(), 0);
  }
};

HomogeneousMap the_map() {
  HomogeneousMap phi;
  phi.F << 1.3, 0.2, 0, 0.9;
  phi.Q = (Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(0.35, Eigen::Vector3d::UnitX()) *
           Eigen::AngleAxisd(-0.2, Eigen::Vector3d::UnitY()))
              .toRotationMatrix();
  phi.c = Eigen::Vector3d(0.3, -0.2, 0.5);
  return phi;
}

class MembranePatch : public ::testing::TestWithParam<MaterialCase> {
protected:
  void SetUp() override {
    m = tunica::test::make_membrane(GetParam());
    angle = kMaterialAngle + GetParam().angle;
  }
  std::unique_ptr<MembraneMaterial> m;
  double angle = 0;
};

INSTANTIATE_TEST_SUITE_P(Registry, MembranePatch,
                         ::testing::ValuesIn(tunica::test::membrane_cases(tunica::test::Orientations::each)),
                         tunica::test::case_name);

}  // namespace

TEST_P(MembranePatch, HomogeneousDeformationGivesZeroInteriorForceAndUniformStress) {
  std::mt19937 rng(31);
  const Patch p = make_patch(5, rng, 0.1, angle);
  ASSERT_FALSE(p.tris.empty());
  ASSERT_FALSE(p.quads.empty());
  const HomogeneousMap phi = the_map();
  Eigen::VectorXd x(3 * p.X.size());
  for (std::size_t i = 0; i < p.X.size(); ++i) x.segment<3>(3 * i) = phi(p.X[i]);
  // The expected stress: C_ij = (F e_i)·(F e_j) in the material frame.
  const Eigen::Vector2d e1(std::cos(angle), std::sin(angle)), e2(-e1.y(), e1.x());
  const Eigen::Vector2d f1 = phi.F * e1, f2 = phi.F * e2;
  const Eigen::Vector3d S0 = membrane_response(*m, Eigen::Vector3d(f1.squaredNorm(), f2.squaredNorm(), f1.dot(f2))).S;
  Eigen::VectorXd f;
  std::vector<Eigen::Vector3d> S;
  assemble(p, x, *m, f, nullptr, &S);
  double fmax = 0, finterior = 0;
  for (std::size_t i = 0; i < p.X.size(); ++i) {
    const double fi = f.segment<3>(3 * i).norm();
    fmax = std::max(fmax, fi);
    if (!p.boundary[i]) finterior = std::max(finterior, fi);
  }
  EXPECT_LT(finterior, 1e-10 * fmax);
  for (const auto& s : S) EXPECT_LT((s - S0).norm(), 1e-12 * S0.norm());
}

TEST_P(MembranePatch, NewtonFromPerturbedInteriorNodesConvergesQuadraticallyToTheHomogeneousState) {
  std::mt19937 rng(32);
  const Patch p = make_patch(4, rng, 0.1, angle);
  const HomogeneousMap phi = the_map();
  const Eigen::Vector3d normal = phi.Q.col(2);
  std::vector<int> free;
  for (std::size_t i = 0; i < p.X.size(); ++i)
    if (!p.boundary[i])
      for (int k = 0; k < 3; ++k) free.push_back(3 * i + k);
  Eigen::VectorXd exact(3 * p.X.size());
  for (std::size_t i = 0; i < p.X.size(); ++i) exact.segment<3>(3 * i) = phi(p.X[i]);
  std::uniform_real_distribution<double> u(-1, 1);
  const std::string yaml = tunica::test::sample_yaml(GetParam());
  Eigen::VectorXd x = exact;
  for (std::size_t i = 0; i < p.X.size(); ++i)
    if (!p.boundary[i]) {
      // One draw per statement: the evaluation order of function arguments is unspecified
      // (gcc and clang differ), and the perturbation must not depend on the compiler.
      const double a = 0.06 * u(rng);
      const double b = 0.06 * u(rng);
      const double c = 0.03 * u(rng);
      x.segment<3>(3 * i) += phi.Q * Eigen::Vector3d(a, b, 0) + c * normal;
    }
  Eigen::VectorXd f, ff(free.size());
  Eigen::MatrixXd K, Kff(free.size(), free.size());
  assemble(p, exact, *m, f, nullptr);
  const double scale = f.norm();  // boundary reactions of the solution
  std::vector<double> res;
  for (int it = 0; it < 20; ++it) {
    assemble(p, x, *m, f, &K);
    for (std::size_t i = 0; i < free.size(); ++i) {
      ff(i) = f(free[i]);
      for (std::size_t j = 0; j < free.size(); ++j) Kff(i, j) = K(free[i], free[j]);
    }
    res.push_back(ff.norm() / scale);
    if (res.back() < 1e-13) break;
    const Eigen::VectorXd du = Kff.partialPivLu().solve(-ff);
    for (std::size_t i = 0; i < free.size(); ++i) x(free[i]) += du(i);
  }
  std::cout << yaml << ": relative residuals";
  for (double r : res) std::cout << " " << r;
  std::cout << "\n";
  ASSERT_LT(res.back(), 1e-13) << yaml;
  // Plain Newton (no line search) from interior nodes moved by up to 6 % of the element
  // size: 6–9 iterations (Mooney–Rivlin spends two on the way in); the order is tested below.
  EXPECT_LE(res.size(), 10u) << yaml;
  EXPECT_LT((x - exact).norm() / exact.norm(), 1e-12) << yaml;
  // Quadratic convergence: once in the asymptotic range (residual < 1e-3 and
  // above round-off), each step squares the residual up to a moderate constant.
  int checked = 0;
  for (std::size_t k = 0; k + 1 < res.size(); ++k)
    if (res[k] < 1e-3 && res[k + 1] > 1e-14) {
      EXPECT_LT(res[k + 1], 100 * res[k] * res[k]) << yaml << " step " << k;
      ++checked;
    }
  EXPECT_GE(checked, 1) << yaml;
}
