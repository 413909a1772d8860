#pragma once
// Reading axisymmetric solid parts (`element: axisymmetric_solid`, theory manual §10;
// the plaque): the formulation and the structured (r, z) grid between two meridian
// profiles (mesh/solid_grid.hpp), with the node sets `<part>.inner`, `<part>.outer`
// (increasing z), `<part>.bottom`, `<part>.top` (increasing r) and `<part>.all`.
#include "io/deck_node.hpp"
#include "io/read_params.hpp"
#include "model/model.hpp"

namespace tunica {

/// The keys of an `axisymmetric_solid` part (declared for the deck reference).
const ComponentSpec& solid_part_spec();
/// The `mesh` map of a solid part (`type: grid`).
const ComponentSpec& solid_grid_spec();
/// A bump profile map `{radius_ends, radius_centre, shape}` (the `inner`/`outer` of a grid).
const ComponentSpec& profile_bump_spec();

/// Reads the formulation and the `mesh` of solid part `node` into `part` and the model
/// (nodes, one solid4 block, node sets). Mesh errors name the `mesh` key's file and line.
void read_solid_part(const DeckNode& node, const Params& p, Part& part, Model& m);

}  // namespace tunica
