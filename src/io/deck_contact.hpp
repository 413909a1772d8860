#pragma once
// Reading the `rigid_surfaces` and `contact` sections of an axisymmetric deck:
// rigid tools (cylinder, polyline) and contact pairs of a slave (a membrane
// part or an ordered node set) with a rigid surface or a deformable master
// chain (a membrane part or an ordered node set), see model.hpp (ContactPair).
#include "io/deck_node.hpp"
#include "io/read_params.hpp"
#include "model/model.hpp"

namespace tunica {

/// Reads `rigid_surfaces` (after the parts and node sets).
void read_rigid_surfaces(const DeckNode& deck, Model& m);
/// Reads `contact` (after `rigid_surfaces`).
void read_contacts(const DeckNode& deck, Model& m);

/// Declarations of the sections, for the deck reference.
const ComponentSpec& cylinder_spec();
const ComponentSpec& polyline_spec();
const ComponentSpec& contact_spec();

}  // namespace tunica
