#pragma once
// Physical units of input and output values, through UDUNITS-2.
// A deck declares a unit system by its length and force units; every
// dimensional value is converted once on input into that system, and output
// columns are converted from it into the unit the user asks for.
#include <string>

namespace tunica {

/// The physical dimension a parameter or output quantity carries.
/// `penalty`: pressure per length (force/length³), the stiffness of a contact penalty law.
enum class Dimension { dimensionless, length, force, pressure, angle, volume, penalty, moment };

/// Human name of a dimension ("length", "pressure (stress)", ...).
const char* dimension_name(Dimension d);

/// A unit system given by a length unit and a force unit; pressure and stress
/// are force/length², volume length³, angles are radians internally.
class UnitSystem {
public:
  /// Default system: mm and N (stress in N/mm² = MPa). Throws std::invalid_argument
  /// if a unit is unknown or is not a length (force).
  explicit UnitSystem(const std::string& length = "mm", const std::string& force = "N");

  const std::string& length_unit() const { return length_; }
  const std::string& force_unit() const { return force_; }
  /// The internal unit of a dimension as a UDUNITS string ("mm", "N", "N/mm^2", "rad", "1").
  std::string internal_unit(Dimension d) const;
  /// The internal unit of a dimension as messages write it ("mm", "N/mm²", "mm³", "rad", "" for
  /// dimensionless).
  std::string display_unit(Dimension d) const;
  /// Value in `unit` converted to the internal unit of dimension d. Throws
  /// std::invalid_argument with a readable reason (unknown unit, wrong dimension).
  double to_internal(double value, const std::string& unit, Dimension d) const;
  /// Internal value of dimension d converted to `unit` (same errors).
  double from_internal(double value, const std::string& unit, Dimension d) const;
  /// Throws std::invalid_argument unless `unit` is a known unit of dimension d.
  void check_unit(const std::string& unit, Dimension d) const;

private:
  std::string length_, force_;
};

/// True if UDUNITS-2 knows `text` as a unit (of any dimension).
bool is_unit(const std::string& text);

/// Suffix naming a unit in a column or array name: "_mm", "_kPa", "_N_per_mm2" for the
/// internal pressure unit of an mm–N system; "" for dimensionless quantities.
std::string unit_suffix(const UnitSystem& units, Dimension d, const std::string& unit = "");

/// Splits "61.163 kPa" into 61.163 and "kPa"; "0.5" gives an empty unit.
/// Returns false if the text does not start with a number.
bool split_quantity(const std::string& text, double& value, std::string& unit);

}  // namespace tunica
