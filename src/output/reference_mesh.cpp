#include "output/reference_mesh.hpp"

#include <fmt/format.h>

#include <cctype>
#include <vector>

namespace tunica {

std::string reference_mesh_name(const Model& m, int step) {
  std::string name = m.steps.at(step).name;
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_') c = '_';
  return "reference_" + name + (m.geometry == Geometry::axisymmetric ? ".csv" : ".msh");
}

std::string reference_mesh_text(const Model& m, const Eigen::VectorXd& u) {
  const int d = m.dofs_per_node();
  const auto X = [&](int n, int c) { return m.X[n](c) + u(d * n + c); };
  std::string out;
  if (m.geometry == Geometry::axisymmetric) {
    const std::string unit = m.units.display_unit(Dimension::length);
    out = "node,R_" + unit + ",Z_" + unit + "\n";
    for (int n = 0; n < m.num_nodes(); ++n) out += fmt::format("{},{:.17g},{:.17g}\n", n + 1, X(n, 0), X(n, 1));
    return out;
  }
  // Physical groups: the parts (dimension 2) first, then the node sets (dimension 0) but a part's
  // `<part>.all`, which the deck makes for every part.
  std::vector<const NodeSet*> sets;
  for (const NodeSet& set : m.node_sets) {
    bool all = false;
    for (const Part& part : m.parts) all = all || set.name == part.name + ".all";
    if (!all) sets.push_back(&set);
  }
  out = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n";
  out += fmt::format("{}\n", m.parts.size() + sets.size());
  for (std::size_t p = 0; p < m.parts.size(); ++p) out += fmt::format("2 {} \"{}\"\n", p + 1, m.parts[p].name);
  for (std::size_t s = 0; s < sets.size(); ++s) out += fmt::format("0 {} \"{}\"\n", m.parts.size() + s + 1, sets[s]->name);
  out += fmt::format("$EndPhysicalNames\n$Nodes\n{}\n", m.num_nodes());
  for (int n = 0; n < m.num_nodes(); ++n) out += fmt::format("{} {:.17g} {:.17g} {:.17g}\n", n + 1, X(n, 0), X(n, 1), X(n, 2));
  std::string elements;
  long count = 0;
  for (std::size_t p = 0; p < m.parts.size(); ++p)
    for (const ElementBlock& b : m.parts[p].blocks) {
      const int type = b.kind == ElementKind::tri3 ? 2 : b.kind == ElementKind::quad4 ? 3 : 9;  // Gmsh element types
      const int nodes = nodes_per_element(b.kind);
      for (int e = 0; e < b.size(); ++e) {
        elements += fmt::format("{} {} 2 {} {}", ++count, type, p + 1, p + 1);
        for (int a = 0; a < nodes; ++a) elements += fmt::format(" {}", b.element(e)[a] + 1);
        elements += "\n";
      }
    }
  for (std::size_t s = 0; s < sets.size(); ++s)
    for (int n : sets[s]->nodes)
      elements += fmt::format("{} 15 2 {} {} {}\n", ++count, m.parts.size() + s + 1, m.parts.size() + s + 1, n + 1);
  out += fmt::format("$EndNodes\n$Elements\n{}\n{}$EndElements\n", count, elements);
  return out;
}

}  // namespace tunica
