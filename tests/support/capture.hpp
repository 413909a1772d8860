#pragma once
// Runs a deck in-process and keeps what a run reports: the history values
// after each converged increment and every Newton iteration.
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "io/deck.hpp"
#include "output/history.hpp"
#include "solver/analysis.hpp"

namespace tunica::test {

struct Row {
  IncrementInfo info;
  std::vector<double> values;  ///< per model.output.history
};

struct Iteration {
  IncrementInfo info;
  IterationRecord rec;
};

class Capture final : public AnalysisObserver {
public:
  std::vector<Row> rows;
  std::vector<Iteration> iterations;
  int cutbacks = 0;
  void on_iteration(const IncrementInfo& i, const IterationRecord& r) override { iterations.push_back({i, r}); }
  std::vector<std::pair<IncrementInfo, std::string>> retries;  ///< attempt and how it was retried
  void on_cutback(const IncrementInfo&, const std::string&) override { ++cutbacks; }
  void on_retry(const IncrementInfo& i, const std::string&, const std::string& how) override { retries.emplace_back(i, how); }
  void on_increment(const Analysis& a, const IncrementInfo& i) override { rows.push_back({i, history_values(a, i)}); }
  /// Index of a history column by name.
  static int column(const Model& m, const std::string& name) {
    for (std::size_t k = 0; k < m.output.history.size(); ++k)
      if (m.output.history[k].column == name) return static_cast<int>(k);
    throw std::runtime_error("no history column " + name);
  }
};

inline std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

/// Replaces the first occurrence of `from` in `text` (which must occur).
inline std::string replace(std::string text, const std::string& from, const std::string& to) {
  const auto pos = text.find(from);
  if (pos == std::string::npos) throw std::runtime_error("text to replace not found: " + from);
  return text.replace(pos, from.size(), to);
}

}  // namespace tunica::test
