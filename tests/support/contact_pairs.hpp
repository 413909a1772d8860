#pragma once
// The index in Model::contacts of a contact pair named in the deck: its first pass (a two-pass
// pair, the default for deformable pairs, is followed by its reverse pass under the same name).
#include <string>

#include "model/model.hpp"

namespace tunica::test {

inline int contact_pair(const Model& m, const std::string& name) {
  for (std::size_t c = 0; c < m.contacts.size(); ++c)
    if (m.contacts[c].name == name && !m.contacts[c].is_reverse_pass()) return static_cast<int>(c);
  return -1;
}

}  // namespace tunica::test
