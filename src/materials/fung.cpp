#include "materials/fung.hpp"

#include <cmath>
#include <numbers>

namespace tunica {

FungMaterial::FungMaterial(double c, const Eigen::Matrix3d& A, double a7) : c_(c), A_(A), a7_(a7) {}

bool FungMaterial::is_convex(const Eigen::Matrix3d& A, double a7) {
  if (a7 < 0) return false;
  const bool two_d = A(2, 2) == 0 && A(1, 2) == 0 && A(0, 2) == 0;
  if (two_d) return A(0, 0) > 0 && A(1, 1) > 0 && A(0, 0) * A(1, 1) - A(0, 1) * A(0, 1) > 0;
  Eigen::LLT<Eigen::Matrix3d> llt(A);
  return llt.info() == Eigen::Success;
}

EnergyDerivatives FungMaterial::energy(const Eigen::Vector4d& v) const {
  // e = (E1, E2, E3); Q = eᵀ A e + a7 E12², E12 = v(2)/2.
  const Eigen::Vector3d e(0.5 * (v(0) - 1.0), 0.5 * (v(1) - 1.0), 0.5 * (v(3) - 1.0));
  const double e12 = 0.5 * v(2);
  const double Q = e.dot(A_ * e) + a7_ * e12 * e12;
  // dQ/dv: dQ/dC_ii = (A e)_i since dE_i/dC_ii = ½; a7 E12² = a7 v3²/4 gives dQ/dv3 = a7 E12, d²Q/dv3² = a7/2.
  const Eigen::Vector3d Ae = A_ * e;
  Eigen::Vector4d dQ(Ae(0), Ae(1), a7_ * e12, Ae(2));
  Eigen::Matrix4d d2Q = Eigen::Matrix4d::Zero();
  const int map[3] = {0, 1, 3};  // E1, E2, E3 -> v index
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) d2Q(map[i], map[j]) = 0.5 * A_(i, j);
  d2Q(2, 2) = 0.5 * a7_;
  const double eQ = std::exp(Q);
  EnergyDerivatives out;
  out.W = c_ * (eQ - 1.0);
  out.dW = c_ * eQ * dQ;
  out.d2W = c_ * eQ * (dQ * dQ.transpose() + d2Q);
  return out;
}

namespace {
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
      if (!FungMaterial::is_convex(A, p.number("a7")))
        p.fail("a1",
               "Fung quadratic form is not positive definite (need a1 > 0, a2 > 0, a1 a2 > a4² in the "
               "two-dimensional approach; the full matrix [[a1,a4,a6],[a4,a2,a5],[a6,a5,a3]] positive "
               "definite otherwise): W would not be convex");
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
