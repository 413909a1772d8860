#include "io/inverse_step_checks.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "contributions/element_type.hpp"

namespace tunica {

void check_inverse_step(const DeckNode& node, const Model& m, const Step& step) {
  const DeckNode type = node["type"];
  if (!m.steps.empty() && m.steps.front().inverse)
    type.fail(fmt::format("a deck takes one inverse step, and step '{}' is one already: the steps after it are "
                          "forward steps on the zero-pressure reference it computes (`type: forward`, the default); "
                          "the imaged geometry of a second inverse step would have to be a configuration of that "
                          "reference, which the deck's geometry is not",
                          m.steps.front().name));
  if (!m.steps.empty())
    type.fail(fmt::format("an inverse step must be the first step: the deck's geometry is the imaged (loaded) "
                          "configuration it starts from, and step '{}' comes before it",
                          m.steps.front().name));
  if (step.volume_control.load >= 0)
    node["volume_control"].fail("an inverse step takes its loads at their imaged values in `set`, not volume control");
  for (const Part& part : m.parts) {
    for (const ElementBlock& b : part.blocks)
      if (!element_type(b.kind).inverse)
        type.fail(fmt::format("part '{}' is made of {}s, which have no inverse element: an inverse step takes "
                              "membrane parts only (3-D triangles and quadrilaterals, 6-node triangles, "
                              "axisymmetric membranes)",
                              part.name, element_type(b.kind).name));
    if (part.enter_step > 0)
      type.fail(fmt::format("part '{}' enters in a later step: an inverse step solves for the reference of every part "
                            "at once (leave out its `enter_step`)",
                            part.name));
  }
  if (!m.contacts.empty())
    type.fail(fmt::format("contact pair '{}': an inverse step takes no contact (the imaged configuration's contact "
                          "forces are unknown)",
                          m.contacts.front().name));
  // The fixed point's forward problem ramps a prescribed value v to the displacement −v and a load to
  // its value (13.15): a name that is a boundary and a load at once would take both.
  if (step.inverse_method == Step::InverseMethod::fixed_point)
    for (const auto& target : step.targets) {
      const std::string& name = target.first;  // a named variable: lambdas may not capture a structured binding (clang)
      const bool boundary = std::any_of(m.boundaries.begin(), m.boundaries.end(), [&](auto& b) { return b.name == name; });
      const bool load = std::any_of(m.loads.begin(), m.loads.end(), [&](auto& l) { return l.name == name; });
      if (boundary && load)
        node["set"][name].fail(fmt::format("'{}' names a boundary and a load: `method: fixed_point` sets them apart "
                                           "(a prescribed value becomes the opposite displacement); rename one",
                                           name));
    }
  // The prestress method keeps the imaged geometry as the reference: a prescribed value holds a
  // node off it, which no prestress balances (theory manual §13.2).
  if (step.inverse_method == Step::InverseMethod::prestress)
    for (const auto& target : step.targets) {
      const std::string& name = target.first;  // a named variable: lambdas may not capture a structured binding (clang)
      const double value = target.second;
      const bool boundary = std::any_of(m.boundaries.begin(), m.boundaries.end(), [&](auto& b) { return b.name == name; });
      if (boundary && value != 0)
        node["set"][name].fail(fmt::format("`method: prestress` keeps the imaged geometry as the reference, and "
                                           "boundary '{}' would move its nodes off it, which no prestress "
                                           "balances (theory manual §13.2). A value that places the zero-pressure "
                                           "reference (an axial prestretch held by the ends) needs `method: direct` "
                                           "or `fixed_point`, which find that reference; with ends held where they "
                                           "are imaged, prescribe 0",
                                           name));
    }
    // The fixed point's linear systems are the forward problem's (13.15), symmetric where it is.
  if (step.solver.linear_solver == "cholmod" && step.inverse_method == Step::InverseMethod::direct)
    (node.has("solver") && node["solver"].has("linear_solver") ? node["solver"]["linear_solver"] : type)
        .fail("the tangent of an inverse step is not symmetric, and cholmod takes symmetric tangents only: use "
              "`linear_solver: auto` (UMFPACK for it) or umfpack");
}

}  // namespace tunica
