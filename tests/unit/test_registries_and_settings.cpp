// The registries and declared tables the core looks things up in, instead of switching on names:
// - linear solvers: the deck's choices are the registered names, an unknown name or a second
//   registration is refused;
// - solver settings: the declared defaults are SolverSettings{} (written once), every declared
//   key sets its member, and a step inherits the top-level keys it does not override;
// - history quantities: every entry has the evaluator of its target and only that;
// - VTK cell types come from the element kind, an unknown kind is an error.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <stdexcept>
#include <string>

#include "contributions/element_type.hpp"
#include "io/deck.hpp"
#include "linalg/linear_solver.hpp"
#include "model/solver_settings.hpp"
#include "quantities/history_quantity.hpp"

namespace tunica {
namespace {

const ParamSpec& declared(const std::string& key) {
  const auto& ps = solver_settings_spec().params;
  const auto it = std::find_if(ps.begin(), ps.end(), [&](const ParamSpec& p) { return p.name == key; });
  if (it == ps.end()) throw std::logic_error("no solver key " + key);
  return *it;
}

TEST(LinearSolverRegistry, TheDeckOffersExactlyTheRegisteredSolvers) {
  const std::vector<std::string> names = linear_solver_names();
  for (const char* shipped : {"auto", "cholmod", "sparse_lu", "umfpack"})  // a solver added later joins them
    EXPECT_NE(std::find(names.begin(), names.end(), shipped), names.end()) << shipped;
  EXPECT_EQ(declared("linear_solver").choices, names);
  for (const auto& n : names) {
    const auto solver = make_linear_solver(n);
    ASSERT_TRUE(solver);
    SparseMatrix K(2, 2);
    K.insert(0, 0) = 4.0;
    K.insert(1, 1) = 2.0;
    K.insert(0, 1) = 1.0;
    K.insert(1, 0) = 1.0;
    K.makeCompressed();
    ASSERT_TRUE(solver->factorize(K)) << n;
    const Eigen::VectorXd x = solver->solve(Eigen::Vector2d(5.0, 3.0));
    EXPECT_NEAR(x(0), 1.0, 1e-14) << n;
    EXPECT_NEAR(x(1), 1.0, 1e-14) << n;
  }
  EXPECT_THROW(make_linear_solver("pardiso"), std::invalid_argument);
  EXPECT_THROW(register_linear_solver({"umfpack", "again", [] { return make_linear_solver("umfpack"); }}),
               std::logic_error);
}

TEST(SolverSettings, TheDeclaredDefaultsAreTheStructsAndEveryKeySetsItsMember) {
  // A deck without a solver section gets SolverSettings{} in every step.
  const std::string deck_head = R"(units: {length: mm, force: N}
materials:
  rubber: {type: neo_hookean, mu: 1 MPa}
parts:
  tube:
    element: axisymmetric_membrane
    material: rubber
    thickness: 0.1 mm
    mesh: {type: line, from: [1, 0], to: [1, 1], elements: 4}
boundary:
  ends: {node_set: tube.start, dofs: [z]}
  top: {node_set: tube.end, dofs: [z]}
loads:
  p: {type: pressure, part: tube}
)";
  const Model plain = read_deck_text(deck_head + "steps:\n  - {increments: 1, set: {p: 0.01 MPa}}\n", "plain.yaml");
  const SolverSettings d, s = plain.steps.at(0).solver;
  EXPECT_EQ(s.max_iterations, d.max_iterations);
  EXPECT_EQ(s.residual_tolerance, d.residual_tolerance);
  EXPECT_EQ(s.energy_tolerance, d.energy_tolerance);
  EXPECT_EQ(s.roundoff_tolerance, d.roundoff_tolerance);
  EXPECT_EQ(s.divergence_ratio, d.divergence_ratio);
  EXPECT_EQ(s.max_cutbacks, d.max_cutbacks);
  EXPECT_EQ(s.line_search, d.line_search);
  EXPECT_EQ(s.line_search_halvings, d.line_search_halvings);
  EXPECT_EQ(s.linear_solver, d.linear_solver);
  EXPECT_EQ(s.tangent_predictor, d.tangent_predictor);
  EXPECT_EQ(s.stiffen_stress_free_start, d.stiffen_stress_free_start);
  EXPECT_EQ(s.symmetrize_pressure_stiffness, d.symmetrize_pressure_stiffness);
  // The reference writes the defaults as a deck would.
  EXPECT_EQ(declared("residual_tolerance").default_text, "1e-9");
  EXPECT_EQ(declared("divergence_ratio").default_text, "1e8");
  EXPECT_EQ(declared("line_search_halvings").default_text, "8");

  // Every declared key, set at the top level and overridden in a step.
  const Model set = read_deck_text(deck_head + R"(solver: {max_iterations: 20, residual_tolerance: 1e-8, energy_tolerance: 1e-11,
         roundoff_tolerance: 1e-13, divergence_ratio: 1e6, max_cutbacks: 3, line_search: false,
         line_search_halvings: 4, linear_solver: umfpack, predictor: none, stress_free_start: exact,
         pressure_stiffness: symmetrized}
steps:
  - {increments: 1, set: {p: 0.01 MPa}}
  - {increments: 1, set: {p: 0.02 MPa}, solver: {line_search_halvings: 2, divergence_ratio: 100}}
)",
                                   "set.yaml");
  const SolverSettings& a = set.steps.at(0).solver;
  EXPECT_EQ(a.max_iterations, 20);
  EXPECT_EQ(a.residual_tolerance, 1e-8);
  EXPECT_EQ(a.energy_tolerance, 1e-11);
  EXPECT_EQ(a.roundoff_tolerance, 1e-13);
  EXPECT_EQ(a.divergence_ratio, 1e6);
  EXPECT_EQ(a.max_cutbacks, 3);
  EXPECT_FALSE(a.line_search);
  EXPECT_EQ(a.line_search_halvings, 4);
  EXPECT_EQ(a.linear_solver, "umfpack");
  EXPECT_FALSE(a.tangent_predictor);
  EXPECT_FALSE(a.stiffen_stress_free_start);
  EXPECT_TRUE(a.symmetrize_pressure_stiffness);
  const SolverSettings& b = set.steps.at(1).solver;
  EXPECT_EQ(b.line_search_halvings, 2);
  EXPECT_EQ(b.divergence_ratio, 100);
  EXPECT_EQ(b.max_iterations, 20);  // inherited from the top level

  // Out of range: named in the message.
  try {
    read_deck_text(deck_head + "solver: {line_search_halvings: 0}\nsteps:\n  - {increments: 1, set: {p: 0.01 MPa}}\n",
                   "bad.yaml");
    FAIL() << "line_search_halvings: 0 was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("line_search_halvings"), std::string::npos) << e.what();
  }
}

TEST(HistoryQuantities, EachHasTheEvaluatorOfItsTargetAndUniqueName) {
  std::set<std::string> names;
  for (const auto& q : history_quantities()) {
    EXPECT_TRUE(names.insert(q.name).second) << q.name << " twice";
    EXPECT_FALSE(q.doc.empty()) << q.name;
    EXPECT_EQ(find_history_quantity(q.name), &q);
    const bool part = q.target == QuantityTarget::part;
    EXPECT_EQ(static_cast<bool>(q.global), q.target == QuantityTarget::none) << q.name;
    EXPECT_EQ(static_cast<bool>(q.at), q.target == QuantityTarget::load || q.target == QuantityTarget::node_set) << q.name;
    EXPECT_EQ(static_cast<bool>(q.contact), q.target == QuantityTarget::contact) << q.name;
    if (part) {
      EXPECT_TRUE(q.membrane || q.membrane_whole || q.solid) << q.name;
    } else {
      EXPECT_FALSE(q.membrane || q.membrane_whole || q.solid) << q.name;
    }
  }
  EXPECT_EQ(find_history_quantity("no_such_quantity"), nullptr);
}

TEST(VtkCellTypes, ComeFromTheElementKindAndAnUnknownKindIsAnError) {
  EXPECT_EQ(vtk_cell_type(ElementKind::axisym2), 3);
  EXPECT_EQ(vtk_cell_type(ElementKind::shell2), 3);
  EXPECT_EQ(vtk_cell_type(ElementKind::tri3), 5);
  EXPECT_EQ(vtk_cell_type(ElementKind::quad4), 9);
  EXPECT_EQ(vtk_cell_type(ElementKind::solid4), 9);
  EXPECT_EQ(vtk_cell_type(ElementKind::tri6), 22);  // VTK_QUADRATIC_TRIANGLE
  EXPECT_EQ(vtk_revolved_cell_type(ElementKind::axisym2), 9);
  EXPECT_EQ(vtk_revolved_cell_type(ElementKind::solid4), 12);
  EXPECT_THROW(vtk_revolved_cell_type(ElementKind::tri3), std::logic_error);
  EXPECT_THROW(vtk_cell_type(static_cast<ElementKind>(99)), std::logic_error);
}

TEST(ElementTypes, EveryKindIsRegisteredOnceWithTheModelsNodeCount) {
  // Every ElementKind value up to the last one has an element type (a kind without one would
  // be refused by System, not assembled silently), and its declaration agrees with the model's.
  std::set<ElementKind> kinds;
  for (const ElementType* t : element_types()) {
    EXPECT_TRUE(kinds.insert(t->kind).second) << t->name;
    EXPECT_EQ(t->nodes, nodes_per_element(t->kind)) << t->name;
    EXPECT_GT(t->unknowns_per_node, 0) << t->name;
    EXPECT_NE(t->vtk_cell, 0) << t->name;
    EXPECT_TRUE(static_cast<bool>(t->make)) << t->name;
    EXPECT_TRUE(static_cast<bool>(t->points_per_element)) << t->name;
    EXPECT_FALSE(t->name.empty());
  }
  for (ElementKind k : {ElementKind::axisym2, ElementKind::tri3, ElementKind::quad4, ElementKind::solid4, ElementKind::shell2,
                        ElementKind::tri6})
    EXPECT_EQ(kinds.count(k), 1u) << static_cast<int>(k);
  ElementType again = element_type(ElementKind::tri3);
  EXPECT_THROW(register_element_type(again), std::logic_error);
}

}  // namespace
}  // namespace tunica
