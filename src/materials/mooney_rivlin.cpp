// Incompressible Mooney–Rivlin strain energy (theory manual (3.4)): W = b1 (I1 − 3) + b2 (I2 − 3),
// I1 = C11 + C22 + C33, I2 = ½(I1² − tr C²) = C11 C22 − C12² + C33 (C11 + C22).
#include "materials/membrane_material.hpp"

namespace tunica {

namespace {

class MooneyRivlinMaterial final : public MembraneMaterial {
public:
  MooneyRivlinMaterial(double b1, double b2) : b1_(b1), b2_(b2) {}
  std::string type() const override { return "mooney_rivlin"; }
  bool isotropic() const override { return true; }
  EnergyDerivatives energy(const Eigen::Vector4d& v) const override {
    const double I1 = v(0) + v(1) + v(3);
    const double I2 = v(0) * v(1) - v(2) * v(2) + v(3) * (v(0) + v(1));
    EnergyDerivatives out;
    out.W = b1_ * (I1 - 3.0) + b2_ * (I2 - 3.0);
    // dI2/dv = (C22 + C33, C11 + C33, −2 C12, C11 + C22)
    out.dW = b1_ * Eigen::Vector4d(1, 1, 0, 1) + b2_ * Eigen::Vector4d(v(1) + v(3), v(0) + v(3), -2.0 * v(2), v(0) + v(1));
    Eigen::Matrix4d d2I2;
    d2I2 << 0, 1, 0, 1,  //
        1, 0, 0, 1,      //
        0, 0, -2, 0,     //
        1, 1, 0, 0;
    out.d2W = b2_ * d2I2;
    return out;
  }

private:
  double b1_, b2_;
};

const RegisterMaterial reg(MaterialType{
    ComponentSpec{"materials", "mooney_rivlin",
                  "Incompressible Mooney–Rivlin W = b1 (I1 − 3) + b2 (I2 − 3) (the balloon material); "
                  "small-strain shear modulus 2 (b1 + b2).",
                  {required(positive(number("b1", Dimension::pressure, "I1 coefficient"))),
                   required(at_least(number("b2", Dimension::pressure, "I2 coefficient"), 0.0))}},
    [](const Params& p) -> std::unique_ptr<MembraneMaterial> {
      return std::make_unique<MooneyRivlinMaterial>(p.number("b1"), p.number("b2"));
    },
    {MaterialSample{"angioplasty_balloon",
                    "the balloon of examples/balloon-angioplasty.yaml (the paper's constants are unreadable, "
                    "theory manual §12.3)",
                    {{"b1", "2.0 MPa"}, {"b2", "0.5 MPa"}}}}});

}  // namespace
}  // namespace tunica
