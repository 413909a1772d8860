#pragma once
// A YAML node together with the file it came from and its dotted key path, so
// that every error can name the file, the line and the key.
#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

#include "core/errors.hpp"

namespace tunica {

class DeckNode {
public:
  DeckNode() = default;
  DeckNode(YAML::Node node, std::string file, std::string path, SourceLocation parent = {})
      : node_(std::move(node)), file_(std::move(file)), path_(std::move(path)), parent_(std::move(parent)) {}

  const YAML::Node& yaml() const { return node_; }
  const std::string& file() const { return file_; }
  const std::string& path() const { return path_; }
  bool defined() const { return node_.IsDefined() && !node_.IsNull(); }
  bool is_map() const { return node_.IsMap(); }
  bool is_sequence() const { return node_.IsSequence(); }
  bool is_scalar() const { return node_.IsScalar(); }

  /// Location of this node (of its parent map when the node is missing).
  SourceLocation where() const;
  /// Throws an InputError at this node.
  [[noreturn]] void fail(const std::string& what) const;

  bool has(const std::string& key) const;
  /// The child at `key` (may be undefined; where() then points at this map).
  DeckNode operator[](const std::string& key) const;
  /// The child at `key`; error "missing required key '<key>'" if absent, followed by `fix`
  /// (": add ...", or " (what it is): add ...").
  DeckNode required(const std::string& key, const std::string& fix = "") const;
  /// Elements of a sequence.
  std::vector<DeckNode> items() const;
  /// (key, value) pairs of a map, in file order.
  std::vector<std::pair<std::string, DeckNode>> entries() const;
  /// Errors on a key given twice in this map (YAML parsers keep one silently).
  void expect_unique_keys() const;
  /// Errors unless this is a map; errors on any key not in `allowed` or given twice.
  void expect_map_with_keys(const std::vector<std::string>& allowed) const;

  /// Scalar as text; errors if not a scalar.
  std::string as_string() const;
  /// Scalar as an integer; errors otherwise.
  long as_integer() const;
  /// Scalar as a boolean; errors otherwise.
  bool as_bool() const;

private:
  YAML::Node node_;
  std::string file_, path_;
  SourceLocation parent_;
};

}  // namespace tunica
