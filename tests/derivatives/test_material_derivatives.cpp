// Checks of every registered membrane material (theory manual §2.1, §3, §8), over the registry:
// every type × every sample it declares (materials/material_sample.hpp) × its orientations,
// at random, moderately large deformations (stretches 0.8–1.6, shear, the material frame turned
// by the sample's orientation; tests/support/random_deformation.hpp):
//  - the material's own derivatives of W(C11, C22, C12, C33), at general states (C33 not tied
//    to det C), by central differences;
//  - the plane-stress incompressible reduction (2.5)–(2.8): S against the reduced energy
//    Ŵ(C) = W(C, 1/det C), the tangent D against S, D symmetric;
//  - the reference state is stress free; an isotropic material is indifferent to the frame, an
//    anisotropic one is not, and its sample declares orientations that show it;
//  - the registries: every type declares samples, with valid names, that a deck accepts.
// And closed forms of the paper's Fung law and the neo-Hookean balloon.
#include <gtest/gtest.h>

#include <cctype>
#include <random>
#include <set>

#include "../support/fd.hpp"
#include "../support/material_registry.hpp"
#include "../support/random_deformation.hpp"
#include "io/deck.hpp"
#include "materials/fung.hpp"
#include "materials/membrane_material.hpp"

using namespace tunica;
using namespace tunica::test;

namespace {

constexpr double kH = 1e-6;
constexpr double kTol = kFdTolerance;  // tests/support/fd.hpp
// Errors are relative to the derivative's norm, or to this fraction of the material's modulus
// where the derivative nearly vanishes (a stress near zero is not known to 1e-7 of itself).
constexpr double kFloor = 1e-3;
constexpr int kStates = 12;

class MembraneMaterialFd : public ::testing::TestWithParam<MaterialCase> {
protected:
  void SetUp() override { m = make_membrane(GetParam()); }
  std::unique_ptr<MembraneMaterial> m;
};

INSTANTIATE_TEST_SUITE_P(Registry, MembraneMaterialFd, ::testing::ValuesIn(membrane_cases(Orientations::each)),
                         case_name);

/// Properties of a sample that do not depend on an orientation: one case per sample.
class MembraneMaterialSample : public MembraneMaterialFd {};

INSTANTIATE_TEST_SUITE_P(Registry, MembraneMaterialSample, ::testing::ValuesIn(membrane_cases()), case_name);

}  // namespace

TEST_P(MembraneMaterialFd, EnergyGradientAndHessianMatchFiniteDifferences) {
  std::mt19937 rng(1);
  const double floor = kFloor * sample_scale(*m);
  double worst = 0;
  for (int k = 0; k < kStates; ++k) {
    const Eigen::Vector4d v = general_v(C_in_frame(random_F2(rng), GetParam().angle), rng);
    const EnergyDerivatives e = m->energy(v);
    const auto W = [&](const Eigen::VectorXd& x) { return m->energy(x).W; };
    const auto dW = [&](const Eigen::VectorXd& x) -> Eigen::VectorXd { return m->energy(x).dW; };
    const double e1 = relative_error(e.dW, fd_gradient(W, v, kH), floor);
    const double e2 = relative_error(e.d2W, fd_jacobian(dW, v, kH), floor);
    EXPECT_LT(e1, kTol) << "v = " << v.transpose();
    EXPECT_LT(e2, kTol) << "v = " << v.transpose();
    EXPECT_LT(relative_error(e.d2W, e.d2W.transpose(), 1e-12), 1e-14) << "the Hessian must be symmetric";
    worst = std::max({worst, e1, e2});
  }
  tunica::test::record_error("worst_relative_error", worst);
}

TEST_P(MembraneMaterialFd, StressIsTheDerivativeOfTheReducedEnergyAndTangentOfStress) {
  std::mt19937 rng(2);
  const double floor = kFloor * sample_scale(*m);
  double worst = 0;
  for (int k = 0; k < kStates; ++k) {
    const Eigen::Vector3d C = C_in_frame(random_F2(rng), GetParam().angle);
    const MembraneResponse r = membrane_response(*m, C);
    // Ŵ as a function of x = (C11, C22, C12): S = (2 ∂Ŵ/∂x1, 2 ∂Ŵ/∂x2, ∂Ŵ/∂x3), (2.8).
    const auto What = [&](const Eigen::VectorXd& x) { return membrane_response(*m, x).W; };
    const Eigen::VectorXd g = fd_gradient(What, C, kH);
    const double e1 = relative_error(r.S, Eigen::Vector3d(2 * g(0), 2 * g(1), g(2)), floor);
    // D = dS/dE with dE = (dC11/2, dC22/2, dC12) (engineering shear 2 dE12 = dC12).
    const auto S = [&](const Eigen::VectorXd& x) -> Eigen::VectorXd { return membrane_response(*m, x).S; };
    Eigen::MatrixXd J = fd_jacobian(S, C, kH);
    J.col(0) *= 2.0;
    J.col(1) *= 2.0;
    const double e2 = relative_error(r.D, J, floor);
    EXPECT_LT(e1, kTol) << "C = " << C.transpose();
    EXPECT_LT(e2, kTol) << "C = " << C.transpose();
    EXPECT_LT(relative_error(r.D, r.D.transpose(), 1e-12), 1e-12) << "the tangent must be symmetric";
    worst = std::max({worst, e1, e2});
  }
  tunica::test::record_error("worst_relative_error", worst);
}

TEST_P(MembraneMaterialSample, ReferenceStateIsStressFree) {
  const MembraneResponse r = membrane_response(*m, Eigen::Vector3d(1, 1, 0));
  EXPECT_NEAR(r.W, 0.0, 1e-15 * r.D.norm());  // Ogden: Σ g(c_i) − Σ 3μ_p/α_p, to rounding
  EXPECT_LT(r.S.norm(), 1e-15 * r.D.norm());
  EXPECT_EQ(r.C33, 1.0);
  // The small-strain tangent is symmetric positive semidefinite (convex W; the paper's Fung law
  // has no shear stiffness in its two-dimensional approach, a7 = 0) and not zero.
  EXPECT_LT((r.D - r.D.transpose()).norm(), 1e-15 * r.D.norm());
  EXPECT_GT(r.D.norm(), 0.0);
  EXPECT_GE(Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(r.D).eigenvalues().minCoeff(), -1e-15 * r.D.norm());
}

TEST_P(MembraneMaterialSample, TheFrameMattersExactlyWhenTheMaterialIsAnisotropic) {
  // Turning the material frame by θ turns C by θ; an isotropic W sees the same invariants and
  // gives the turned stress and tangent, S(QᵀCQ) = Qᵀ S(C) Q. An anisotropic sample must declare
  // orientations, and the energy must differ between them at some state.
  std::mt19937 rng(3);
  const MaterialSample& sample = sample_of(GetParam());
  ASSERT_FALSE(sample.orientations.empty());
  // W = (μ/2)(I1 − 3) and the like lose digits to cancellation: rounding is relative to the modulus.
  const double scale = sample_scale(*m);
  double largest_change = 0;
  for (int k = 0; k < kStates; ++k) {
    const Eigen::Matrix2d F = random_F2(rng);
    const MembraneResponse a = membrane_response(*m, C_in_frame(F, 0.0));
    for (double angle : {0.3, 1.1, -0.7}) {
      const MembraneResponse b = membrane_response(*m, C_in_frame(F, angle));
      largest_change = std::max(largest_change, std::abs(b.W - a.W) / (std::abs(a.W) + scale));
      if (!m->isotropic()) continue;
      // The stress as a tensor in the turned frame: Qᵀ S Q.
      const Eigen::Matrix2d Q = rotation2(angle);
      Eigen::Matrix2d Sa;
      Sa << a.S(0), a.S(2), a.S(2), a.S(1);
      const Eigen::Matrix2d St = Q.transpose() * Sa * Q;
      EXPECT_NEAR(b.W, a.W, 1e-13 * (std::abs(a.W) + scale));
      EXPECT_LT((Eigen::Vector3d(St(0, 0), St(1, 1), St(0, 1)) - b.S).norm(), 1e-12 * a.S.norm());
      // Two invariants of the tangent 𝒞_ijkl: 𝒞_ijij = D11 + D22 + 2 D33, 𝒞_iijj = D11 + D22 + 2 D12.
      EXPECT_NEAR(b.D(0, 0) + b.D(1, 1) + 2 * b.D(2, 2), a.D(0, 0) + a.D(1, 1) + 2 * a.D(2, 2), 1e-12 * a.D.norm());
      EXPECT_NEAR(b.D(0, 0) + b.D(1, 1) + 2 * b.D(0, 1), a.D(0, 0) + a.D(1, 1) + 2 * a.D(0, 1), 1e-12 * a.D.norm());
    }
  }
  if (m->isotropic()) {
    EXPECT_LT(largest_change, 1e-13);
  } else {
    EXPECT_GT(largest_change, 1e-3) << "an anisotropic material that does not see its frame";
    EXPECT_GE(sample.orientations.size(), 2u) << "an anisotropic sample should declare orientations that exercise it";
  }
}

TEST(MaterialRegistry, EveryTypeDeclaresSamplesThatADeckAccepts) {
  const auto valid_name = [](const std::string& s) {
    if (s.empty()) return false;
    for (char c : s)
      if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) return false;
    return true;
  };
  const auto check = [&](const std::string& type, const std::vector<MaterialSample>& samples, bool solid) {
    EXPECT_FALSE(samples.empty()) << type << " declares no sample: the element tests would not run it";
    std::set<std::string> names;
    for (const MaterialSample& s : samples) {
      EXPECT_TRUE(valid_name(s.name)) << type << ": sample name '" << s.name << "' (letters, digits, _)";
      EXPECT_TRUE(names.insert(s.name).second) << type << ": sample name '" << s.name << "' twice";
      EXPECT_FALSE(s.doc.empty()) << type << " " << s.name;
      EXPECT_FALSE(s.orientations.empty()) << type << " " << s.name;
      const std::string yaml = sample_yaml(type, s);
      if (solid)
        EXPECT_NO_THROW(solid_from_yaml(yaml)) << yaml;
      else
        EXPECT_NO_THROW(material_from_yaml(yaml)) << yaml;
    }
  };
  ASSERT_FALSE(material_types().empty());
  ASSERT_FALSE(solid_material_types().empty());
  for (const auto& [type, t] : material_types()) check(type, t.samples, false);
  for (const auto& [type, t] : solid_material_types()) check(type, t.samples, true);
  // The suites above run every case: one per sample and orientation.
  std::size_t expected = 0;
  for (const auto& [type, t] : material_types())
    for (const MaterialSample& s : t.samples) expected += s.orientations.size();
  EXPECT_EQ(membrane_cases(Orientations::each).size(), expected);
}

TEST(MaterialDerivatives, FungTwoDimensionalApproachMatchesThePaperClosedForms) {
  // Theory manual (3.2): S1 = 2c(a1E1 + a4E2)e^Q, D11 = 2c[a1 + 2(a1E1 + a4E2)²]e^Q, ...
  const double c = 0.061163, a1 = 0.68238, a2 = 0.60558, a4 = 0.1067;
  const auto m = material_from_yaml("{type: fung, c: 0.061163, a1: 0.68238, a2: 0.60558, a4: 0.1067}");
  for (double l1 : {0.87, 1.0, 1.3, 1.69})
    for (double l2 : {1.0, 1.6}) {
      const double E1 = 0.5 * (l1 * l1 - 1), E2 = 0.5 * (l2 * l2 - 1);
      const double eQ = std::exp(a1 * E1 * E1 + a2 * E2 * E2 + 2 * a4 * E1 * E2);
      const double s1 = a1 * E1 + a4 * E2, s2 = a4 * E1 + a2 * E2;
      const MembraneResponse r = membrane_response(*m, Eigen::Vector3d(l1 * l1, l2 * l2, 0));
      EXPECT_NEAR(r.S(0), 2 * c * s1 * eQ, 1e-13);
      EXPECT_NEAR(r.S(1), 2 * c * s2 * eQ, 1e-13);
      EXPECT_NEAR(r.D(0, 0), 2 * c * (a1 + 2 * s1 * s1) * eQ, 1e-12);
      EXPECT_NEAR(r.D(1, 1), 2 * c * (a2 + 2 * s2 * s2) * eQ, 1e-12);
      EXPECT_NEAR(r.D(0, 1), 2 * c * (a4 + 2 * s1 * s2) * eQ, 1e-12);
      EXPECT_NEAR(r.C33, 1.0 / (l1 * l1 * l2 * l2), 1e-15);
    }
}

TEST(MaterialDerivatives, NeoHookeanEquibiaxialStressMatchesClosedForm) {
  // S_α = μ(1 − λ3²/λα²) with λ3 = 1/λ² (equibiaxial): σ = μ(λ² − λ⁻⁴) (theory manual (8.3), the balloon).
  const auto m = material_from_yaml("{type: neo_hookean, mu: 0.3}");
  for (double l : {0.9, 1.2, 1.383, 2.0}) {
    const MembraneResponse r = membrane_response(*m, Eigen::Vector3d(l * l, l * l, 0));
    EXPECT_NEAR(l * l * r.S(0), 0.3 * (l * l - std::pow(l, -4)), 1e-14);
    EXPECT_NEAR(r.S(0), r.S(1), 1e-15);
  }
}

TEST(MaterialDerivatives, FungConvexityCheck) {
  Eigen::Matrix3d A;
  A << 0.68238, 0.1067, 0, 0.1067, 0.60558, 0, 0, 0, 0;
  EXPECT_TRUE(FungMaterial::is_convex(A, 0));
  A(0, 1) = A(1, 0) = 0.7;
  EXPECT_FALSE(FungMaterial::is_convex(A, 0));
  A << 1, 0.2, 0.1, 0.2, 1, 0.1, 0.1, 0.1, -0.5;
  EXPECT_FALSE(FungMaterial::is_convex(A, 0));
  A(2, 2) = 0.5;
  EXPECT_TRUE(FungMaterial::is_convex(A, 0.1));
  EXPECT_FALSE(FungMaterial::is_convex(A, -0.1));
}
