#pragma once
// Declared parameters. Every component a deck can name (a material, an element,
// a mesh generator, a load, ...) declares its parameters here: type, unit
// dimension, default, allowed range and a one-line doc. The same declaration
// validates the deck (unknown keys, missing keys, types, units, ranges; io/read_params.hpp)
// and generates the deck reference in docs/ (`tunica reference`). Nothing here reads YAML:
// the components that declare parameters do not depend on the deck reader.
#include <optional>
#include <string>
#include <vector>

#include "params/units.hpp"

namespace tunica {

/// `structured`: a list or map the section reads itself (documented here, validated there).
enum class ParamType { number, integer, text, boolean, numbers, structured };

/// One declared parameter.
struct ParamSpec {
  std::string name;
  ParamType type = ParamType::number;
  Dimension dim = Dimension::dimensionless;
  bool required = false;
  std::string default_text;             ///< default as it would be written in a deck ("" = none)
  std::optional<double> min, max;       ///< allowed range (in internal units)
  bool min_exclusive = false;           ///< min is excluded (e.g. thickness > 0)
  std::vector<std::string> choices;     ///< allowed values of a text parameter
  int count = 0;                        ///< required length of a numbers list (0 = any)
  std::string doc;
  /// The fix a message for the missing key gives, e.g. "add the part's geometry, e.g. `mesh:
  /// {...}`" ("": one built from the type, the unit and the doc). For messages only.
  std::string missing_fix;
  /// What a message for a value out of range adds: what the bounds mean, a convention that
  /// differs ("": nothing). For messages only.
  std::string range_fix;
};

/// A component's declaration: the key under which decks select it and its parameters.
struct ComponentSpec {
  std::string section;  ///< e.g. "materials"
  std::string type;     ///< value of the `type` key selecting it ("" if none)
  std::string doc;
  std::vector<ParamSpec> params;
};

/// Builders for terse declarations.
ParamSpec number(std::string name, Dimension dim, std::string doc);
ParamSpec integer(std::string name, std::string doc);
ParamSpec text(std::string name, std::string doc);
ParamSpec boolean(std::string name, std::string doc);
ParamSpec numbers(std::string name, Dimension dim, int count, std::string doc);
/// A list or map read by the section itself; `shape` names it in the reference ("map", "list", ...).
ParamSpec structured(std::string name, std::string shape, std::string doc);
ParamSpec required(ParamSpec p);
ParamSpec with_default(ParamSpec p, std::string default_text);
ParamSpec positive(ParamSpec p);
ParamSpec at_least(ParamSpec p, double min);
ParamSpec at_most(ParamSpec p, double max);
ParamSpec one_of(ParamSpec p, std::vector<std::string> choices);
/// p with ParamSpec::range_fix set.
ParamSpec explaining_range(ParamSpec p, std::string why);

/// Markdown table documenting a component's parameters.
std::string params_markdown(const ComponentSpec& spec);

/// The allowed range as the reference and the messages write it ("> 0", ">= 1, <= 2"; "" if none).
std::string range_text(const ParamSpec& spec);

}  // namespace tunica
