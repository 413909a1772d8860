// Units: conversion of deck values into the deck's unit system (UDUNITS-2).
#include <gtest/gtest.h>

#include "core/article.hpp"
#include "params/units.hpp"

using namespace tunica;

TEST(Units, MmHgToMegapascalInMillimetreNewtonSystem) {
  const UnitSystem u("mm", "N");
  // UDUNITS-2 defines 1 mmHg = 133.322387415 Pa (13.5951 g/cm³ · g_n · 1 mm); the theory manual (§12) rounds to 133.322.
  EXPECT_NEAR(u.to_internal(200, "mmHg", Dimension::pressure), 200 * 133.322387415e-6, 1e-12);
  EXPECT_NEAR(u.to_internal(61.163, "kPa", Dimension::pressure), 0.061163, 1e-15);
  EXPECT_NEAR(u.to_internal(0.122, "mm", Dimension::length), 0.122, 1e-15);
  EXPECT_NEAR(u.to_internal(90, "deg", Dimension::angle), 1.5707963267948966, 1e-14);
  EXPECT_NEAR(u.from_internal(0.026664477483, "mmHg", Dimension::pressure), 200.0, 1e-9);
}

TEST(Units, WrongDimensionAndUnknownUnitAreRefused) {
  const UnitSystem u("mm", "N");
  EXPECT_THROW(u.to_internal(1, "kPa", Dimension::length), std::invalid_argument);
  EXPECT_THROW(u.to_internal(1, "furlongs_per_fortnight", Dimension::length), std::invalid_argument);
  EXPECT_THROW(UnitSystem("N", "N"), std::invalid_argument);
}

TEST(Units, AWrongDimensionIsNamedWithItsArticle) {
  const UnitSystem u("mm", "N");
  const auto reason = [&](const std::string& unit, Dimension d) {
    try {
      u.to_internal(1, unit, d);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(reason("mm", Dimension::angle), "unit 'mm' is not an angle");
  EXPECT_EQ(reason("deg", Dimension::length), "unit 'deg' is not a length");
  EXPECT_EQ(with_article("unit"), "a unit");
  EXPECT_EQ(with_article("element"), "an element");
}

TEST(Units, SplitQuantity) {
  double v;
  std::string unit;
  ASSERT_TRUE(split_quantity("61.163 kPa", v, unit));
  EXPECT_EQ(v, 61.163);
  EXPECT_EQ(unit, "kPa");
  ASSERT_TRUE(split_quantity("1e-3", v, unit));
  EXPECT_EQ(unit, "");
  EXPECT_FALSE(split_quantity("kPa", v, unit));
  EXPECT_FALSE(split_quantity("inf", v, unit));
}
