#include "io/deck_node.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <map>

#include "core/suggest.hpp"

namespace tunica {

SourceLocation DeckNode::where() const {
  if (node_.IsDefined() && !node_.Mark().is_null()) {
    const auto m = node_.Mark();
    return {file_, m.line + 1, m.column + 1, path_};
  }
  SourceLocation w = parent_;
  w.file = file_;
  w.key = path_;
  return w;
}

void DeckNode::fail(const std::string& what) const { throw InputError(where(), what); }

bool DeckNode::has(const std::string& key) const {
  if (!node_.IsMap()) return false;
  const YAML::Node c = node_[key];
  return c.IsDefined();
}

DeckNode DeckNode::operator[](const std::string& key) const {
  const std::string p = path_.empty() ? key : path_ + "." + key;
  SourceLocation here = where();
  if (!node_.IsMap()) return DeckNode(YAML::Node(YAML::NodeType::Undefined), file_, p, here);
  return DeckNode(node_[key], file_, p, here);
}

DeckNode DeckNode::required(const std::string& key, const std::string& fix) const {
  if (!node_.IsMap()) fail("expected a map (key: value entries) containing '" + key + "'");
  DeckNode c = (*this)[key];
  if (!c.yaml().IsDefined()) {
    SourceLocation w = where();
    w.key = c.path();
    throw InputError(w, "missing required key '" + key + "'" + fix);
  }
  if (c.yaml().IsNull()) c.fail("key '" + key + "' has no value");
  return c;
}

std::vector<DeckNode> DeckNode::items() const {
  if (!node_.IsSequence()) fail("expected a list");
  std::vector<DeckNode> out;
  for (std::size_t i = 0; i < node_.size(); ++i)
    out.emplace_back(node_[i], file_, path_ + "[" + std::to_string(i) + "]", where());
  return out;
}

void DeckNode::expect_unique_keys() const {
  std::map<std::string, int> seen;
  for (auto it = node_.begin(); it != node_.end(); ++it) {
    if (!it->first.IsScalar()) DeckNode(it->first, file_, path_, where()).fail("map keys must be plain names");
    const std::string k = it->first.Scalar();
    const int line = it->first.Mark().is_null() ? 0 : it->first.Mark().line + 1;
    auto [first, fresh] = seen.emplace(k, line);
    if (!fresh)
      DeckNode(it->first, file_, path_.empty() ? k : path_ + "." + k, where())
          .fail("duplicate key '" + k + "' (first given on line " + std::to_string(first->second) + ")");
  }
}

std::vector<std::pair<std::string, DeckNode>> DeckNode::entries() const {
  if (!node_.IsMap()) fail("expected a map (key: value entries)");
  expect_unique_keys();
  std::vector<std::pair<std::string, DeckNode>> out;
  for (auto it = node_.begin(); it != node_.end(); ++it) {
    const std::string k = it->first.Scalar();
    out.emplace_back(k, DeckNode(it->second, file_, path_.empty() ? k : path_ + "." + k, where()));
  }
  return out;
}

void DeckNode::expect_map_with_keys(const std::vector<std::string>& allowed) const {
  if (!node_.IsMap()) fail("expected a map (key: value entries)");
  expect_unique_keys();
  for (auto it = node_.begin(); it != node_.end(); ++it) {
    const std::string k = it->first.IsScalar() ? it->first.Scalar() : std::string("?");
    if (std::find(allowed.begin(), allowed.end(), k) == allowed.end()) {
      std::string list;
      for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
      DeckNode(it->first, file_, path_.empty() ? k : path_ + "." + k, where())
          .fail("unknown key '" + k + "' (allowed here: " + list + ")" + did_you_mean(k, allowed));
    }
  }
}

std::string DeckNode::as_string() const {
  if (!node_.IsScalar()) fail("expected a single value, not a list or a map");
  return node_.Scalar();
}

long DeckNode::as_integer() const {
  const std::string s = as_string();
  char* end = nullptr;
  errno = 0;
  const long v = std::strtol(s.c_str(), &end, 10);
  if (s.empty() || *end != '\0' || errno == ERANGE) fail("expected an integer, got '" + s + "'");
  return v;
}

bool DeckNode::as_bool() const {
  const std::string s = as_string();
  if (s == "true" || s == "yes" || s == "on") return true;
  if (s == "false" || s == "no" || s == "off") return false;
  fail("expected true or false, got '" + s + "'");
}

}  // namespace tunica
