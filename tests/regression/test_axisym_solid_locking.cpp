// Volumetric locking of the four-node axisymmetric solid (theory manual §10): the plain
// displacement element (Q1) against the mean-dilatation element (Q1/P0) on a
// nearly incompressible (κ/μ = 10⁴) neo-Hookean thick-walled cylinder in plane
// strain (λ_z = 1) whose inner radius is prescribed.
//
// Exact incompressible solution (derived here). Reference radii R ∈ [R_i, R_o],
// inner radius moved to r_i. Incompressibility with λ_z = 1: r dr = R dR, so
//   r² = R² + c,   c = r_i² − R_i²,   λ_θ = r/R = λ,   λ_r = R/r = 1/λ.
// Neo-Hookean (incompressible, σ = μ b − q I): σ_θθ − σ_rr = μ(λ² − λ⁻²).
// Radial equilibrium dσ_rr/dr + (σ_rr − σ_θθ)/r = 0 with σ_rr(r_o) = 0 gives the
// inner pressure P_i = −σ_rr(r_i) = μ ∫_{r_i}^{r_o} (λ² − λ⁻²) dr/r. With s = r²,
// λ² = s/(s − c), dr/r = ds/(2s):
//   P_i = (μ/2) ∫ [1/(s − c) − 1/s + c/s²] ds = (μ/2) [ln(R²/r²) − c/r²]_{r_i}^{r_o}
//       = (μ/2) [ln(λ_i²/λ_o²) + c/r_i² − c/r_o²].
// The reaction on the inner surface of a slice of height h is F = P_i 2π r_i h,
// and the stored energy, with W = (μ/2)(λ² + λ⁻² − 2) = (μ/2)(c/R² − c/(R² + c)),
//   Π = 2πh ∫ W R dR = (πhμc/2) ln(λ_i²/λ_o²),   dΠ/dr_i = F (checked below).
// Outer radius r_o = √(R_o² + c).
//
// The slice: nr × 2 elements, R ∈ [1, 2], Z ∈ [0, 0.5], the middle row of nodes
// displaced axially (a distorted mesh); u_z = 0 on the top and bottom faces,
// u_r = r_i − R_i on the inner face, everything else free. Newton's method on the
// dense assembled system, in load steps on r_i; each step is predicted by adding the
// increment of the exact incompressible map to the last converged state (only an
// initial guess: Newton converges to the discrete solution), with backtracking on
// the residual norm. (A predictor that puts the whole exact map on the mesh makes
// the discrete dilatation error of the map times κ a large pressure, and the
// tangent there is indefinite for Q1/P0.)
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "elements/axisym_solid.hpp"
#include "io/deck_node.hpp"
#include "io/read_params.hpp"
#include "materials/solid_material.hpp"

using namespace tunica;

namespace {

constexpr double kRi = 1.0, kRo = 2.0, kH = 0.5, kMu = 1.0, kKappa = 1e4;

struct Exact {
  double c, ro, P, F, energy;
};

Exact exact(double ri) {
  Exact e;
  e.c = ri * ri - kRi * kRi;
  e.ro = std::sqrt(kRo * kRo + e.c);
  const double li2 = ri * ri / (kRi * kRi), lo2 = e.ro * e.ro / (kRo * kRo);
  e.P = 0.5 * kMu * (std::log(li2 / lo2) + e.c / (ri * ri) - e.c / (e.ro * e.ro));
  e.F = e.P * 2 * std::numbers::pi * ri * kH;
  e.energy = 0.5 * std::numbers::pi * kH * kMu * e.c * std::log(li2 / lo2);
  return e;
}

struct Result {
  double F = 0, ro = 0, energy = 0;
  int iterations = 0;
  bool converged = false;
};

Result solve_cylinder(const SolidMaterial& m, SolidFormulation form, int nr, double ri, int steps) {
  const int nz = 2, nn = (nr + 1) * (nz + 1), ndof = 2 * nn;
  std::vector<Eigen::Vector2d> X(nn);
  for (int j = 0; j <= nz; ++j)
    for (int i = 0; i <= nr; ++i) {
      const double dz = (j == 1) ? 0.2 * (kH / nz) * ((i % 2) ? 1 : -1) : 0.0;  // distortion
      X[j * (nr + 1) + i] = Eigen::Vector2d(kRi + (kRo - kRi) * i / nr, kH * j / nz + dz);
    }
  std::vector<std::array<int, 4>> elements;
  for (int j = 0; j < nz; ++j)
    for (int i = 0; i < nr; ++i) {
      const int a = j * (nr + 1) + i;
      elements.push_back({a, a + 1, a + nr + 2, a + nr + 1});
    }
  // Prescribed DOFs: z on the top and bottom faces, r on the inner face.
  std::vector<bool> fixed(ndof, false);
  for (int n = 0; n < nn; ++n) {
    const int i = n % (nr + 1), j = n / (nr + 1);
    if (j == 0 || j == nz) fixed[2 * n + 1] = true;
    if (i == 0) fixed[2 * n] = true;
  }
  std::vector<int> eq(ndof, -1);
  int nfree = 0;
  for (int d = 0; d < ndof; ++d)
    if (!fixed[d]) eq[d] = nfree++;

  Eigen::VectorXd x(ndof);
  for (int n = 0; n < nn; ++n) x.segment<2>(2 * n) = X[n];
  Result res;
  Eigen::VectorXd f(ndof);
  Eigen::MatrixXd K(ndof, ndof);
  double energy = 0;
  const auto assemble = [&](bool tangent) {
    f.setZero();
    if (tangent) K.setZero();
    energy = 0;
    for (const auto& e : elements) {
      SolidNodes Xe, xe;
      for (int a = 0; a < 4; ++a) {
        Xe.col(a) = X[e[a]];
        xe.col(a) = x.segment<2>(2 * e[a]);
      }
      SolidVector fe;
      SolidMatrix Ke;
      energy += axisym_solid(Xe, xe, m, form, fe, tangent ? &Ke : nullptr);
      for (int a = 0; a < 4; ++a) {
        f.segment<2>(2 * e[a]) += fe.segment<2>(2 * a);
        if (tangent)
          for (int b = 0; b < 4; ++b) K.block<2, 2>(2 * e[a], 2 * e[b]) += Ke.block<2, 2>(2 * a, 2 * b);
      }
    }
  };
  // Norm of the residual on the free DOFs at the current x; +∞ where an element inverts.
  const auto free_residual_norm = [&]() {
    try {
      assemble(false);
    } catch (const std::domain_error&) {
      return std::numeric_limits<double>::infinity();
    }
    double n2 = 0;
    for (int a = 0; a < ndof; ++a)
      if (eq[a] >= 0) n2 += f(a) * f(a);
    return std::sqrt(n2);
  };
  double c_prev = 0;
  for (int s = 1; s <= steps; ++s) {
    const double ri_s = kRi + (ri - kRi) * s / steps;
    const double c = ri_s * ri_s - kRi * kRi;
    // Predictor: the increment of the exact incompressible map r² = R² + c added to
    // the last converged state (and r_i on the inner face).
    for (int n = 0; n < nn; ++n) {
      const double R2 = X[n](0) * X[n](0);
      x(2 * n) += std::sqrt(R2 + c) - std::sqrt(R2 + c_prev);
    }
    c_prev = c;
    bool ok = false;
    for (int it = 0; it < 40 && !ok; ++it) {
      assemble(true);
      Eigen::VectorXd r(nfree);
      Eigen::MatrixXd Kf(nfree, nfree);
      for (int a = 0; a < ndof; ++a) {
        if (eq[a] < 0) continue;
        r(eq[a]) = f(a);
        for (int b = 0; b < ndof; ++b)
          if (eq[b] >= 0) Kf(eq[a], eq[b]) = K(a, b);
      }
      double scale = 0;
      for (int a = 0; a < ndof; ++a) scale = std::max(scale, std::abs(f(a)));
      if (r.norm() <= 1e-8 * scale) {  // the round-off floor is ~1e-10 of the reaction at κ/μ = 1e4
        ok = true;
        break;
      }
      const Eigen::VectorXd du = Kf.partialPivLu().solve(-r);
      // Backtracking on the residual norm (halving; the full step is taken near the solution).
      const Eigen::VectorXd x0 = x;
      double alpha = 1;
      for (int ls = 0; ls < 30; ++ls, alpha *= 0.5) {
        x = x0;
        for (int a = 0; a < ndof; ++a)
          if (eq[a] >= 0) x(a) += alpha * du(eq[a]);
        if (free_residual_norm() < (1 - 1e-4 * alpha) * r.norm()) break;
      }
      ++res.iterations;
    }
    if (!ok) return res;
  }
  assemble(false);
  res.converged = true;
  res.energy = energy;
  for (int n = 0; n < nn; ++n) {
    const int i = n % (nr + 1);
    if (i == 0) res.F += f(2 * n);
  }
  double ro = 0;
  for (int j = 0; j <= nz; ++j) ro += x(2 * (j * (nr + 1) + nr));
  res.ro = ro / (nz + 1);
  return res;
}

std::unique_ptr<SolidMaterial> nearly_incompressible() {
  const YAML::Node node = YAML::Load("{type: neo_hookean_solid, mu: 1.0, kappa: 1.0e4}");
  const auto& type = solid_material_types().at("neo_hookean_solid");
  return type.make(read_params(DeckNode(node, "test", "solid_materials.m"), type.spec, UnitSystem("mm", "N"), {"type"}));
}

}  // namespace

TEST(AxisymSolidLocking, ExactThickCylinderSolutionIsConsistent) {
  // dΠ/dr_i = F (energy and pressure derived independently above).
  const double ri = 1.3, h = 1e-6;
  EXPECT_NEAR((exact(ri + h).energy - exact(ri - h).energy) / (2 * h), exact(ri).F, 1e-8);
}

TEST(AxisymSolidLocking, PlainElementLocksMeanDilatationIsAccurateAndConverges) {
  const auto m = nearly_incompressible();
  const double ri = 1.3;
  const Exact ex = exact(ri);
  std::printf("thick cylinder, plane strain, κ/μ = 1e4, r_i/R_i = %.2f: exact F = %.6f, r_o = %.6f, Π = %.6f\n", ri,
              ex.F, ex.ro, ex.energy);
  std::printf("%4s %6s %12s %10s %12s %10s %12s %10s %5s\n", "nr", "form", "F", "err F", "u_o", "err u_o", "energy",
              "err Π", "its");
  double previous_mixed = 1e300;
  for (int nr : {4, 8, 16}) {
    for (SolidFormulation form : {SolidFormulation::displacement, SolidFormulation::mean_dilatation}) {
      const Result r = solve_cylinder(*m, form, nr, ri, 4);
      ASSERT_TRUE(r.converged) << nr;
      const double eF = std::abs(r.F - ex.F) / ex.F;
      const double eu = std::abs((r.ro - kRo) - (ex.ro - kRo)) / (ex.ro - kRo);
      const double eE = std::abs(r.energy - ex.energy) / ex.energy;
      const bool mixed = form == SolidFormulation::mean_dilatation;
      std::printf("%4d %6s %12.6f %9.3f%% %12.6f %9.3f%% %12.6f %9.3f%% %5d\n", nr, mixed ? "Q1/P0" : "Q1", r.F,
                  100 * eF, r.ro - kRo, 100 * eu, r.energy, 100 * eE, r.iterations);
      if (mixed) {
        EXPECT_LT(eF, 0.02) << nr;
        EXPECT_LT(eE, 0.02) << nr;
        EXPECT_LT(eu, 0.02) << nr;
        EXPECT_LT(eF, previous_mixed) << nr;  // converges under refinement
        previous_mixed = eF;
      } else {
        EXPECT_GT(eF, 0.2) << nr;  // locked
        EXPECT_GT(eE, 0.2) << nr;
      }
    }
  }
}
