#pragma once
// What to say about a value whose unit could not be converted: the unit UDUNITS-2 does not know
// or whose dimension is wrong, and the value as it should be written. A unit of several words
// is read by UDUNITS-2 as their product (`N m`), so a note after the unit (`3 MPa abs`) makes
// the whole unit unknown: the message names the word that is not a unit and the unit before it.
// `grad` is the degree in some languages and the gradian in others: the message offers both.
#include <string>
#include <vector>

#include "params/units.hpp"

namespace tunica {

/// Common units of a dimension, as UDUNITS-2 spells them, for the nearest to a mistyped one.
std::vector<std::string> common_units(Dimension dim);

/// The reason a value `written` ("3 MPa abs"), of unit `unit` ("MPa abs"), expected of dimension
/// `dim`, was refused, with the fix: `reason` is what the unit conversion said ("unknown unit
/// 'kPaa'", "unit 'kPa' is not a length").
std::string unit_advice(const std::string& written, const std::string& unit, Dimension dim, const UnitSystem& units,
                        const std::string& reason);

}  // namespace tunica
