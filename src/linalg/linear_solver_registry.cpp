#include <map>
#include <stdexcept>

#include "linalg/linear_solver.hpp"

namespace tunica {

namespace {
std::map<std::string, LinearSolverType>& registry() {
  static std::map<std::string, LinearSolverType> r;
  return r;
}
}  // namespace

bool register_linear_solver(LinearSolverType type) {
  const std::string name = type.name;
  if (!registry().emplace(name, std::move(type)).second)
    throw std::logic_error("linear solver '" + name + "' registered twice");
  return true;
}

std::vector<std::string> linear_solver_names() {
  std::vector<std::string> names;
  for (const auto& entry : registry()) names.push_back(entry.first);
  return names;
}

std::string linear_solver_docs() {
  std::string s;
  for (const auto& [name, type] : registry()) s += (s.empty() ? "" : "; ") + ("`" + name + "`: " + type.doc);
  return s;
}

std::unique_ptr<LinearSolver> make_linear_solver(const std::string& name) {
  const auto it = registry().find(name);
  if (it == registry().end()) throw std::invalid_argument("unknown linear solver '" + name + "'");
  return it->second.make();
}

}  // namespace tunica
