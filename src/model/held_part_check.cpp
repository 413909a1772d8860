#include "model/held_part_check.hpp"

#include <fmt/format.h>

namespace tunica {

std::vector<HeldPart> held_part_warnings(const Model& m) {
  std::vector<HeldPart> out;
  const int dim = m.dofs_per_node();
  // Per node, the translational DOFs some boundary holds (bit d).
  std::vector<unsigned> held(m.num_nodes(), 0);
  for (const Boundary& b : m.boundaries)
    for (int d : b.dofs)
      if (d < dim)
        for (int n : m.node_sets[b.node_set].nodes) held[n] |= 1u << d;
  const unsigned all = (1u << dim) - 1;
  for (int p = 0; p < static_cast<int>(m.parts.size()); ++p) {
    const Part& part = m.parts[p];
    if (part.nodes.size() < 2) continue;
    bool every = true;
    for (int n : part.nodes) every = every && held[n] == all;
    if (!every) continue;
    // A part held whole on purpose: a fixed tool that a contact pair presses on, with no load of its own.
    bool loaded = false, in_contact = false;
    for (const PressureLoad& l : m.loads) loaded = loaded || l.part == p;
    std::vector<char> on_part(m.num_nodes(), 0);
    for (int n : part.nodes) on_part[n] = 1;
    for (const ContactPair& c : m.contacts) {
      for (int n : c.nodes) in_contact = in_contact || on_part[n];
      for (int n : c.master) in_contact = in_contact || on_part[n];
    }
    if (in_contact && !loaded) continue;
    // The boundaries on its nodes, and the one holding the most of them.
    std::string names;
    int most = -1;
    std::size_t most_count = 0;
    for (int b = 0; b < static_cast<int>(m.boundaries.size()); ++b) {
      std::size_t count = 0;
      for (int n : m.node_sets[m.boundaries[b].node_set].nodes) count += on_part[n];
      if (count == 0) continue;
      names += (names.empty() ? "'" : ", '") + m.boundaries[b].name + "'";
      if (count > most_count) most_count = count, most = b;
    }
    const std::vector<std::string> dofs = m.dof_names();
    std::string list;
    for (int d = 0; d < dim; ++d) list += (d == 0 ? "" : ", ") + dofs[d];
    out.push_back({p, most,
                   fmt::format("every node of part '{}' is held in every DOF ({}) by boundary {}: the part cannot "
                               "deform, a load on it does nothing and its results stay those of the reference "
                               "state (a boundary's value moves all its nodes alike). Hold only what the model "
                               "needs: {} and the DOFs a symmetry plane fixes",
                               part.name, list, names,
                               part.element == "axisymmetric_membrane" || part.is_shell()
                                   ? fmt::format("the ends ('{0}.start', '{0}.end')", part.name)
                                   : std::string("the nodes of its edges (a tube's ends) or a few nodes against "
                                                 "rigid motion"))});
  }
  return out;
}

}  // namespace tunica
