#include "io/deck_shell_parts.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "elements/axisym_shell.hpp"
#include "mesh/meridian_tangents.hpp"

namespace tunica {

const ComponentSpec& shell_part_spec() {
  static const ComponentSpec s{
      "parts", "axisymmetric_shell",
      "An axisymmetric Kirchhoff–Love shell (selected by `element: axisymmetric_shell`; theory manual §11): a "
      "layered incompressible shell of revolution with membrane and bending stiffness, 2-node elements with a "
      "cubic Hermite meridian. Each node carries (r, z) and the meridian slopes (∂r/∂S, ∂z/∂S) (S: reference "
      "arc length), whose changes are the DOFs `slope_r`, `slope_z` of `boundary`. Same meshes (`line`, "
      "`arc`, or a list of them whose pieces meet tangentially, within 0.5 deg), node sets (`<part>.start`, `.end`, `.all`), pressure loads and contact as "
      "`axisymmetric_membrane`; any membrane material, evaluated in each layer. Slopes left free at an end "
      "make a hinge; a clamped or symmetry end of a tube holds `slope_r`, a pole on the axis holds `r` and "
      "`slope_z`.",
      {required(one_of(text("element", "element type"),
                       {"axisymmetric_membrane", "membrane", "axisymmetric_solid", "axisymmetric_shell"})),
       required(text("material", "name of a membrane material in `materials`, used in every layer")),
       required(positive(number("thickness", Dimension::length, "reference (load-free) wall thickness H"))),
       required(structured("mesh", "map or list",
                           "`type: line` or `arc` and its keys, or a list of them joined end to start and "
                           "tangentially (see Meshes)")),
       with_default(at_most(at_least(integer("meridian_points", "Gauss points along each element's meridian"), 2), 16),
                    "3"),
       with_default(at_most(at_least(integer("thickness_points", "Gauss points through the thickness (layers)"), 2), 16),
                    "5"),
       text("enter_step", "name of the step from which the part is assembled, stress free in its deck geometry "
                          "(default: from the start; see the user guide)")}};
  return s;
}

void finish_shell_part(const DeckNode& node, const Params& p, Part& part, const Model& m,
                       const std::vector<int>& joints) {
  part.shell_meridian_points = static_cast<int>(p.integer("meridian_points"));
  part.shell_thickness_points = static_cast<int>(p.integer("thickness_points"));
  const DeckNode mesh = node["mesh"];
  Meridian meridian;
  for (int n : part.nodes) meridian.push_back(m.X[n].head<2>());
  // Each piece's tangents on its own (exact for lines and arcs); at a joint the two pieces must
  // agree, since a Kirchhoff–Love meridian has one slope at each node.
  std::vector<int> cuts{0};
  cuts.insert(cuts.end(), joints.begin(), joints.end());
  cuts.push_back(static_cast<int>(meridian.size()) - 1);
  part.tangents.assign(meridian.size(), Eigen::Vector2d::Zero());
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    std::vector<Eigen::Vector2d> t;
    try {
      t = meridian_tangents(Meridian(meridian.begin() + cuts[k], meridian.begin() + cuts[k + 1] + 1));
    } catch (const std::invalid_argument& e) {
      mesh.fail(std::string("shell part '") + part.name + "': " + e.what());
    }
    if (k > 0) {
      const Eigen::Vector2d& before = part.tangents[static_cast<std::size_t>(cuts[k])];
      const double turn = std::atan2(before(0) * t.front()(1) - before(1) * t.front()(0), before.dot(t.front()));
      if (std::abs(turn) > kShellJointAngle)
        (mesh.is_sequence() ? mesh.items()[k] : mesh)
            .fail(fmt::format("shell part '{}': the meridian turns by {:.3g} deg at node {}, where mesh[{}] and "
                              "mesh[{}] join: a shell's meridian has one slope at each node, so its pieces must meet "
                              "tangentially (within {:g} deg); round the corner with an arc piece",
                              part.name, turn * 180 / std::numbers::pi, cuts[k], k - 1, k,
                              kShellJointAngle * 180 / std::numbers::pi));
      t.front() = (before + t.front()).normalized();
    }
    std::copy(t.begin(), t.end(), part.tangents.begin() + cuts[k]);
  }
  // Each element at its reference state: the kernel's own checks of the reference geometry.
  const ShellQuadrature quadrature{part.shell_meridian_points, part.shell_thickness_points};
  const ElementBlock& block = part.blocks.front();
  for (int e = 0; e < block.size(); ++e) {
    ShellNodes X;
    for (int a = 0; a < 2; ++a) {
      X.block<2, 1>(0, a) = meridian[static_cast<std::size_t>(e + a)];
      X.block<2, 1>(2, a) = part.tangents[static_cast<std::size_t>(e + a)];
    }
    ShellVector f;
    try {
      axisym_shell(X, X, part.thickness, *part.material, f, nullptr, quadrature);
    } catch (const std::exception& ex) {
      const std::string what = ex.what();
      const bool thick = what.find("thickness") != std::string::npos || what.find("layer") != std::string::npos;
      if (thick)
        p.fail("thickness", fmt::format("shell part '{}', element {}: the thickness {:g} does not fit the curvature of "
                                        "the reference meridian (half of it must stay within every radius of "
                                        "curvature): {}",
                                        part.name, e, part.thickness, what));
      const std::string message = fmt::format("shell part '{}', element {}: {}", part.name, e, what);
      mesh.fail(message);
    }
  }
}

}  // namespace tunica
