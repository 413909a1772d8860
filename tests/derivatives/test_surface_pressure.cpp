// Checks of the 3-D follower pressure and the enclosed volume (surface_pressure.hpp):
//  - per element, ∂f/∂x and ∂V_e/∂x (about a point and about an axis) against
//    finite differences (relative error below 1e-6), tri3, quad4 and tri6;
//  - the in-place subtraction the element loop uses (subtract_surface_pressure) against them;
//  - on closed surfaces (octahedron of triangles, cube of quadrilaterals and
//    its triangulation, octahedron of 6-node triangles, all with perturbed nodes: the
//    last one curved) the assembled pressure force is p ∂V/∂x and the assembled load
//    stiffness is symmetric;
//  - exact volumes: unit cube, tetrahedron, octahedron (also of straight-edged 6-node
//    triangles), a warped cube (= the trilinear hexahedron's volume), and, about an axis,
//    an open prism (polygon area × length).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <numbers>
#include <random>
#include <vector>

#include "../support/fd.hpp"
#include "elements/tri6_shape.hpp"
#include "loads/surface_pressure.hpp"

using namespace tunica;
using tunica::test::fd_gradient;
using tunica::test::fd_jacobian;
using tunica::test::relative_error;

namespace {

Eigen::Matrix3d random_rotation(std::mt19937& rng) {
  std::normal_distribution<double> g;
  return Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng)).normalized().toRotationMatrix();
}

template <int N>
SurfaceNodes<N> nodes(const Eigen::VectorXd& v) {
  return Eigen::Map<const SurfaceNodes<N>>(v.data());
}
template <int N>
Eigen::VectorXd flat(const SurfaceNodes<N>& x) {
  return Eigen::Map<const Eigen::VectorXd>(x.data(), 3 * N);
}

/// A closed (or open) surface mesh: nodes and outward-oriented triangles, quadrilaterals and
/// 6-node triangles.
struct Mesh {
  std::vector<Eigen::Vector3d> nodes;
  std::vector<std::array<int, 3>> tris;
  std::vector<std::array<int, 4>> quads;
  std::vector<std::array<int, 6>> tri6s;
};

template <int N>
SurfaceNodes<N> element_nodes(const Eigen::VectorXd& pos, const std::array<int, N>& conn) {
  SurfaceNodes<N> x;
  for (int a = 0; a < N; ++a) x.col(a) = pos.segment<3>(3 * conn[a]);
  return x;
}

Eigen::VectorXd positions(const Mesh& m) {
  Eigen::VectorXd v(3 * m.nodes.size());
  for (std::size_t i = 0; i < m.nodes.size(); ++i) v.segment<3>(3 * i) = m.nodes[i];
  return v;
}

/// Σ_e V_e and, if wanted, Σ_e ∂V_e/∂x.
double mesh_volume(const Mesh& m, const Eigen::VectorXd& pos, const VolumeMeasure& how,
                   Eigen::VectorXd* grad = nullptr) {
  double V = 0;
  if (grad) grad->setZero(pos.size());
  const auto add = [&]<std::size_t M>(const std::array<int, M>& conn) {
    constexpr int N = static_cast<int>(M);
    ElementVector<N> g;
    V += enclosed_volume<N>(element_nodes<N>(pos, conn), how, grad ? &g : nullptr);
    if (grad)
      for (int a = 0; a < N; ++a) grad->segment<3>(3 * conn[a]) += g.template segment<3>(3 * a);
  };
  for (const auto& t : m.tris) add(t);
  for (const auto& q : m.quads) add(q);
  for (const auto& t : m.tri6s) add(t);
  return V;
}

/// Σ_e f_e and Σ_e ∂f_e/∂x (dense).
void mesh_pressure(const Mesh& m, const Eigen::VectorXd& pos, double p, Eigen::VectorXd& F, Eigen::MatrixXd& K,
                   double* max_element_asymmetry = nullptr) {
  const int n = pos.size();
  F.setZero(n);
  K.setZero(n, n);
  const auto add = [&]<std::size_t M>(const std::array<int, M>& conn) {
    constexpr int N = static_cast<int>(M);
    ElementVector<N> f;
    ElementMatrix<N> d;
    surface_pressure<N>(element_nodes<N>(pos, conn), p, f, &d);
    if (max_element_asymmetry)
      *max_element_asymmetry = std::max(*max_element_asymmetry, (d - d.transpose()).norm() / d.norm());
    for (int a = 0; a < N; ++a) {
      F.segment<3>(3 * conn[a]) += f.template segment<3>(3 * a);
      for (int b = 0; b < N; ++b) K.block<3, 3>(3 * conn[a], 3 * conn[b]) += d.template block<3, 3>(3 * a, 3 * b);
    }
  };
  for (const auto& t : m.tris) add(t);
  for (const auto& q : m.quads) add(q);
  for (const auto& t : m.tri6s) add(t);
}

/// Regular octahedron |x| + |y| + |z| = 1 of eight outward triangles.
Mesh octahedron() {
  Mesh m;
  for (int i = 0; i < 3; ++i)
    for (double s : {1.0, -1.0}) m.nodes.push_back(s * Eigen::Vector3d::Unit(i));  // node 2i (+), 2i+1 (−)
  for (int sx = 0; sx < 2; ++sx)
    for (int sy = 0; sy < 2; ++sy)
      for (int sz = 0; sz < 2; ++sz) {
        std::array<int, 3> t{sx, 2 + sy, 4 + sz};
        if ((sx + sy + sz) % 2 == 1) std::swap(t[1], t[2]);  // an odd number of reflections reverses the order
        m.tris.push_back(t);
      }
  return m;
}

/// Unit cube [0, 1]³ of six outward quadrilaterals; node i + 2j + 4k at (i, j, k).
Mesh cube() {
  Mesh m;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) m.nodes.emplace_back(i, j, k);
  m.quads = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  return m;
}

/// The cube with each quadrilateral split into two triangles (same orientation).
Mesh triangulated(const Mesh& q) {
  Mesh m;
  m.nodes = q.nodes;
  for (const auto& c : q.quads) {
    m.tris.push_back({c[0], c[1], c[2]});
    m.tris.push_back({c[0], c[2], c[3]});
  }
  return m;
}

/// The triangles of t as 6-node triangles (same orientation), a node at the midpoint of each edge.
Mesh quadratic(const Mesh& t) {
  Mesh m;
  m.nodes = t.nodes;
  std::map<std::pair<int, int>, int> mid;
  const auto midpoint = [&](int a, int b) {
    const std::pair<int, int> key(std::min(a, b), std::max(a, b));
    const auto [it, added] = mid.emplace(key, static_cast<int>(m.nodes.size()));
    if (added) m.nodes.push_back(0.5 * (t.nodes[a] + t.nodes[b]));
    return it->second;
  };
  for (const auto& c : t.tris)
    m.tri6s.push_back({c[0], c[1], c[2], midpoint(c[0], c[1]), midpoint(c[1], c[2]), midpoint(c[2], c[0])});
  return m;
}

void perturb(Mesh& m, std::mt19937& rng, double amount) {
  std::uniform_real_distribution<double> u(-amount, amount);
  for (auto& x : m.nodes) x += Eigen::Vector3d(u(rng), u(rng), u(rng));
}

/// Volume of the trilinear hexahedron with the cube's node numbering: 2 × 2 × 2
/// Gauss quadrature of det ∂x/∂ξ (exact: degree ≤ 2 in each variable).
double trilinear_hex_volume(const std::vector<Eigen::Vector3d>& x) {
  const double g = 1.0 / std::sqrt(3.0);
  double V = 0;
  for (double xi : {-g, g})
    for (double eta : {-g, g})
      for (double zeta : {-g, g}) {
        Eigen::Matrix3d J = Eigen::Matrix3d::Zero();
        for (int k = 0; k < 2; ++k)
          for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 2; ++i) {
              const double a = 2 * i - 1, b = 2 * j - 1, c = 2 * k - 1;
              const Eigen::Vector3d dN(a * (1 + b * eta) * (1 + c * zeta), b * (1 + a * xi) * (1 + c * zeta),
                                       c * (1 + a * xi) * (1 + b * eta));
              J += x[i + 2 * j + 4 * k] * (dN / 8).transpose();
            }
        V += J.determinant();
      }
  return V;
}

template <int N>
SurfaceNodes<N> random_element(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  SurfaceNodes<N> x;
  if constexpr (N == 3) {
    x << 0, 1.0, 0.3, 0, 0.1, 0.9, 0, 0, 0;
  } else if constexpr (N == 6) {  // the triangle above with its mid-edge nodes
    x << 0, 1.0, 0.3, 0.5, 0.65, 0.15, 0, 0.1, 0.9, 0.05, 0.5, 0.45, 0, 0, 0, 0, 0, 0;
  } else {
    x << 0, 1.0, 1.1, -0.1, 0, 0, 0.9, 1.0, 0, 0, 0, 0;
  }
  x += 0.2 * SurfaceNodes<N>::NullaryExpr([&] { return u(rng); });  // warped (tri6: curved)
  x = random_rotation(rng) * x;
  x.colwise() += Eigen::Vector3d(u(rng), u(rng), u(rng));
  return x;
}

template <int N>
void check_element_derivatives(std::mt19937& rng, double& max_df, double& max_dv) {
  std::uniform_real_distribution<double> u(-1, 1);
  for (int k = 0; k < 20; ++k) {
    const SurfaceNodes<N> x = random_element<N>(rng);
    const double p = 0.3 + u(rng);
    ElementVector<N> f;
    ElementMatrix<N> d;
    surface_pressure<N>(x, p, f, &d);
    const auto force = [&](const Eigen::VectorXd& v) -> Eigen::VectorXd {
      ElementVector<N> g;
      surface_pressure<N>(nodes<N>(v), p, g, nullptr);
      return g;
    };
    const double ef = relative_error(d, fd_jacobian(force, flat<N>(x), 1e-6));
    EXPECT_LT(ef, 1e-6) << "N=" << N;
    max_df = std::max(max_df, ef);
    for (bool axis : {false, true}) {
      VolumeMeasure how;
      how.point = Eigen::Vector3d(u(rng), u(rng), u(rng));
      how.about_axis = axis;
      how.axis = Eigen::Vector3d(u(rng), u(rng), u(rng)).normalized();
      ElementVector<N> g;
      enclosed_volume<N>(x, how, &g);
      const auto volume = [&](const Eigen::VectorXd& v) { return enclosed_volume<N>(nodes<N>(v), how, nullptr); };
      const double ev = relative_error(g, fd_gradient(volume, flat<N>(x), 1e-6));
      EXPECT_LT(ev, 1e-6) << "N=" << N << " axis=" << axis;
      max_dv = std::max(max_dv, ev);
    }
  }
}

/// subtract_surface_pressure, the in-place form the element loop uses, against surface_pressure:
/// r − f, K − ∂f/∂x and ‖f‖², on random r and K; and its stiffness against finite differences.
template <int N>
void check_in_place(std::mt19937& rng, double& max_diff) {
  std::uniform_real_distribution<double> u(-1, 1);
  for (int k = 0; k < 20; ++k) {
    const SurfaceNodes<N> x = random_element<N>(rng);
    const double p = 0.3 + u(rng);
    ElementVector<N> f;
    ElementMatrix<N> d;
    surface_pressure<N>(x, p, f, &d);
    const ElementVector<N> r0 = ElementVector<N>::NullaryExpr([&] { return u(rng); });
    const ElementMatrix<N> K0 = ElementMatrix<N>::NullaryExpr([&] { return u(rng); });
    ElementVector<N> r = r0;
    ElementMatrix<N> K = K0;
    const double f2 = subtract_surface_pressure<N>(x, p, r, &K);
    const double er = relative_error(r, r0 - f), eK = relative_error(K, K0 - d);
    EXPECT_LT(er, 1e-15) << "N=" << N;
    EXPECT_LT(eK, 1e-15) << "N=" << N;
    EXPECT_NEAR(f2, f.squaredNorm(), 1e-15 * f.squaredNorm()) << "N=" << N;
    max_diff = std::max({max_diff, er, eK});
    // Without K, the residual alone; from K = 0, minus the load stiffness.
    ElementVector<N> r1 = r0;
    subtract_surface_pressure<N>(x, p, r1, nullptr);
    EXPECT_EQ(r1, r) << "N=" << N;
    ElementMatrix<N> K1 = ElementMatrix<N>::Zero();
    ElementVector<N> r2 = ElementVector<N>::Zero();
    subtract_surface_pressure<N>(x, p, r2, &K1);
    const auto minus_force = [&](const Eigen::VectorXd& v) -> Eigen::VectorXd {
      ElementVector<N> g = ElementVector<N>::Zero();
      subtract_surface_pressure<N>(nodes<N>(v), p, g, nullptr);
      return g;
    };
    EXPECT_LT(relative_error(K1, fd_jacobian(minus_force, flat<N>(x), 1e-6)), 1e-6) << "N=" << N;
  }
}

}  // namespace

TEST(SurfacePressure, InPlaceSubtractionIsTheLoadAndItsStiffness) {
  std::mt19937 rng(25);
  double diff = 0;
  check_in_place<3>(rng, diff);
  check_in_place<4>(rng, diff);
  check_in_place<6>(rng, diff);
  std::cout << "subtract_surface_pressure: max relative difference from surface_pressure " << diff << "\n";
}

TEST(SurfacePressure, LoadStiffnessAndVolumeGradientMatchFiniteDifferences) {
  std::mt19937 rng(21);
  double df = 0, dv = 0;
  check_element_derivatives<3>(rng, df, dv);
  check_element_derivatives<4>(rng, df, dv);
  check_element_derivatives<6>(rng, df, dv);
  std::cout << "surface_pressure: max FD relative error: load stiffness " << df << ", volume gradient " << dv
            << "\n";
}

TEST(SurfacePressure, PressureOnAClosedSurfaceIsPressureTimesVolumeGradientAndItsStiffnessIsSymmetric) {
  std::mt19937 rng(22);
  Mesh oct = octahedron(), box = cube();
  perturb(oct, rng, 0.15);
  perturb(box, rng, 0.15);
  const Mesh tribox = triangulated(box);
  Mesh oct6 = quadratic(octahedron());
  perturb(oct6, rng, 0.15);  // corners and mid-edge nodes: curved faces
  for (const Mesh* m : std::initializer_list<const Mesh*>{&oct, &box, &tribox, &oct6}) {
    const Eigen::VectorXd pos = positions(*m);
    const double p = 1.3;
    Eigen::VectorXd F, G;
    Eigen::MatrixXd K;
    double asym_element = 0;
    mesh_pressure(*m, pos, p, F, K, &asym_element);
    VolumeMeasure how;
    how.point = Eigen::Vector3d(0.3, -0.2, 0.4);
    mesh_volume(*m, pos, how, &G);
    const auto volume = [&](const Eigen::VectorXd& v) { return mesh_volume(*m, v, how); };
    EXPECT_LT(relative_error(F, p * G), 1e-13);  // analytic ∂V/∂x
    EXPECT_LT(relative_error(F, p * fd_gradient(volume, pos, 1e-6)), 1e-8);
    // Load stiffness: nonsymmetric per element, symmetric once assembled on a closed surface,
    // and p times the Hessian of the volume.
    EXPECT_GT(asym_element, 0.1);
    EXPECT_LT((K - K.transpose()).norm() / K.norm(), 1e-14);
    const auto grad = [&](const Eigen::VectorXd& v) -> Eigen::VectorXd {
      Eigen::VectorXd g;
      mesh_volume(*m, v, how, &g);
      return g;
    };
    EXPECT_LT(relative_error(K, p * fd_jacobian(grad, pos, 1e-6)), 1e-8);
  }
}

TEST(SurfacePressure, VolumesOfClosedPolyhedraAreExact) {
  VolumeMeasure how;
  for (const Eigen::Vector3d& p0 : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.3, 2.0, -1.1)}) {
    how.point = p0;
    const Mesh box = cube();
    EXPECT_NEAR(mesh_volume(box, positions(box), how), 1.0, 1e-14);
    EXPECT_NEAR(mesh_volume(triangulated(box), positions(box), how), 1.0, 1e-14);
    const Mesh oct = octahedron();
    EXPECT_NEAR(mesh_volume(oct, positions(oct), how), 4.0 / 3.0, 1e-14);
    const Mesh oct6 = quadratic(oct);
    EXPECT_NEAR(mesh_volume(oct6, positions(oct6), how), 4.0 / 3.0, 1e-14);
    Mesh tet;
    tet.nodes = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    tet.tris = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    EXPECT_NEAR(mesh_volume(tet, positions(tet), how), 1.0 / 6.0, 1e-15);
    // A general tetrahedron: |det(b − a, c − a, d − a)|/6.
    tet.nodes = {{0.1, -0.3, 0.2}, {1.4, 0.2, -0.1}, {0.3, 1.1, 0.4}, {0.2, 0.3, 1.7}};
    Eigen::Matrix3d D;
    D << tet.nodes[1] - tet.nodes[0], tet.nodes[2] - tet.nodes[0], tet.nodes[3] - tet.nodes[0];
    EXPECT_NEAR(mesh_volume(tet, positions(tet), how), D.determinant() / 6.0, 1e-14);
  }
  // A warped cube (non-planar faces): the volume of the trilinear hexahedron it bounds.
  std::mt19937 rng(23);
  Mesh box = cube();
  perturb(box, rng, 0.2);
  how.point = Eigen::Vector3d(-0.4, 0.1, 0.9);
  const double Vhex = trilinear_hex_volume(box.nodes);
  EXPECT_NEAR(mesh_volume(box, positions(box), how), Vhex, 1e-14);
  EXPECT_GT(std::abs(Vhex - 1.0), 1e-3);
}

TEST(SurfacePressure, VolumeAboutAnAxisOfAnOpenPrismIsPolygonAreaTimesLength) {
  // An open prism (no end caps) around an axis through p₀ with direction a: an
  // irregular polygon (random radii) swept over length L; the measure about the
  // axis gives area × L for any p₀ on or off the prism's centre line.
  std::mt19937 rng(24);
  std::uniform_real_distribution<double> u(0.8, 1.3);
  const int n = 9;
  const double L = 2.5;
  const Eigen::Matrix3d R = random_rotation(rng);
  const Eigen::Vector3d e1 = R.col(0), e2 = R.col(1), a = R.col(2);  // e1 × e2 = a
  const Eigen::Vector3d c(0.4, -0.7, 1.2);
  std::vector<Eigen::Vector2d> poly;
  for (int k = 0; k < n; ++k) {
    const double t = 2 * std::numbers::pi * k / n;
    poly.emplace_back(u(rng) * std::cos(t), u(rng) * std::sin(t));
  }
  double area = 0;  // shoelace
  for (int k = 0; k < n; ++k) {
    const auto& p = poly[k];
    const auto& q = poly[(k + 1) % n];
    area += 0.5 * (p.x() * q.y() - q.x() * p.y());
  }
  Mesh quads;
  for (int end = 0; end < 2; ++end)
    for (int k = 0; k < n; ++k) quads.nodes.push_back(c + poly[k].x() * e1 + poly[k].y() * e2 + end * L * a);
  // Outward: g1 along the polygon (counterclockwise about a), g2 along a: g1 × g2 points out.
  for (int k = 0; k < n; ++k) quads.quads.push_back({k, (k + 1) % n, n + (k + 1) % n, n + k});
  const Mesh tris = triangulated(quads);
  for (const Eigen::Vector3d& off : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.2, -0.1, 3.0)}) {
    VolumeMeasure how;
    how.about_axis = true;
    how.axis = a;
    how.point = c + off.x() * e1 + off.y() * e2 + off.z() * a;
    EXPECT_NEAR(mesh_volume(quads, positions(quads), how), area * L, 1e-13);
    EXPECT_NEAR(mesh_volume(tris, positions(tris), how), area * L, 1e-13);
    // The same surface measured about a point is not a closed-surface volume.
    VolumeMeasure pt;
    pt.point = how.point;
    EXPECT_GT(std::abs(mesh_volume(quads, positions(quads), pt) - area * L), 1e-3);
    // ∂V/∂x of the whole open prism against finite differences.
    Eigen::VectorXd G;
    mesh_volume(quads, positions(quads), how, &G);
    const auto volume = [&](const Eigen::VectorXd& v) { return mesh_volume(quads, v, how); };
    EXPECT_LT(relative_error(G, fd_gradient(volume, positions(quads), 1e-6)), 1e-8);
  }
}
