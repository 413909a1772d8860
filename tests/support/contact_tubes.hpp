#pragma once
// The two-tube deck of the deformable-contact tests: a neo-Hookean tube (slave, R_i = 1 mm)
// inflated inside a Fung tube (master, R_o = 1.2 mm), both at λ_z = 1 (ends held axially), with
// the offset c = half thicknesses (tests/regression/test_deformable_contact.cpp has the closed
// form). First free inflation to 0.003, then contact up to 0.009 N/mm².
#include <string>

namespace tunica::test {

/// The deck with the pair's `penalty` as written, `artery_elements` master elements (8: matching
/// the slave's), `contact_increments` in the contact step and `pair_keys` appended to the pair's
/// map (", passes: 2").
inline std::string contact_tubes_deck(const std::string& penalty, int artery_elements = 8, int contact_increments = 12,
                                      const std::string& pair_keys = "") {
  return R"(title: neo-Hookean tube inflated against a Fung tube
units: {length: mm, force: N}
materials:
  soft: {type: neo_hookean, mu: 0.1 MPa}
  wall: {type: fung, c: 0.2 MPa, a1: 1.0, a2: 1.0, a4: 0.1}
parts:
  balloon:
    element: axisymmetric_membrane
    material: soft
    thickness: 0.1 mm
    mesh: {type: line, from: [1, 0], to: [1, 1], elements: 8}
  artery:
    element: axisymmetric_membrane
    material: wall
    thickness: 0.1 mm
    mesh: {type: line, from: [1.2, 0], to: [1.2, 1], elements: )" +
         std::to_string(artery_elements) + R"(}
boundary:
  b0: {node_set: balloon.start, dofs: [z]}
  b1: {node_set: balloon.end, dofs: [z]}
  a0: {node_set: artery.start, dofs: [z]}
  a1: {node_set: artery.end, dofs: [z]}
loads:
  lumen: {type: pressure, part: balloon}
contact:
  press: {slave: balloon, master: artery, master_orientation: reversed, penalty: )" +
         penalty + ", offset: 0.1 mm" + pair_keys + R"(}
solver: {residual_tolerance: 1e-11}
steps:
  - {name: free, increments: 3, set: {lumen: 0.003}}
  - {name: contact, increments: )" +
         std::to_string(contact_increments) + R"(, set: {lumen: 0.009}}
output:
  vtk: false
  history:
    - {quantity: pressure, load: lumen}
    - {quantity: radius, part: balloon, name: ri}
    - {quantity: radius, part: artery, name: ro}
    - {quantity: contact_pressure, contact: press, name: pc_max}
    - {quantity: contact_pressure, contact: press, name: pc_min, reduce: min}
    - {quantity: contact_force, contact: press}
    - {quantity: contact_penetration, contact: press}
)";
}

}  // namespace tunica::test
