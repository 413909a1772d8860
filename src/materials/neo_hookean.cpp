// Incompressible neo-Hookean strain energy (theory manual (3.3)): W = (μ/2)(I1 − 3),
// I1 = C11 + C22 + C33.
#include "materials/membrane_material.hpp"

namespace tunica {

namespace {

class NeoHookeanMaterial final : public MembraneMaterial {
public:
  explicit NeoHookeanMaterial(double mu) : mu_(mu) {}
  std::string type() const override { return "neo_hookean"; }
  bool isotropic() const override { return true; }
  EnergyDerivatives energy(const Eigen::Vector4d& v) const override {
    EnergyDerivatives out;
    out.W = 0.5 * mu_ * (v(0) + v(1) + v(3) - 3.0);
    out.dW = Eigen::Vector4d(0.5 * mu_, 0.5 * mu_, 0.0, 0.5 * mu_);
    return out;
  }

private:
  double mu_;
};

const RegisterMaterial reg(MaterialType{
    ComponentSpec{"materials", "neo_hookean", "Incompressible neo-Hookean W = (μ/2)(I1 − 3).",
                  {required(positive(number("mu", Dimension::pressure, "shear modulus μ")))}},
    [](const Params& p) -> std::unique_ptr<MembraneMaterial> {
      return std::make_unique<NeoHookeanMaterial>(p.number("mu"));
    },
    {MaterialSample{"balloon", "the rubber balloon of examples/balloon-sphere.yaml (theory manual §8)",
                    {{"mu", "1 MPa"}}}}});

}  // namespace
}  // namespace tunica
