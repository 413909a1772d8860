// Checks of the Holzapfel–Gasser–Ogden and Ogden materials beyond those every registered
// material gets (test_material_derivatives.cpp runs the finite-difference checks of W, S and D
// over every sample of the registry):
//  - HGO: the derivatives of W(C11, C22, C12, C33) by central differences with both fibre
//    families in tension, exactly one, and neither, for every HGO sample of the registry;
//    a family in compression contributes nothing; closed-form stresses;
//  - Ogden at equal and nearly equal in-plane eigenvalues (the spectral divided difference and
//    its Taylor limit) and across the switch between them, for every Ogden sample;
//  - equivalences with neo-Hookean and Mooney–Rivlin, and closed-form stresses;
//  - both in the balloon example (a sphere: equal in-plane stretches everywhere)
//    against the closed-form pressure–stretch curve p = 2 (H/R) σ(λ)/λ³.
#include <limits>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <random>

#include "../support/capture.hpp"
#include "../support/fd.hpp"
#include "../support/material_registry.hpp"
#include "materials/hgo.hpp"
#include "materials/membrane_material.hpp"
#include "materials/ogden.hpp"

using namespace tunica;
using tunica::test::fd_gradient;
using tunica::test::fd_jacobian;
using tunica::test::material_from_yaml;
using tunica::test::relative_error;

namespace {

/// The registry's samples of a material type: (label, deck text).
std::vector<std::pair<std::string, std::string>> samples(const std::string& type) {
  std::vector<std::pair<std::string, std::string>> out;
  for (const MaterialSample& s : material_types().at(type).samples)
    out.emplace_back(type + " " + s.name, tunica::test::sample_yaml(type, s));
  return out;
}

// Ogden's classical rubber constants, for the closed forms below.
const std::string kOgden3 = "{type: ogden, mu: [0.63 MPa, 0.0012 MPa, -0.01 MPa], alpha: [1.3, 5.0, -2.0]}";

/// Random in-plane C = FᵀF with stretches in [0.7, 1.5] and shear (as in test_material_derivatives).
Eigen::Vector3d random_C(std::mt19937& rng) {
  std::uniform_real_distribution<double> s(0.7, 1.5), g(-0.3, 0.3);
  Eigen::Matrix2d F;
  F << s(rng), g(rng), g(rng), s(rng);
  const Eigen::Matrix2d C = F.transpose() * F;
  return Eigen::Vector3d(C(0, 0), C(1, 1), C(0, 1));
}

/// A general state v = (C11, C22, C12, C33): sheared, C33 not tied to det C.
Eigen::Vector4d random_v(std::mt19937& rng) {
  const Eigen::Vector3d C = random_C(rng);
  return Eigen::Vector4d(C(0), C(1), C(2), std::uniform_real_distribution<double>(0.5, 2.0)(rng));
}

const HgoMaterial& as_hgo(const MembraneMaterial& m) { return dynamic_cast<const HgoMaterial&>(m); }

/// Number of HGO fibre families in tension at v; -1 if one is within `margin` of the
/// tension switch I* = 1 (where a central difference would straddle the kink).
int fibres_in_tension(const MembraneMaterial& m, const Eigen::Vector4d& v, double margin = 1e-3) {
  int n = 0;
  for (int i = 0; i < 2; ++i) {
    const double e = as_hgo(m).fibre_invariant(i, v) - 1.0;
    if (std::abs(e) < margin) return -1;
    n += e > 0;
  }
  return n;
}

/// Largest relative errors seen (of dW and d2W, or of S and D), printed for the record.
struct MaxError {
  double dW = 0, d2W = 0;
  void print(const std::string& label) const {
    std::printf("[ fd error ] %-48s first %.2e  second %.2e\n", label.c_str(), dW, d2W);
  }
};

/// dW against central differences of W and d2W against central differences of dW at v.
void check_energy_derivatives(const MembraneMaterial& m, const Eigen::Vector4d& v, const std::string& label,
                              MaxError& max, double h = 1e-6, double tol = 1e-6) {
  const EnergyDerivatives e = m.energy(v);
  const auto W = [&](const Eigen::VectorXd& x) { return m.energy(x).W; };
  const auto dW = [&](const Eigen::VectorXd& x) -> Eigen::VectorXd { return m.energy(x).dW; };
  const double e1 = relative_error(e.dW, fd_gradient(W, v, h), 1e-8);
  const double e2 = relative_error(e.d2W, fd_jacobian(dW, v, h), 1e-8);
  EXPECT_LT(e1, tol) << label << " at v = " << v.transpose();
  EXPECT_LT(e2, tol) << label << " at v = " << v.transpose();
  EXPECT_LT(relative_error(e.d2W, e.d2W.transpose(), 1e-8), 1e-14) << label << ": Hessian must be symmetric";
  max.dW = std::max(max.dW, e1);
  max.d2W = std::max(max.d2W, e2);
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// HGO

TEST(HgoDerivatives, EnergyGradientAndHessianMatchFiniteDifferences) {
  std::mt19937 rng(11);
  ASSERT_FALSE(samples("hgo").empty());
  for (const auto& [label, yaml] : samples("hgo")) {
    const auto m = material_from_yaml(yaml);
    // Both families in tension, exactly one, and neither (ground matrix alone).
    for (int wanted : {2, 1, 0}) {
      const std::string what = std::string(label) + ", fibres in tension: " + std::to_string(wanted);
      MaxError max;
      int found = 0;
      for (int tries = 0; found < 20 && tries < 100000; ++tries) {
        const Eigen::Vector4d v = random_v(rng);
        if (fibres_in_tension(*m, v) != wanted) continue;
        ++found;
        check_energy_derivatives(*m, v, what, max);
      }
      EXPECT_EQ(found, 20) << what << ": not enough random states of this kind";
      max.print(what);
    }
  }
}

TEST(HgoDerivatives, OneFamilyInCompressionContributesNothing) {
  // β = 45 deg, stretch along +β and shortening along −β: I4_1 > 1 > I4_2 (κ = 0).
  const auto m = material_from_yaml("{type: hgo, mu: 3 kPa, k1: 2.3632 kPa, k2: 0.8393, beta: 45 deg}");
  const auto k1_zero = material_from_yaml("{type: hgo, mu: 3 kPa, k1: 0, k2: 0.8393, beta: 45 deg}");
  const Eigen::Vector4d v(1.0, 1.0, 0.3, 1.0 / 0.91);  // I4_{1,2} = 1 ± 0.3
  EXPECT_NEAR(as_hgo(*m).fibre_invariant(0, v), 1.3, 1e-14);
  EXPECT_NEAR(as_hgo(*m).fibre_invariant(1, v), 0.7, 1e-14);
  // Only family 1 acts: Ψ(I*) = k1/(2k2)(exp(k2 e²) − 1), e = 0.3, gradient along a_1 = (½, ½, 1, 0).
  const double k1 = 2.3632e-3, k2 = 0.8393, e = 0.3, x = std::exp(k2 * e * e);
  const EnergyDerivatives full = m->energy(v), ground = k1_zero->energy(v);
  const Eigen::Vector4d a(0.5, 0.5, 1.0, 0.0);
  EXPECT_NEAR(full.W - ground.W, 0.5 * k1 / k2 * (x - 1.0), 1e-16);
  EXPECT_LT((full.dW - ground.dW - k1 * e * x * a).norm(), 1e-16);
  EXPECT_LT((full.d2W - k1 * (1 + 2 * k2 * e * e) * x * a * a.transpose()).norm(), 1e-16);
}

TEST(HgoDerivatives, WithoutFibreStiffnessItIsNeoHookean) {
  std::mt19937 rng(13);
  const auto hgo = material_from_yaml("{type: hgo, mu: 0.3, k1: 0, k2: 0.8393, beta: 29 deg, kappa: 0.1}");
  const auto nh = material_from_yaml("{type: neo_hookean, mu: 0.3}");
  for (int k = 0; k < 20; ++k) {
    const Eigen::Vector4d v = random_v(rng);
    const EnergyDerivatives a = hgo->energy(v), b = nh->energy(v);
    EXPECT_NEAR(a.W, b.W, 1e-15);
    EXPECT_LT((a.dW - b.dW).norm(), 1e-15);
    EXPECT_LT(a.d2W.norm(), 1e-15);
    EXPECT_LT(b.d2W.norm(), 1e-15);
  }
}

TEST(HgoDerivatives, UniaxialStrainStressMatchesTheClosedForm) {
  // β = 0, κ = 0: both families along direction 1, I4 = C11 = λ1². With C33 = 1/(λ1²λ2²):
  //   S11 = 2 ∂W/∂C11 − 2 C33 ∂W/∂C33 / C11 = μ (1 − 1/(λ1⁴λ2²)) + 4 k1 (λ1² − 1) exp(k2 (λ1² − 1)²),
  //   S22 = μ (1 − 1/(λ1²λ2⁴)),  S12 = 0.
  const double mu = 3e-3, k1 = 2.3632e-3, k2 = 0.8393, l1 = 1.2, l2 = 1.0;
  const auto m = material_from_yaml("{type: hgo, mu: 3 kPa, k1: 2.3632 kPa, k2: 0.8393, beta: 0}");
  const MembraneResponse r = membrane_response(*m, Eigen::Vector3d(l1 * l1, l2 * l2, 0));
  const double e = l1 * l1 - 1.0;
  const double S11 = mu * (1 - 1 / (std::pow(l1, 4) * l2 * l2)) + 4 * k1 * e * std::exp(k2 * e * e);
  // By hand: μ(1 − 1/2.0736) + 4 k1 (0.44) exp(0.8393·0.1936) = 0.00155324 + 0.00489307 (MPa).
  EXPECT_NEAR(S11, 6.44631e-3, 1e-8);
  EXPECT_NEAR(r.S(0), S11, 1e-15);
  EXPECT_NEAR(r.S(1), mu * (1 - 1 / (l1 * l1 * std::pow(l2, 4))), 1e-15);
  EXPECT_NEAR(r.S(2), 0.0, 1e-18);
}

TEST(HgoDerivatives, EquibiaxialStressWithDispersionMatchesTheClosedForm) {
  // C = diag(λ², λ², λ⁻⁴): I4_1 = I4_2 = λ², I* = κ(2λ² + λ⁻⁴) + (1 − 3κ)λ², Ψ' = k1 (I* − 1) exp(k2 (I* − 1)²),
  //   S11 = μ + 4Ψ'(κ + (1 − 3κ) cos²β) − (C33/C11)(μ + 4Ψ'κ), S22 likewise with sin²β.
  const double mu = 3e-3, k1 = 2.3632e-3, k2 = 0.8393, kappa = 0.2, beta = 39.98 * std::numbers::pi / 180;
  const auto m = material_from_yaml("{type: hgo, mu: 3 kPa, k1: 2.3632 kPa, k2: 0.8393, beta: 39.98 deg, kappa: 0.2}");
  for (double l : {1.1, 1.2, 1.35}) {
    const double C = l * l, C33 = 1 / (C * C);
    const double I = kappa * (2 * C + C33) + (1 - 3 * kappa) * C;
    ASSERT_GT(I, 1.0);
    const double dPsi = k1 * (I - 1) * std::exp(k2 * (I - 1) * (I - 1));
    const double c2 = std::cos(beta) * std::cos(beta), s2 = std::sin(beta) * std::sin(beta);
    const MembraneResponse r = membrane_response(*m, Eigen::Vector3d(C, C, 0));
    EXPECT_NEAR(r.S(0), mu + 4 * dPsi * (kappa + (1 - 3 * kappa) * c2) - C33 / C * (mu + 4 * dPsi * kappa), 1e-15);
    EXPECT_NEAR(r.S(1), mu + 4 * dPsi * (kappa + (1 - 3 * kappa) * s2) - C33 / C * (mu + 4 * dPsi * kappa), 1e-15);
    EXPECT_NEAR(r.S(2), 0.0, 1e-18);
  }
}

// ---------------------------------------------------------------------------------------------
// Ogden

TEST(OgdenDerivatives, EqualAndNearlyEqualInPlaneStretches) {
  // Equal eigenvalues: C11 = C22, C12 = 0 (undeformed, equibiaxial, sphere), then gaps of 1e-9 and 1e-6,
  // in C11 − C22 and in C12. W is analytic in v there; with h = 1e-6 the central differences are
  // accurate to ~1e-10, so the tolerance (1e-8) is tighter than for the random states.
  ASSERT_FALSE(samples("ogden").empty());
  for (const auto& [label, yaml] : samples("ogden")) {
    const auto m = material_from_yaml(yaml);
    const auto& og = dynamic_cast<const OgdenMaterial&>(*m);
    MaxError max;
    for (double c : {1.0, 0.81, 1.44, 2.25}) {
      const Eigen::Vector4d equal(c, c, 0.0, 1.0 / (c * c));
      // At C = c I the Hessian of the in-plane part is g''(c) diag(1, 1, 2) (exact).
      const EnergyDerivatives e0 = m->energy(equal);
      Eigen::Matrix3d exact = Eigen::Vector3d(1, 1, 2).asDiagonal();
      exact *= og.g(2, c);
      EXPECT_LT(relative_error(e0.d2W.topLeftCorner<3, 3>(), exact, 1e-12), 1e-14) << label;
      EXPECT_NEAR(e0.dW(0), og.g(1, c), 1e-15);
      EXPECT_NEAR(e0.dW(1), og.g(1, c), 1e-15);
      EXPECT_EQ(e0.dW(2), 0.0);
      for (const Eigen::Vector4d& gap : {Eigen::Vector4d(0, 0, 0, 0), Eigen::Vector4d(1e-9, 0, 0, 0),
                                         Eigen::Vector4d(1e-6, 0, 0, 0), Eigen::Vector4d(0, 0, 1e-9, 0),
                                         Eigen::Vector4d(0, 0, 1e-6, 0), Eigen::Vector4d(0, 1e-6, 1e-6, 0)}) {
        const Eigen::Vector4d v = equal + gap;
        check_energy_derivatives(*m, v, label + std::string(" near equal"), max, 1e-6, 1e-8);
        // Continuity: the derivatives move by O(gap) from those at equal eigenvalues.
        const EnergyDerivatives e = m->energy(v);
        EXPECT_LE((e.dW - e0.dW).norm(), 10 * gap.norm() * (1 + e0.d2W.norm())) << label;
        EXPECT_LE((e.d2W - e0.d2W).norm(), 1e3 * gap.norm() * (1 + e0.d2W.norm())) << label;
      }
    }
    max.print(std::string(label) + " near equal eigenvalues");
  }
}

TEST(OgdenDerivatives, ContinuousAcrossTheSwitchToTheTaylorLimit) {
  // Just below and just above the relative gap where the divided difference (g'(c1) − g'(c2))/(c1 − c2)
  // takes over from its Taylor series: the Hessians agree to rounding, and with a central difference.
  const double gap = OgdenMaterial::kEqualEigenvalueGap;
  double jump = 0;
  for (const auto& [label, yaml] : samples("ogden")) {
    const auto m = material_from_yaml(yaml);
    for (double mean : {0.9, 1.0, 1.7}) {
      for (double shear_share : {0.0, 0.6, 1.0}) {
        // r = √(d² + C12²) = gap · m · rel, split between C11 − C22 and C12.
        const auto at = [&](double rel) {
          const double r = gap * mean * rel;
          const double d = r * std::sqrt(1 - shear_share * shear_share), c12 = r * shear_share;
          return Eigen::Vector4d(mean + d, mean - d, c12, 1.1);
        };
        // Relative distance 1e-10 from the switch: W's own variation between the two is ~1e-13.
        const Eigen::Vector4d vb = at(1 - 1e-10), va = at(1 + 1e-10);
        const auto side = [&](const Eigen::Vector4d& v) {  // the material's own test, r > gap m
          return std::hypot(0.5 * (v(0) - v(1)), v(2)) > gap * 0.5 * (v(0) + v(1));
        };
        ASSERT_FALSE(side(vb));
        ASSERT_TRUE(side(va));
        const EnergyDerivatives below = m->energy(vb), above = m->energy(va);
        EXPECT_LT(relative_error(below.d2W, above.d2W), 5e-12) << "mean " << mean << " shear " << shear_share;
        EXPECT_LT(relative_error(below.dW, above.dW), 5e-12);
        jump = std::max(jump, relative_error(below.d2W, above.d2W));
        MaxError max;
        check_energy_derivatives(*m, at(1.0), label + " at the switch", max, 1e-6, 1e-8);
      }
    }
  }
  std::printf("[ switch   ] largest relative jump of d2W across the Taylor switch: %.2e\n", jump);
}

TEST(OgdenDerivatives, OneTermWithAlphaTwoIsNeoHookean) {
  // μ/2 (λ1² + λ2² + λ3² − 3) = μ/2 (I1 − 3) as a function of all four components of v.
  std::mt19937 rng(23);
  const auto og = material_from_yaml("{type: ogden, mu: [0.3], alpha: [2]}");
  const auto nh = material_from_yaml("{type: neo_hookean, mu: 0.3}");
  for (int k = 0; k < 20; ++k) {
    const Eigen::Vector4d v = k == 0 ? Eigen::Vector4d(1, 1, 0, 1) : random_v(rng);
    const EnergyDerivatives a = og->energy(v), b = nh->energy(v);
    EXPECT_NEAR(a.W, b.W, 1e-15);
    EXPECT_LT((a.dW - b.dW).norm(), 1e-15);
    EXPECT_LT((a.d2W - b.d2W).norm(), 1e-15);
  }
}

TEST(OgdenDerivatives, AlphaTwoAndMinusTwoIsMooneyRivlin) {
  // μ1/2 (I1 − 3) − μ2/2 (Σ λ_i⁻² − 3), and Σ λ_i⁻² = I2/I3 = I2 on det C = 1: Mooney–Rivlin with
  // b1 = μ1/2, b2 = −μ2/2. The two differ as functions of four independent components (I3 ≠ 1),
  // so the reduced membrane responses are compared: W, S and D at C33 = 1/det C.
  std::mt19937 rng(24);
  const double b1 = 0.2, b2 = 0.05;
  const auto og = material_from_yaml("{type: ogden, mu: [0.4, -0.1], alpha: [2, -2]}");
  const auto mr = material_from_yaml("{type: mooney_rivlin, b1: 0.2, b2: 0.05}");
  (void)b1;  // mu = (2 b1, −2 b2) = (0.4, −0.1)
  (void)b2;
  for (int k = 0; k < 20; ++k) {
    const Eigen::Vector3d C = k == 0 ? Eigen::Vector3d(1, 1, 0) : random_C(rng);
    const MembraneResponse a = membrane_response(*og, C), b = membrane_response(*mr, C);
    EXPECT_NEAR(a.W, b.W, 1e-14);
    EXPECT_LT((a.S - b.S).norm(), 1e-14);
    EXPECT_LT((a.D - b.D).norm(), 1e-13);
  }
}

TEST(OgdenDerivatives, EquibiaxialStressMatchesTheClosedForm) {
  // Equibiaxial stretch λ, λ3 = λ⁻²: Cauchy σ = Σ_p μ_p (λ^α_p − λ^(−2α_p)), S = σ/λ² (the sphere).
  const std::vector<double> mu = {0.63, 0.0012, -0.01}, alpha = {1.3, 5.0, -2.0};
  const auto m = material_from_yaml(kOgden3);
  for (double l : {0.9, 1.0, 1.2, 1.5, 2.5}) {
    double sigma = 0;
    for (int p = 0; p < 3; ++p) sigma += mu[p] * (std::pow(l, alpha[p]) - std::pow(l, -2 * alpha[p]));
    const MembraneResponse r = membrane_response(*m, Eigen::Vector3d(l * l, l * l, 0));
    EXPECT_NEAR(r.S(0), sigma / (l * l), 1e-14 * (1 + std::abs(sigma)));
    EXPECT_NEAR(r.S(1), sigma / (l * l), 1e-14 * (1 + std::abs(sigma)));
    EXPECT_NEAR(r.S(2), 0.0, 1e-16);
  }
}

// ---------------------------------------------------------------------------------------------
// Both

TEST(HgoOgden, StressFreeReferenceStateWithTheIncompressibleSmallStrainTangent) {
  // At C = I: S = 0 and, for Ogden, D = μ0 [[4, 2, 0], [2, 4, 0], [0, 0, 1]] (plane stress, ν = ½),
  // μ0 = ½ Σ μ_p α_p. HGO's fibres are on their kink there (I* = 1), theory manual (3.5a).
  const std::vector<std::pair<std::string, double>> cases = {
      {"{type: ogden, mu: [0.5 MPa], alpha: [3.2]}", 0.5 * 0.5 * 3.2},
      {kOgden3, 0.5 * (0.63 * 1.3 + 0.0012 * 5 + 0.02)}};
  for (const auto& [yaml, mu0] : cases) {
    const auto m = material_from_yaml(yaml);
    const MembraneResponse r = membrane_response(*m, Eigen::Vector3d(1, 1, 0));
    EXPECT_LT(r.S.norm(), 1e-16 * (1 + mu0)) << yaml;
    Eigen::Matrix3d D;
    D << 4, 2, 0, 2, 4, 0, 0, 0, 1;
    EXPECT_LT(relative_error(r.D, mu0 * D), 1e-14) << yaml;
    EXPECT_NEAR(m->energy(Eigen::Vector4d(1, 1, 0, 1)).W, 0.0, 1e-15) << yaml;
  }
}

TEST(HgoOgden, OnTheFibreKinkTheTangentIsTheMeanOfTheTautAndSlackSidesAtEveryPointAlike) {
  // (3.5a): at C = I, and at C = I to within round-off of either sign (as Gauss points of a mesh at
  // rest compute it), D is the mean of the one-sided tangents: the slack side (equibiaxial
  // shrinking, I* < 1) and the taut side (equibiaxial stretching, I* > 1), S = 0.
  for (const char* yaml : {"{type: hgo, mu: 3 kPa, k1: 2.3632 kPa, k2: 0.8393, beta: 29 deg}",
                           "{type: hgo, mu: 3 kPa, k1: 2.3632 kPa, k2: 0.8393, beta: 29 deg, kappa: 0.2}"}) {
    const auto m = material_from_yaml(yaml);
    const MembraneResponse at = membrane_response(*m, Eigen::Vector3d(1, 1, 0));
    const double d = 1e-9;
    const MembraneResponse taut = membrane_response(*m, Eigen::Vector3d(1 + d, 1 + d, 0));
    const MembraneResponse slack = membrane_response(*m, Eigen::Vector3d(1 - d, 1 - d, 0));
    EXPECT_LT(at.S.norm(), 1e-16) << yaml;
    EXPECT_GT(relative_error(taut.D, slack.D), 0.05) << yaml;  // the kink is there
    EXPECT_LT(relative_error(at.D, 0.5 * (taut.D + slack.D)), 1e-7) << yaml;
    const double ulp = std::numeric_limits<double>::epsilon();
    for (const Eigen::Vector3d& c : {Eigen::Vector3d(1 + 2 * ulp, 1, 0), Eigen::Vector3d(1 - 2 * ulp, 1 - ulp, 0),
                                     Eigen::Vector3d(1, 1 + ulp, ulp)}) {
      const MembraneResponse r = membrane_response(*m, c);
      EXPECT_LT(relative_error(r.D, at.D), 1e-14) << yaml << " at C = " << c.transpose();
    }
  }
}

namespace {

/// Runs the balloon example (R = 1 mm, H = 0.01 mm) with 40 elements, `material` and final pressure `p_end`;
/// largest relative error of the FE pressure against p(λ) = 2 (H/R) σ(λ)/λ³, λ the equator stretch.
double sphere_error(const std::string& material, const std::string& p_end, const std::function<double(double)>& sigma) {
  const std::string path = std::string(TUNICA_SOURCE_DIR) + "/examples/balloon-sphere.yaml";
  std::string deck = tunica::test::replace(tunica::test::read_text(path), "{type: neo_hookean, mu: 1 MPa}", material);
  deck = tunica::test::replace(deck, "elements: 100}", "elements: 40}");
  deck = tunica::test::replace(deck, "{inflation: 0.0118 MPa}", "{inflation: " + p_end + "}");
  const Model m = read_deck_text(deck, path);
  tunica::test::Capture c;
  Analysis a(m);
  a.run(c);
  EXPECT_EQ(c.cutbacks, 0);
  const int p = tunica::test::Capture::column(m, "pressure_kPa"), r = tunica::test::Capture::column(m, "equator_radius_mm");
  double err = 0;
  for (const auto& row : c.rows) {
    if (row.info.step == 0) continue;
    const double l = row.values[r];
    const double exact = 2 * 0.01 * sigma(l) / (l * l * l) * 1e3;  // MPa → kPa
    err = std::max(err, std::abs(row.values[p] - exact) / exact);
  }
  EXPECT_GT(c.rows.size(), 10u);
  return err;
}

}  // namespace

TEST(HgoOgden, SphericalBalloonMatchesTheClosedForm) {
  // Ogden rubber: σ = Σ μ_p (λ^α_p − λ^(−2α_p)); p peaks at λ ≈ 1.374 (0.005494 MPa), load to 0.005 MPa.
  const double og = sphere_error("{type: ogden, mu: [0.63 MPa, 0.0012 MPa, -0.01 MPa], alpha: [1.3, 5.0, -2.0]}",
                                 "0.005 MPa", [](double l) {
                                   const double mu[3] = {0.63, 0.0012, -0.01}, al[3] = {1.3, 5.0, -2.0};
                                   double s = 0;
                                   for (int k = 0; k < 3; ++k) s += mu[k] * (std::pow(l, al[k]) - std::pow(l, -2 * al[k]));
                                   return s;
                                 });
  // HGO with β = 45 deg (hoop and meridional fibres alike, the sphere stays a sphere): σ = λ² S11 with
  // S11 from the equibiaxial closed form above.
  const double hgo = sphere_error("{type: hgo, mu: 1 MPa, k1: 1 MPa, k2: 1, beta: 45 deg, kappa: 0.1}", "0.03 MPa",
                                  [](double l) {
                                    const double mu = 1, k1 = 1, k2 = 1, kappa = 0.1, C = l * l, C33 = 1 / (C * C);
                                    const double I = kappa * (2 * C + C33) + (1 - 3 * kappa) * C;
                                    const double dPsi = I > 1 ? k1 * (I - 1) * std::exp(k2 * (I - 1) * (I - 1)) : 0.0;
                                    const double S = mu + 4 * dPsi * (kappa + (1 - 3 * kappa) * 0.5) -
                                                     C33 / C * (mu + 4 * dPsi * kappa);
                                    return C * S;
                                  });
  std::printf("sphere, 40 elements, max relative pressure error: ogden %.3e, hgo %.3e\n", og, hgo);
  EXPECT_LT(og, 1e-3);
  EXPECT_LT(hgo, 1e-3);
}
