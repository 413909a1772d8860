#pragma once
// A deck with axisymmetric shell parts, shared by the shell tests: an artery (shell tube,
// ends held in z and in slope_r, i.e. clamped against rotation) prestretched and pressurized
// in step 1, a shell balloon (a sphere from pole to pole, poles held in r, z and slope_z) that
// enters in step 2 and is inflated against the artery (penalty contact, balloon slave), and a
// membrane cuff that shares nothing with them (mixed DOF map: nodes with and without slopes).
#include <string>

namespace tunica::test {

inline const std::string kShellArteryBalloon = R"(title: shell artery and shell balloon
units: {length: mm, force: N}
materials:
  wall: {type: neo_hookean, mu: 0.1}
  rubber: {type: mooney_rivlin, b1: 0.4, b2: 0.1}
  stiff_wall: {type: neo_hookean, mu: 1.0}
parts:
  cuff:
    element: axisymmetric_membrane
    material: wall
    thickness: 0.05
    mesh: {type: line, from: [2, 0], to: [2, 1], elements: 3}
  artery:
    element: axisymmetric_shell
    material: stiff_wall
    thickness: 0.1
    mesh: {type: line, from: [1, 0], to: [1, 2], elements: 7}
  balloon:
    element: axisymmetric_shell
    material: rubber
    thickness: 0.08
    thickness_points: 3
    mesh: {type: arc, center: [0, 1], radius: 0.8, start_angle: -90 deg, end_angle: 90 deg, elements: 9}
    enter_step: inflate
node_sets:
  artery_ends: {part: artery, nodes: [0, 7]}
  poles: {part: balloon, nodes: [0, 9]}
boundary:
  artery_base: {node_set: artery.start, dofs: [z]}
  stretch: {node_set: artery.end, dofs: [z]}
  artery_clamp: {node_set: artery_ends, dofs: [slope_r]}
  poles: {node_set: poles, dofs: [r, z, slope_z]}
  cuff_base: {node_set: cuff.start, dofs: [z]}
loads:
  lumen: {type: pressure, part: artery}
  inflation: {type: pressure, part: balloon}
  cuff_pressure: {type: pressure, part: cuff}
contact:
  balloon_artery:
    slave: balloon
    master: artery
    master_orientation: reversed
    penalty: 50
    offset: 0.09
solver: {residual_tolerance: 1e-10}
steps:
  - {name: prestretch, increments: 2, set: {stretch: 0.2, lumen: 0.005, cuff_pressure: 0.001}}
  - {name: inflate, increments: 8, set: {inflation: 0.16}}
output:
  vtk: false
  history:
    - {quantity: radius, part: artery, reduce: min, name: artery_rmin, unit: mm}
    - {quantity: position_r, node_set: balloon.all, reduce: max, name: balloon_rmax, unit: mm}
    - {quantity: contact_pressure, contact: balloon_artery, name: pc, unit: MPa}
    - {quantity: M_2, part: artery, reduce: max, name: M_s_max, unit: N}
    - {quantity: sigma_2_outer, part: artery, reduce: max, name: s_outer_max, unit: MPa}
    - {quantity: volume, load: inflation, name: balloon_volume}
)";

}  // namespace tunica::test
