// The units a message proposes for a mistyped one (io/unit_advice.hpp) are units UDUNITS-2
// knows in the dimension asked for: a proposal the deck then refuses would send the user in a
// circle (`dyn`, which UDUNITS-2 does not know, was proposed for a force; it knows `dyne`).
#include <gtest/gtest.h>

#include "io/unit_advice.hpp"
#include "params/units.hpp"

using namespace tunica;

TEST(UnitAdvice, EveryProposedUnitIsKnownInItsDimension) {
  const UnitSystem units;
  for (Dimension d : {Dimension::length, Dimension::force, Dimension::pressure, Dimension::angle, Dimension::volume,
                      Dimension::penalty, Dimension::moment}) {
    const std::vector<std::string> proposed = common_units(d);
    EXPECT_FALSE(proposed.empty()) << dimension_name(d);
    for (const std::string& u : proposed) EXPECT_NO_THROW(units.check_unit(u, d)) << u << " as " << dimension_name(d);
  }
}
