#pragma once
// Reading a component's declared parameters (params/param_spec.hpp) from a deck map.
#include <string>
#include <vector>

#include "io/deck_node.hpp"
#include "params/param_spec.hpp"
#include "params/params.hpp"
#include "params/units.hpp"

namespace tunica {

/// Reads the map `node` against `spec`: errors on unknown keys (other than
/// `extra_keys`), missing required keys, wrong types, unknown or wrong units and
/// out-of-range values; fills defaults.
Params read_params(const DeckNode& node, const ComponentSpec& spec, const UnitSystem& units,
                   const std::vector<std::string>& extra_keys = {});

/// A number with an optional unit ("0.122 mm", 200 with the deck's units) in internal units.
double read_quantity(const DeckNode& node, Dimension dim, const UnitSystem& units);

}  // namespace tunica
