#pragma once
// Declared parameters. Every component a deck can name (a material, an element,
// a mesh generator, a load, ...) declares its parameters here: type, unit
// dimension, default, allowed range and a one-line doc. The same declaration
// validates the deck (unknown keys, missing keys, types, units, ranges) and
// generates the deck reference in docs/ (`tunica reference`).
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "io/deck_node.hpp"
#include "io/units.hpp"

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

/// Values read against a ComponentSpec, in internal units.
class Params {
public:
  double number(const std::string& name) const;
  long integer(const std::string& name) const;
  const std::string& text(const std::string& name) const;
  bool boolean(const std::string& name) const;
  const std::vector<double>& numbers(const std::string& name) const;
  bool has(const std::string& name) const { return values_.count(name) != 0; }
  /// Where the value was given (the component's map if defaulted).
  const SourceLocation& where(const std::string& name) const;
  /// The component's own location.
  const SourceLocation& where() const { return self_; }
  [[noreturn]] void fail(const std::string& name, const std::string& what) const;

private:
  struct Value {
    std::vector<double> nums;
    std::string str;
    SourceLocation loc;
  };
  const Value& get(const std::string& name) const;
  std::map<std::string, Value> values_;
  SourceLocation self_;
  friend Params read_params(const DeckNode&, const ComponentSpec&, const UnitSystem&,
                            const std::vector<std::string>&);
};

/// Reads the map `node` against `spec`: errors on unknown keys (other than
/// `extra_keys`), missing required keys, wrong types, unknown or wrong units and
/// out-of-range values; fills defaults.
Params read_params(const DeckNode& node, const ComponentSpec& spec, const UnitSystem& units,
                   const std::vector<std::string>& extra_keys = {});

/// A number with an optional unit ("0.122 mm", 200 with the deck's units) in internal units.
double read_quantity(const DeckNode& node, Dimension dim, const UnitSystem& units);

/// Markdown table documenting a component's parameters.
std::string params_markdown(const ComponentSpec& spec);

}  // namespace tunica
