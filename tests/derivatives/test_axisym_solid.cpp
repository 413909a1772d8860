// Finite-difference and consistency checks of the solid materials and the
// four-node axisymmetric solid element (theory manual §10, the plaque), over every
// registered solid material and each of its samples (tests/support/material_registry.hpp):
//  - material (10.2): S = 2 ∂W/∂C and 𝒞 = 2 ∂S/∂C by central differences at random
//    3-D states (stretches 0.8–1.6, shear, rotation), both the isochoric part and the total;
//    U' and U'' of the volumetric part; the reference state is stress free;
//  - element (displacement and mean-dilatation, (10.4)–(10.5)): f = ∂Π_e/∂x and K = ∂f/∂x by
//    central differences at distorted, stretched, sheared states; K symmetric;
//  - zero force in the reference state and under a rigid axial translation;
//  - patch test: a homogeneous deformation r → λ_r r, z → λ_z z of a distorted
//    mesh gives the same stress everywhere and no force on interior nodes;
//  - the homogeneous Cauchy stress against the hand-derived neo-Hookean formula.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "../support/fd.hpp"
#include "../support/material_registry.hpp"
#include "elements/axisym_solid.hpp"
#include "materials/solid_material.hpp"

using namespace tunica;
using tunica::test::fd_gradient;
using tunica::test::fd_jacobian;
using tunica::test::kFdTolerance;
using tunica::test::MaterialCase;
using tunica::test::relative_error;
using tunica::test::solid_from_yaml;

namespace {

const SolidFormulation kForms[] = {SolidFormulation::displacement, SolidFormulation::mean_dilatation};
const char* name(SolidFormulation f) { return f == SolidFormulation::displacement ? "Q1" : "Q1/P0"; }

Eigen::Matrix3d C_of(const Voigt6& v) { return from_voigt(v); }

Eigen::Matrix3d random_rotation(std::mt19937& rng) {
  std::normal_distribution<double> g;
  return Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng)).normalized().toRotationMatrix();
}

/// Random deformation gradient F = Q₁ diag(s) Q₂, principal stretches s ∈ [0.8, 1.6] (J from
/// 0.51 to 4.1: large volume changes of a compressible solid), shear and rotation.
Eigen::Matrix3d random_F(std::mt19937& rng) {
  std::uniform_real_distribution<double> stretch(0.8, 1.6);
  const Eigen::Vector3d s(stretch(rng), stretch(rng), stretch(rng));
  return random_rotation(rng) * s.asDiagonal() * random_rotation(rng);
}

/// Finite differences are taken with respect to the 6 Voigt entries v of C; an
/// off-diagonal v_I moves both C_ij and C_ji, so ∂W/∂v_I = ∂W/∂C_ii (diagonal) or
/// 2 ∂W/∂C_ij (shear). Hence S_I = 2 ∂W/∂v_I (diagonal), ∂W/∂v_I (shear); and with
/// dS = D dE, dE_J = ½ dv_J (diagonal) or 2dE_ij = dv_J (shear):
/// D_IJ = 2 ∂S_I/∂v_J (diagonal J), ∂S_I/∂v_J (shear J).
Voigt6 S_from_fd(const Eigen::VectorXd& dWdv) {
  Voigt6 S;
  for (int I = 0; I < 6; ++I) S(I) = (I < 3 ? 2.0 : 1.0) * dWdv(I);
  return S;
}
Voigt66 D_from_fd(const Eigen::MatrixXd& dSdv) {
  Voigt66 D;
  for (int J = 0; J < 6; ++J) D.col(J) = (J < 3 ? 2.0 : 1.0) * dSdv.col(J);
  return D;
}

SolidNodes unflat(const Eigen::VectorXd& v) { return Eigen::Map<const SolidNodes>(v.data()); }
Eigen::VectorXd flat(const SolidNodes& x) { return Eigen::Map<const Eigen::VectorXd>(x.data(), 8); }

/// Random distorted reference quad (counter-clockwise, away from the axis) and a
/// current state about its centre c: x = c' + A (X − c), A = Q₁ diag(s) Q₂ with in-plane
/// stretches s ∈ [0.8, 1.6], rotations up to ±0.3 rad (shear), and c' = (λ_θ c_r, c_z + t)
/// with a hoop stretch λ_θ ∈ [0.8, 1.6]; then nodes moved by up to ±0.03.
void random_state(std::mt19937& rng, SolidNodes& X, SolidNodes& x) {
  std::uniform_real_distribution<double> u(-1, 1), stretch(0.8, 1.6);
  const double R0 = 1.0 + 0.4 * u(rng), Z0 = u(rng), hr = 0.3 + 0.1 * u(rng), hz = 0.4 + 0.1 * u(rng);
  X << R0, R0 + hr, R0 + hr, R0, Z0, Z0, Z0 + hz, Z0 + hz;
  X += 0.06 * SolidNodes::NullaryExpr([&] { return u(rng); });
  const auto rot = [](double t) {
    Eigen::Matrix2d Q;
    Q << std::cos(t), -std::sin(t), std::sin(t), std::cos(t);
    return Q;
  };
  const double s1 = stretch(rng), s2 = stretch(rng), t1 = 0.3 * u(rng), t2 = 0.3 * u(rng);
  const Eigen::Matrix2d A = rot(t1) * Eigen::Vector2d(s1, s2).asDiagonal() * rot(t2);
  const Eigen::Vector2d c = X.rowwise().mean();
  const Eigen::Vector2d c_new(stretch(rng) * c(0), c(1) + 0.3 * u(rng));
  x = (A * (X.colwise() - c)).colwise() + c_new;
  x += 0.03 * SolidNodes::NullaryExpr([&] { return u(rng); });
}

/// Every registered solid material × sample.
class SolidFd : public ::testing::TestWithParam<MaterialCase> {
protected:
  void SetUp() override { m = tunica::test::make_solid(GetParam()); }
  std::unique_ptr<SolidMaterial> m;
};

INSTANTIATE_TEST_SUITE_P(Registry, SolidFd, ::testing::ValuesIn(tunica::test::solid_cases()),
                         tunica::test::case_name);

}  // namespace

TEST_P(SolidFd, MaterialStressAndTangentMatchFiniteDifferencesOfTheEnergy) {
  std::mt19937 rng(11);
  // Errors are relative to the derivative's norm, or to 1e-3 of the modulus where it nearly
  // vanishes (S_iso of a nearly pure dilation is not known to 1e-7 of itself).
  const double floor_iso = 1e-3 * m->isochoric(Eigen::Matrix3d::Identity()).D.norm();
  const double floor_tot = 1e-3 * solid_response(*m, Eigen::Matrix3d::Identity()).D.norm();
  double worst_S = 0, worst_D = 0;
  for (int k = 0; k < 12; ++k) {
    const Eigen::Matrix3d F = random_F(rng);
    const Voigt6 c = to_voigt(F.transpose() * F);
    // Isochoric part alone.
    const IsochoricResponse iso = m->isochoric(C_of(c));
    const auto Wiso = [&](const Eigen::VectorXd& v) { return m->isochoric(C_of(v)).W; };
    const auto Siso = [&](const Eigen::VectorXd& v) -> Eigen::VectorXd { return m->isochoric(C_of(v)).S; };
    const double eS = relative_error(iso.S, S_from_fd(fd_gradient(Wiso, c, 1e-6)), floor_iso);
    const double eD = relative_error(iso.D, D_from_fd(fd_jacobian(Siso, c, 1e-6)), floor_iso);
    // Total W = W_iso + U(J).
    const SolidResponse tot = solid_response(*m, C_of(c));
    const auto W = [&](const Eigen::VectorXd& v) { return solid_response(*m, C_of(v)).W; };
    const auto S = [&](const Eigen::VectorXd& v) -> Eigen::VectorXd { return solid_response(*m, C_of(v)).S; };
    const double tS = relative_error(tot.S, S_from_fd(fd_gradient(W, c, 1e-6)), floor_tot);
    const double tD = relative_error(tot.D, D_from_fd(fd_jacobian(S, c, 1e-6)), floor_tot);
    EXPECT_LT(eS, kFdTolerance) << "state " << k;
    EXPECT_LT(eD, kFdTolerance) << "state " << k;
    EXPECT_LT(tS, kFdTolerance) << "state " << k;
    EXPECT_LT(tD, kFdTolerance) << "state " << k;
    EXPECT_LT((tot.D - tot.D.transpose()).norm(), 1e-12 * tot.D.norm());
    worst_S = std::max({worst_S, eS, tS});
    worst_D = std::max({worst_D, eD, tD});
  }
  tunica::test::record_error("worst_relative_error_stress", worst_S);
  tunica::test::record_error("worst_relative_error_tangent", worst_D);
}

TEST_P(SolidFd, VolumetricDerivativesAndAStressFreeReference) {
  const double kappa = m->volumetric(1.0).d2U;  // the small-strain bulk modulus
  EXPECT_GT(kappa, 0.0);
  for (double J : {0.3, 0.6, 0.9, 1.0, 1.4, 2.5}) {
    const double h = 1e-6;
    const VolumetricResponse v = m->volumetric(J);
    const double scale = kappa * (1 + 1 / (J * J));
    EXPECT_NEAR(v.dU, (m->volumetric(J + h).U - m->volumetric(J - h).U) / (2 * h), 1e-8 * scale) << "J = " << J;
    EXPECT_NEAR(v.d2U, (m->volumetric(J + h).dU - m->volumetric(J - h).dU) / (2 * h), 1e-8 * scale) << "J = " << J;
  }
  const VolumetricResponse one = m->volumetric(1.0);
  EXPECT_EQ(one.U, 0.0);
  EXPECT_EQ(one.dU, 0.0);
  const SolidResponse r = solid_response(*m, Eigen::Matrix3d::Identity());
  EXPECT_EQ(r.W, 0.0);
  EXPECT_LT(r.S.norm(), 1e-15 * r.D.norm());
  EXPECT_LT((r.D - r.D.transpose()).norm(), 1e-15 * r.D.norm());
  // Small-strain elasticity: 𝒞 is positive definite at C = I.
  EXPECT_GT(Eigen::SelfAdjointEigenSolver<Voigt66>(r.D).eigenvalues().minCoeff(), 0.0);
}

TEST(SolidMaterial, NeoHookeanSmallStrainModuli) {
  const auto m = solid_from_yaml("{type: neo_hookean_solid, mu: 0.5, kappa: 0.7246}");
  const VolumetricResponse one = m->volumetric(1.0);
  EXPECT_EQ(one.U, 0.0);
  EXPECT_EQ(one.dU, 0.0);
  EXPECT_DOUBLE_EQ(one.d2U, 0.7246);
  // At C = I: S = 0 and 𝒞 = λ I⊗I + 2μ 𝕀 with λ = κ − 2μ/3 (small-strain isotropic elasticity).
  const SolidResponse r = solid_response(*m, Eigen::Matrix3d::Identity());
  EXPECT_LT(r.S.norm(), 1e-15);
  const Voigt6 id = to_voigt(Eigen::Matrix3d::Identity());
  const Voigt66 lin = (0.7246 - 2.0 * 0.5 / 3.0) * id * id.transpose() + 2.0 * 0.5 * voigt_odot(Eigen::Matrix3d::Identity());
  EXPECT_LT((r.D - lin).norm(), 1e-14);
}

TEST(SolidMaterial, RegistryDeclaresParameters) {
  ASSERT_EQ(solid_material_types().count("neo_hookean_solid"), 1u);
  const auto& spec = solid_material_types().at("neo_hookean_solid").spec;
  EXPECT_EQ(spec.section, "materials");
  ASSERT_EQ(spec.params.size(), 2u);
  EXPECT_EQ(spec.params[0].name, "mu");
  EXPECT_EQ(spec.params[1].name, "kappa");
  EXPECT_THROW(solid_from_yaml("{type: neo_hookean_solid, mu: 0.5, kappa: 0}"), std::exception);
  EXPECT_THROW(solid_from_yaml("{type: neo_hookean_solid, mu: 0.5}"), std::exception);
}

TEST_P(SolidFd, ElementInternalForceIsTheGradientOfTheElementEnergy) {
  std::mt19937 rng(21);
  double worst = 0;
  for (SolidFormulation form : kForms) {
    for (int k = 0; k < 10; ++k) {
      SolidNodes X, x;
      random_state(rng, X, x);
      SolidVector f;
      axisym_solid(X, x, *m, form, f, nullptr);
      const auto energy = [&](const Eigen::VectorXd& v) {
        SolidVector g;
        return axisym_solid(X, unflat(v), *m, form, g, nullptr);
      };
      const double e = relative_error(f, fd_gradient(energy, flat(x), 1e-6));
      EXPECT_LT(e, kFdTolerance) << name(form) << " state " << k;
      worst = std::max(worst, e);
      // Σ W·weight reproduces the element energy.
      std::array<SolidPoint, 4> pts;
      const double Pi = axisym_solid(X, x, *m, form, f, nullptr, &pts);
      double sum = 0;
      for (const auto& p : pts) sum += p.W * p.weight;
      EXPECT_NEAR(sum, Pi, 1e-12 * std::abs(Pi));
    }
  }
  tunica::test::record_error("worst_relative_error", worst);
}

TEST_P(SolidFd, ElementTangentIsTheSymmetricHessianOfTheElementEnergy) {
  std::mt19937 rng(22);
  double worst = 0;
  for (SolidFormulation form : kForms) {
    for (int k = 0; k < 10; ++k) {
      SolidNodes X, x;
      random_state(rng, X, x);
      SolidVector f;
      SolidMatrix K;
      axisym_solid(X, x, *m, form, f, &K);
      const auto force = [&](const Eigen::VectorXd& v) -> Eigen::VectorXd {
        SolidVector g;
        axisym_solid(X, unflat(v), *m, form, g, nullptr);
        return g;
      };
      const double e = relative_error(K, fd_jacobian(force, flat(x), 1e-6));
      EXPECT_LT(e, kFdTolerance) << name(form) << " state " << k;
      EXPECT_LT((K - K.transpose()).norm(), 1e-12 * K.norm()) << name(form);
      worst = std::max(worst, e);
    }
  }
  tunica::test::record_error("worst_relative_error", worst);
}

TEST_P(SolidFd, ElementHasNoForceInTheReferenceStateNorUnderARigidAxialTranslation) {
  std::mt19937 rng(23);
  // Force scale: modulus × element volume (~2π × 0.3 × 0.4).
  const double scale = solid_response(*m, Eigen::Matrix3d::Identity()).D.norm() * 0.75;
  for (SolidFormulation form : kForms) {
    for (int k = 0; k < 5; ++k) {
      SolidNodes X, x;
      random_state(rng, X, x);
      SolidVector f;
      SolidMatrix K;
      EXPECT_NEAR(axisym_solid(X, X, *m, form, f, &K), 0.0, 1e-14 * scale) << name(form);
      EXPECT_LT(f.norm(), 1e-14 * scale) << name(form);
      SolidNodes y = X;
      y.row(1).array() += 0.37;
      axisym_solid(X, y, *m, form, f, nullptr);
      EXPECT_LT(f.norm(), 1e-14 * scale) << name(form);
      // The translation is a zero-energy mode of the tangent.
      SolidVector t;
      for (int a = 0; a < 4; ++a) t.segment<2>(2 * a) = Eigen::Vector2d(0, 1);
      EXPECT_LT((K * t).norm(), 1e-12 * K.norm()) << name(form);
    }
  }
}

namespace {

/// A patch of nr × nz distorted quads, R ∈ [0.5, 2], Z ∈ [0, 1]: node (i, j) at index j (nr+1) + i.
struct Patch {
  int nr, nz;
  std::vector<Eigen::Vector2d> nodes;
  std::vector<std::array<int, 4>> elements;
  bool interior(int n) const {
    const int i = n % (nr + 1), j = n / (nr + 1);
    return i > 0 && i < nr && j > 0 && j < nz;
  }
};

Patch distorted_patch(int nr, int nz) {
  Patch p{nr, nz, {}, {}};
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int j = 0; j <= nz; ++j)
    for (int i = 0; i <= nr; ++i) {
      Eigen::Vector2d X(0.5 + 1.5 * i / nr, 1.0 * j / nz);
      const bool inner = i > 0 && i < nr && j > 0 && j < nz;
      if (inner) X += Eigen::Vector2d(0.3 * 1.5 / nr * u(rng), 0.3 / nz * u(rng));
      p.nodes.push_back(X);
    }
  for (int j = 0; j < nz; ++j)
    for (int i = 0; i < nr; ++i) {
      const int a = j * (nr + 1) + i;
      p.elements.push_back({a, a + 1, a + nr + 2, a + nr + 1});
    }
  return p;
}

/// Cauchy stress of the compressible neo-Hookean solid in the homogeneous state
/// F = diag(λ_r, λ_z, λ_θ = λ_r), by hand: J = λ_r² λ_z, b = F Fᵀ = diag(λ_r², λ_z², λ_r²),
/// σ = J⁻¹ F S Fᵀ = μ J^(−5/3) (b − (tr b/3) I) + U'(J) I,  U'(J) = (κ/2)(J − 1/J).
Eigen::Vector4d homogeneous_sigma(double mu, double kappa, double lr, double lz) {
  const double J = lr * lr * lz;
  const double I1 = 2 * lr * lr + lz * lz;
  const double p = 0.5 * kappa * (J - 1 / J);
  const double c = mu * std::pow(J, -5.0 / 3.0);
  return Eigen::Vector4d(c * (lr * lr - I1 / 3) + p, c * (lz * lz - I1 / 3) + p, c * (lr * lr - I1 / 3) + p, 0.0);
}

}  // namespace

TEST(AxisymSolid, PatchTestAndHomogeneousStressAgainstTheClosedForm) {
  const double mu = 0.3, kappa = 30;
  const auto m = solid_from_yaml("{type: neo_hookean_solid, mu: 0.3, kappa: 30}");
  const Patch patch = distorted_patch(4, 3);
  for (SolidFormulation form : kForms) {
    for (const auto& [lr, lz] : {std::pair{1.2, 0.9}, std::pair{0.85, 1.3}, std::pair{1.05, 1.05}}) {
      const Eigen::Vector4d expected = homogeneous_sigma(mu, kappa, lr, lz);
      std::vector<Eigen::Vector2d> F(patch.nodes.size(), Eigen::Vector2d::Zero());
      double fscale = 0, worst_sigma = 0;
      for (const auto& e : patch.elements) {
        SolidNodes X, x;
        for (int a = 0; a < 4; ++a) {
          X.col(a) = patch.nodes[e[a]];
          x.col(a) = Eigen::Vector2d(lr * X(0, a), lz * X(1, a));
        }
        SolidVector f;
        std::array<SolidPoint, 4> pts;
        axisym_solid(X, x, *m, form, f, nullptr, &pts);
        for (int a = 0; a < 4; ++a) F[e[a]] += f.segment<2>(2 * a);
        fscale = std::max(fscale, f.cwiseAbs().maxCoeff());
        for (const auto& p : pts) {
          worst_sigma = std::max(worst_sigma, (p.sigma - expected).norm() / expected.norm());
          EXPECT_NEAR(p.J, lr * lr * lz, 1e-13);
          EXPECT_NEAR(p.p, (p.sigma(0) + p.sigma(1) + p.sigma(2)) / 3, 1e-12 * expected.norm());
        }
      }
      EXPECT_LT(worst_sigma, 1e-12) << name(form) << " λr=" << lr << " λz=" << lz;
      double worst_interior = 0;
      for (std::size_t n = 0; n < F.size(); ++n)
        if (patch.interior(static_cast<int>(n))) worst_interior = std::max(worst_interior, F[n].norm());
      EXPECT_LT(worst_interior, 1e-12 * fscale) << name(form) << " λr=" << lr << " λz=" << lz;
    }
  }
}
