#include "io/deck_fingerprint.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <cstring>

namespace tunica {

namespace {

/// Values longer than this are recorded as a digest.
constexpr std::size_t kLongestValue = 160;

/// FNV-1a, 64 bits: a digest for change detection, not for security.
class Digest {
public:
  void add(const void* data, std::size_t n) {
    const auto* b = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < n; ++i) h_ = (h_ ^ b[i]) * 0x100000001b3ULL;
  }
  void add(double x) { add(&x, sizeof x); }
  void add(long x) { add(&x, sizeof x); }
  std::string text() const { return fmt::format("digest {:016x}", h_); }

private:
  std::uint64_t h_ = 0xcbf29ce484222325ULL;
};

using Places = std::map<std::string, std::pair<int, int>>;

void place(Places* places, const std::string& key, const DeckNode& node) {
  if (!places) return;
  const SourceLocation w = node.where();
  if (w.line > 0) places->emplace(key, std::make_pair(w.line, w.column));
}

void flatten(const DeckNode& node, const std::string& key, int step, std::vector<FingerprintEntry>& out,
             Places* places) {
  place(places, key, node);
  if (!node.defined()) {
    out.push_back({key, "", step});
  } else if (node.is_scalar()) {
    std::string v = node.yaml().Scalar();
    if (v.size() > kLongestValue) {
      Digest d;
      d.add(v.data(), v.size());
      v = d.text();
    }
    out.push_back({key, v, step});
  } else if (node.is_map()) {
    for (const auto& [k, child] : node.entries()) flatten(child, key + "." + k, step, out, places);
  } else if (node.is_sequence()) {
    const auto items = node.items();
    if (items.empty()) out.push_back({key, "[]", step});
    for (std::size_t i = 0; i < items.size(); ++i) flatten(items[i], fmt::format("{}[{}]", key, i), step, out, places);
  }
}

}  // namespace

std::vector<FingerprintEntry> deck_fingerprint(const DeckNode& deck, const Model& m, Places* places) {
  std::vector<FingerprintEntry> out;
  for (const char* section : {"units", "materials", "parts", "node_sets", "boundary", "loads", "rigid_surfaces", "contact"})
    if (deck.has(section)) flatten(deck[section], section, -1, out, places);
  if (deck.has("steps") && deck["steps"].is_sequence()) {
    place(places, "steps", deck["steps"]);
    const auto steps = deck["steps"].items();
    for (std::size_t k = 0; k < steps.size(); ++k) {
      if (!steps[k].is_map()) continue;
      place(places, fmt::format("steps[{}]", k), steps[k]);
      for (const auto& [key, child] : steps[k].entries())
        if (key != "solver" && key != "name")
          flatten(child, fmt::format("steps[{}].{}", k, key), static_cast<int>(k), out, places);
    }
  }
  if (deck.has("output")) place(places, "output", deck["output"]);
  for (const char* key : {"history", "vtk_fields"})
    if (deck.has("output") && deck["output"].has(key))
      flatten(deck["output"][key], std::string("output.") + key, -1, out, places);
  // The mesh data the keys only name (a file, a generator's output).
  for (const Part& p : m.parts) {
    Digest d;
    for (const ElementBlock& b : p.blocks) {
      d.add(static_cast<long>(b.kind));
      for (int n : b.nodes) {
        d.add(static_cast<long>(n));
        for (int c = 0; c < 3; ++c) d.add(m.X[n](c));
      }
    }
    out.push_back({"parts." + p.name + " (its mesh: node positions and elements)", d.text(), -1});
    // Where the mesh is given: the part's `mesh`, else the part.
    if (places) {
      const auto at = places->find("parts." + p.name + ".mesh");
      const auto part = places->find("parts." + p.name);
      if (at != places->end() || part != places->end()) places->emplace(out.back().key, (at != places->end() ? at : part)->second);
    }
  }
  for (const NodeSet& s : m.node_sets) {
    Digest d;
    for (int n : s.nodes) d.add(static_cast<long>(n));
    out.push_back({"node set " + s.name + " (its nodes)", d.text(), -1});
    // A set of the deck's `node_sets`, or one a part's mesh makes (`wall.start`: part `wall`).
    if (places) {
      auto at = places->find("node_sets." + s.name);
      if (at == places->end() && s.name.find('.') != std::string::npos)
        at = places->find("parts." + s.name.substr(0, s.name.find('.')) + ".mesh");
      if (at != places->end()) places->emplace(out.back().key, at->second);
    }
  }
  return out;
}

}  // namespace tunica
