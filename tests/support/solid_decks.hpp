#pragma once
// Decks with an axisymmetric solid part, shared by the solid tests: an artery (membrane tube)
// prestretched and pressurized in step 1, and a plaque (a solid with a cosine stenosis) that
// enters stress free in step 2, where its top is pushed down while its bottom is held in z.
#include <string>

namespace tunica::test {

inline const std::string kArteryWithPlaque = R"(title: artery with a plaque entering in step 2
units: {length: mm, force: N}
materials:
  wall: {type: neo_hookean, mu: 0.1}
  plaque: {type: neo_hookean_solid, mu: 0.05, kappa: 0.07246}
parts:
  artery:
    element: axisymmetric_membrane
    material: wall
    thickness: 0.1
    mesh: {type: line, from: [1, 0], to: [1, 2], elements: 10}
  plaque:
    element: axisymmetric_solid
    material: plaque
    mesh:
      type: grid
      z0: 0.5
      z1: 1.5
      inner: {radius_ends: 0.85, radius_centre: 0.6, shape: cosine}
      outer: 0.9
      elements_r: 2
      elements_z: 4
    enter_step: squeeze
boundary:
  artery_base: {node_set: artery.start, dofs: [z]}
  stretch: {node_set: artery.end, dofs: [z]}
  plaque_base: {node_set: plaque.bottom, dofs: [z]}
  plaque_push: {node_set: plaque.top, dofs: [z]}
loads:
  lumen: {type: pressure, part: artery}
solver: {residual_tolerance: 1e-11}
steps:
  - {name: prestretch, increments: 2, set: {stretch: 0.2, lumen: 0.005}}
  - {name: squeeze, increments: 2, set: {plaque_push: -0.05}}
output:
  vtk: false
  history:
    - {quantity: sigma_zz, part: plaque, reduce: min, name: szz_min}
    - {quantity: sigma_zz, part: plaque, reduce: max, name: szz_max}
    - {quantity: sigma_rr, part: plaque, reduce: max, name: srr_max}
    - {quantity: hydrostatic_pressure, part: plaque, reduce: max, name: p_max}
    - {quantity: volume_ratio, part: plaque, reduce: min, name: J_min}
    - {quantity: reaction_z, node_set: plaque.top}
    - {quantity: sigma_thetatheta, part: artery, name: artery_hoop}
)";

}  // namespace tunica::test
