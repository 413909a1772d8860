#include "solver/contact_chatter.hpp"

#include <algorithm>

namespace tunica {

double mean_segment(const Model& m, const std::vector<int>& chain) {
  if (chain.size() < 2) return 0;
  double length = 0;
  for (std::size_t i = 0; i + 1 < chain.size(); ++i) length += (m.X[chain[i + 1]] - m.X[chain[i]]).norm();
  return length / static_cast<double>(chain.size() - 1);
}

int part_of_chain(const Model& m, const std::vector<int>& chain) {
  if (chain.empty()) return -1;
  for (std::size_t p = 0; p < m.parts.size(); ++p) {
    const Part& part = m.parts[p];
    if (part.is_solid()) continue;
    if (std::find(part.nodes.begin(), part.nodes.end(), chain.front()) != part.nodes.end()) return static_cast<int>(p);
  }
  return -1;
}

std::vector<int> contact_pairs_in_play(const Model& m, int step_index) {
  std::vector<int> pairs;
  for (std::size_t c = 0; c < m.contacts.size(); ++c) {
    const ContactPair& pair = m.contacts[c];
    if (pair.is_reverse_pass()) continue;
    if (pair.part >= 0 && !m.part_active(pair.part, step_index)) continue;
    if (const int master = part_of_chain(m, pair.master); master >= 0 && !m.part_active(master, step_index)) continue;
    pairs.push_back(static_cast<int>(c));
  }
  return pairs;
}

bool contact_near(const System& system, const Eigen::VectorXd& u, int c, int step_index) {
  const Model& m = system.model();
  const double length = mean_segment(m, m.contacts[c].area_chain);
  for (const ContactNodeState& s : system.contact_states(u, c, step_index))
    if (s.point.normal.squaredNorm() > 0 && s.point.gap < length) return true;
  return false;
}

std::vector<int> pairs_to_smooth(const System& system, const Eigen::VectorXd& u, int step_index,
                                 const NewtonResult& last) {
  std::vector<int> out;
  if (last.active_set_changes < kContactChatterIterations) return out;
  const Model& m = system.model();
  for (int c : contact_pairs_in_play(m, step_index)) {
    const ContactPair& pair = m.contacts[c];
    if (!pair.auto_smoothing || pair.law.smoothing > 0 || pair.area_chain.size() < 2) continue;
    if (contact_near(system, u, c, step_index)) out.push_back(c);
  }
  return out;
}

double auto_smoothing_width(const Model& m, int c) {
  return kAutoSmoothingShare * mean_segment(m, m.contacts[c].area_chain);
}

}  // namespace tunica
