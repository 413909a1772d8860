#include "core/errors.hpp"

namespace tunica {

std::string format_location(const SourceLocation& w, const std::string& what) {
  std::string s = w.file.empty() ? std::string("<input>") : w.file;
  if (w.line > 0) {
    s.append(":").append(std::to_string(w.line));
    if (w.column > 0) s.append(":").append(std::to_string(w.column));
  }
  s.append(": ");
  if (!w.key.empty()) s.append("key '").append(w.key).append("': ");
  return s.append(what);
}

InputError::InputError(const SourceLocation& where, const std::string& what)
    : std::runtime_error(format_location(where, what)), where_(where), reason_(what) {}

}  // namespace tunica
