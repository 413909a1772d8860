#include "model/model.hpp"

namespace tunica {

int Model::find_node_set(const std::string& name) const {
  for (std::size_t i = 0; i < node_sets.size(); ++i)
    if (node_sets[i].name == name) return static_cast<int>(i);
  return -1;
}

int Model::find_part(const std::string& name) const {
  for (std::size_t i = 0; i < parts.size(); ++i)
    if (parts[i].name == name) return static_cast<int>(i);
  return -1;
}

}  // namespace tunica
