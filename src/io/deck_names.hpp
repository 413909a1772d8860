#pragma once
// The names a deck has defined (parts, loads, node sets, ...), for messages about a
// name that is not among them (core/suggest.hpp lists them and finds a likely typo).
#include <string>
#include <vector>

#include "core/suggest.hpp"

namespace tunica {

/// The `name` of every item of a list (parts, loads, node sets, boundaries, contact pairs).
template <class List>
std::vector<std::string> names_of(const List& list) {
  std::vector<std::string> out;
  for (const auto& x : list) out.push_back(x.name);
  return out;
}

/// The keys of a map (materials, material types).
template <class Map>
std::vector<std::string> keys_of(const Map& map) {
  std::vector<std::string> out;
  for (const auto& [k, v] : map) out.push_back(k);
  return out;
}

}  // namespace tunica
