#include "params/params.hpp"

#include <cmath>
#include <stdexcept>

namespace tunica {

const Params::Value& Params::get(const std::string& name) const {
  auto it = values_.find(name);
  if (it == values_.end()) throw std::logic_error("parameter '" + name + "' was not read");
  return it->second;
}
double Params::number(const std::string& name) const { return get(name).nums.at(0); }
long Params::integer(const std::string& name) const { return std::lround(get(name).nums.at(0)); }
const std::string& Params::text(const std::string& name) const { return get(name).str; }
bool Params::boolean(const std::string& name) const { return get(name).nums.at(0) != 0.0; }
const std::vector<double>& Params::numbers(const std::string& name) const { return get(name).nums; }
const std::string& Params::written(const std::string& name) const { return get(name).written; }
const SourceLocation& Params::where(const std::string& name) const { return get(name).loc; }
void Params::fail(const std::string& name, const std::string& what) const {
  throw InputError(has(name) ? where(name) : self_, what);
}

}  // namespace tunica
