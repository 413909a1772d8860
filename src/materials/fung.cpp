#include "materials/fung.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <utility>

namespace tunica {

FungMaterial::FungMaterial(double c, const Eigen::Matrix3d& A, double a7) : c_(c), A_(A), a7_(a7) {
  // d²Q/dv², constant (Q is quadratic in v): d²Q/dC_ii dC_jj = A_ij/2 (dE_i/dC_ii = ½), d²Q/dv3² = a7/2
  // (a7 E12² = a7 v3²/4), zero elsewhere.
  const int map[3] = {0, 1, 3};  // E1, E2, E3 -> v index
  d2Q_.setZero();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) d2Q_(map[i], map[j]) = 0.5 * A_(i, j);
  d2Q_(2, 2) = 0.5 * a7_;
}

bool FungMaterial::is_convex(const Eigen::Matrix3d& A, double a7) {
  if (a7 < 0) return false;
  const bool two_d = A(2, 2) == 0 && A(1, 2) == 0 && A(0, 2) == 0;
  if (two_d) return A(0, 0) > 0 && A(1, 1) > 0 && A(0, 0) * A(1, 1) - A(0, 1) * A(0, 1) > 0;
  Eigen::LLT<Eigen::Matrix3d> llt(A);
  return llt.info() == Eigen::Success;
}

EnergyDerivatives FungMaterial::energy(const Eigen::Vector4d& v) const {
  // Theory manual (3.1): e = (E1, E2, E3); Q = eᵀ A e + a7 E12², E12 = v(2)/2.
  const Eigen::Vector3d e(0.5 * (v(0) - 1.0), 0.5 * (v(1) - 1.0), 0.5 * (v(3) - 1.0));
  const double e12 = 0.5 * v(2);
  const Eigen::Vector3d Ae = A_ * e;
  const double Q = e.dot(Ae) + a7_ * e12 * e12;
  // dQ/dv: dQ/dC_ii = (A e)_i since dE_i/dC_ii = ½; a7 E12² = a7 v3²/4 gives dQ/dv3 = a7 E12 (d²Q: the constructor).
  const Eigen::Vector4d dQ(Ae(0), Ae(1), a7_ * e12, Ae(2));
  const double eQ = std::exp(Q), ceQ = c_ * eQ;
  // W, dW = c e^Q dQ, d²W = c e^Q (dQ dQᵀ + d²Q).
  return {.W = c_ * (eQ - 1.0), .dW = ceQ * dQ, .d2W = ceQ * (dQ * dQ.transpose() + d2Q_)};
}

namespace {

/// Why the quadratic form of `A` is not positive definite (Sylvester's criterion: the first
/// leading minor of A that is not > 0; in the two-dimensional approach a1, a2 and
/// a1·a2 − a4²), with the constants as the deck wrote them and their lines, and the bound
/// that would make it so. Also the key the message stands at: that of the failed condition.
std::pair<std::string, std::string> not_positive_definite(const Params& p, const Eigen::Matrix3d& A) {
  const auto value = [&](const char* k) {
    const std::string& w = p.written(k);
    return w.empty() ? fmt::format("{:g}", p.number(k)) : w;
  };
  const auto at = [&](const char* k) {
    const SourceLocation& w = p.where(k);
    // A default stands where the material's map does: no value starts there.
    if (w.line == p.where().line && w.column == p.where().column) return fmt::format("{} = {} (the default)", k, value(k));
    return w.line > 0 ? fmt::format("{} = {} (line {})", k, value(k), w.line) : fmt::format("{} = {}", k, value(k));
  };
  const double a1 = A(0, 0), a2 = A(1, 1), a4 = A(0, 1);
  const bool two_d = A(2, 2) == 0 && A(1, 2) == 0 && A(0, 2) == 0;
  const std::string given = two_d ? fmt::format("{}, {}, {}", at("a1"), at("a2"), at("a4"))
                                  : fmt::format("{}, {}, {}, {}, {}, {}", at("a1"), at("a2"), at("a3"), at("a4"),
                                                at("a5"), at("a6"));
  const std::string head = two_d ? "the Fung quadratic form is not positive definite (the two-dimensional approach, "
                                   "a3 = a5 = a6 = 0, needs a1 > 0, a2 > 0 and a1·a2 − a4² > 0), so W would not be "
                                   "convex: "
                                 : "the Fung quadratic form is not positive definite (the matrix [[a1, a4, a6], [a4, "
                                   "a2, a5], [a6, a5, a3]] needs a1 > 0, a1·a2 − a4² > 0 and det > 0), so W would not "
                                   "be convex: ";
  if (!(a1 > 0)) return {"a1", head + fmt::format("a1 = {} ≤ 0 ({}): a1 must be > 0", value("a1"), given)};
  if (two_d && !(a2 > 0)) return {"a2", head + fmt::format("a2 = {} ≤ 0 ({}): a2 must be > 0", value("a2"), given)};
  const double minor2 = a1 * a2 - a4 * a4;
  if (!(minor2 > 0)) {
    if (a4 == 0 || !(a2 > 0))
      return {"a2", head + fmt::format("a1·a2 − a4² = {:.4g} ≤ 0 ({}): a2 must be > a4²/a1 = {:.4g}", minor2, given,
                                       a4 * a4 / a1)};
    std::string s = head + fmt::format("a1·a2 − a4² = {} × {} − ({})² = {:.4g} ≤ 0 ({}): |a4| must be < √(a1·a2) = {:.4g}",
                                       value("a1"), value("a2"), value("a4"), minor2, given, std::sqrt(a1 * a2));
    // Some sources write Q with a4 E1E2, not 2 a4 E1E2: their a4 is twice Tunica's.
    if (a1 * a2 - 0.25 * a4 * a4 > 0)
      s += fmt::format(". If your source writes Q with a4 E1E2 rather than 2 a4 E1E2, give half its value: a4: {:g}",
                       0.5 * a4);
    return {"a4", s};
  }
  // det A is linear in a3: det = a3·(a1·a2 − a4²) + det A|a3=0.
  const double det = A.determinant();
  if (det > 0)  // every leading minor > 0, yet the Cholesky factorization failed: at the edge
    return {"a3", head + fmt::format("it is at the edge of positive definiteness, its determinant {:.4g} is round-off "
                                     "({})",
                                     det, given)};
  Eigen::Matrix3d A0 = A;
  A0(2, 2) = 0;
  const double a3_min = -A0.determinant() / minor2;
  return {"a3", head + fmt::format("its determinant is {:.4g} ≤ 0 ({}): with these a1, a2, a4, a5, a6, a3 must be > "
                                   "{:.4g}, or the couplings a5, a6 smaller",
                                   det, given, a3_min)};
}

const RegisterMaterial reg_fung(MaterialType{
    ComponentSpec{"materials", "fung",
                  "Fung's exponential law W = c (exp Q − 1), Q = a1 E1² + a2 E2² + a3 E3² + 2 a4 E1E2 + 2 a5 E2E3 + "
                  "2 a6 E1E3 + a7 E12² (1 = circumferential, 2 = axial/meridional, 3 = radial). "
                  "a3 = a5 = a6 = 0 is the paper's two-dimensional approach. The quadratic form must be "
                  "positive definite.",
                  {required(positive(number("c", Dimension::pressure, "stress-like constant c"))),
                   required(number("a1", Dimension::dimensionless, "E1² coefficient")),
                   required(number("a2", Dimension::dimensionless, "E2² coefficient")),
                   with_default(number("a3", Dimension::dimensionless, "E3² coefficient"), "0"),
                   required(number("a4", Dimension::dimensionless, "2 E1 E2 coefficient")),
                   with_default(number("a5", Dimension::dimensionless, "2 E2 E3 coefficient"), "0"),
                   with_default(number("a6", Dimension::dimensionless, "2 E1 E3 coefficient"), "0"),
                   with_default(at_least(number("a7", Dimension::dimensionless, "in-plane shear coefficient (E12²)"), 0.0),
                                "0")}},
    [](const Params& p) -> std::unique_ptr<MembraneMaterial> {
      Eigen::Matrix3d A;
      A << p.number("a1"), p.number("a4"), p.number("a6"),  //
          p.number("a4"), p.number("a2"), p.number("a5"),   //
          p.number("a6"), p.number("a5"), p.number("a3");
      if (!FungMaterial::is_convex(A, p.number("a7"))) {
        const auto [key, why] = not_positive_definite(p, A);
        p.fail(key, why);
      }
      return std::make_unique<FungMaterial>(p.number("c"), A, p.number("a7"));
    },
    {MaterialSample{"rat_aorta",
                    "the paper's rat abdominal aorta, two-dimensional approach (theory manual §12.1; a4 from "
                    "the caption of its Fig. 2, §12.3)",
                    {{"c", "61.163 kPa"}, {"a1", "0.68238"}, {"a2", "0.60558"}, {"a4", "0.1067"}},
                    // Orthotropic: the hoop and axial directions on and off the element's axes.
                    {0.0, 35.0 * std::numbers::pi / 180.0, 0.5 * std::numbers::pi}},
     MaterialSample{"three_d_shear",
                    "every term of (3.1): the through-thickness coupling a3, a5, a6 (the multiplier of (2.1) "
                    "is nonzero) and the in-plane shear a7; illustrative constants, A positive definite",
                    {{"c", "50 kPa"},
                     {"a1", "1.1"},
                     {"a2", "0.7"},
                     {"a3", "0.9"},
                     {"a4", "0.2"},
                     {"a5", "0.15"},
                     {"a6", "-0.1"},
                     {"a7", "0.8"}},
                    {0.0, -50.0 * std::numbers::pi / 180.0}}}});
}  // namespace

}  // namespace tunica
