#pragma once
// Error types. InputError is a user error in a deck or data file: it names the
// file, the line and the key. SolveError is a run that cannot go on (no
// convergence after the allowed cut-backs). Both carry a user-readable message.
#include <stdexcept>
#include <string>

namespace tunica {

/// Where in an input file something stands: file, 1-based line and column (0 = unknown), key path.
struct SourceLocation {
  std::string file;
  int line = 0;
  int column = 0;
  std::string key;  ///< dotted key path, e.g. "materials.aorta.c"
};

/// "file:line:column: key 'k': what" (the parts that are known): how messages about an input
/// (errors and warnings) say where.
std::string format_location(const SourceLocation& where, const std::string& what);

/// A user error in an input: the message reads "file:line:column: key: what".
class InputError : public std::runtime_error {
public:
  InputError(const SourceLocation& where, const std::string& what);
  const SourceLocation& where() const { return where_; }
  const std::string& reason() const { return reason_; }

private:
  SourceLocation where_;
  std::string reason_;
};

/// A run that cannot continue (e.g. an increment that does not converge after the allowed cut-backs).
class SolveError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

}  // namespace tunica
