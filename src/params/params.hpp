#pragma once
// The values of a component's declared parameters (params/param_spec.hpp), in internal
// units, each with the place in the deck it came from; filled by io/read_params.hpp.
#include <map>
#include <string>
#include <vector>

#include "core/errors.hpp"

namespace tunica {

/// Values read against a ComponentSpec, in internal units.
class Params {
public:
  double number(const std::string& name) const;
  long integer(const std::string& name) const;
  const std::string& text(const std::string& name) const;
  bool boolean(const std::string& name) const;
  const std::vector<double>& numbers(const std::string& name) const;
  /// A number as written in the deck, with its unit ("0.122 mm"; the default's text if not
  /// given): for messages that echo a value in the units the user typed.
  const std::string& written(const std::string& name) const;
  bool has(const std::string& name) const { return values_.count(name) != 0; }
  /// Where the value was given (the component's map if defaulted).
  const SourceLocation& where(const std::string& name) const;
  /// The component's own location.
  const SourceLocation& where() const { return self_; }
  [[noreturn]] void fail(const std::string& name, const std::string& what) const;

  /// One value as read: numbers (number, integer, boolean as 0/1, list) or text, and its place.
  struct Value {
    std::vector<double> nums;
    std::string str;
    std::string written;  ///< a single number's text as written (number and unit)
    SourceLocation loc;
  };
  /// Filled by the reader: the component's own location, then each value given or defaulted.
  void set_where(SourceLocation self) { self_ = std::move(self); }
  void set(const std::string& name, Value value) { values_[name] = std::move(value); }

private:
  const Value& get(const std::string& name) const;
  std::map<std::string, Value> values_;
  SourceLocation self_;
};

}  // namespace tunica
