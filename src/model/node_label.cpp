#include "model/node_label.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>

namespace tunica {

std::string node_label(const Model& m, int node) {
  const long tag = node >= 0 && node < static_cast<int>(m.node_tags.size()) ? m.node_tags[node] : 0;
  for (const Part& part : m.parts) {
    if (tag != 0)
      for (const ElementBlock& b : part.blocks)
        if (!b.file.empty() && std::find(b.nodes.begin(), b.nodes.end(), node) != b.nodes.end())
          return fmt::format("node {} of {}", tag, std::filesystem::path(b.file).filename().string());
    const auto it = std::find(part.nodes.begin(), part.nodes.end(), node);
    if (tag == 0 && it != part.nodes.end()) return fmt::format("node {} of part '{}'", it - part.nodes.begin(), part.name);
  }
  return fmt::format("node {}", tag != 0 ? tag : node);
}

}  // namespace tunica
