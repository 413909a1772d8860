#pragma once
// Values written without a unit where the unit is easily mistaken: valid, but said. A bare
// pressure is in the deck's pressure unit (N/mm² = MPa for mm and N): a load's `150` meant as
// mmHg is a million mmHg, `mu: 40` meant as kPa is 40 MPa. A bare angle is in radians: `beta: 1`
// is 57° (a bare angle out of its range, `beta: 40`, is an error that proposes `40 deg`). An
// angle in gradians (UDUNITS-2's `grade`, 400 to a turn) is valid but rarely meant: said too.
// Each warning names the line and key, says how the value was read and how to write it with
// a unit; it goes to Model::warnings. A bare contact penalty is in the deck's force per length³, a
// unit few write by heart: said too.
#include "io/deck_node.hpp"
#include "model/model.hpp"
#include "params/param_spec.hpp"

namespace tunica {

/// Warns if `v` is a number other than 0 written without a unit for a value of dimension `dim`
/// (pressure, angle or a contact penalty; other dimensions are not warned about). `load_target`: a pressure a
/// step sets on a load, also given in mmHg. True if it warned.
bool warn_if_unitless(const DeckNode& v, Dimension dim, Model& m, bool load_target = false);

/// Warns if `v` is an angle given in gradians (`40 grade` = 36 deg). True if it warned.
bool warn_if_gradians(const DeckNode& v, Model& m);

/// warn_if_unitless (and for angles warn_if_gradians) for each pressure and angle the component `node` (read against `spec`)
/// gives, one warning per key (the first bare number of a list).
void warn_unitless_values(const DeckNode& node, const ComponentSpec& spec, Model& m);

}  // namespace tunica
