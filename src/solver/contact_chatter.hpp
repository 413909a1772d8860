#pragma once
// Contact that does not settle: which pairs of a step are in play, whether their slave nodes are
// near their surfaces, and which pairs get the automatic smoothing of the penalty law (theory
// manual (9.2)) when an increment fails with a chattering active set.
#include <Eigen/Dense>

#include <vector>

#include "assembly/system.hpp"
#include "solver/newton.hpp"

namespace tunica {

/// The contact active set changed at this many iterations of the failed attempt (or more): Newton
/// did not settle which slave nodes touch (chattering).
constexpr int kContactChatterIterations = 3;

/// The smoothing width Tunica switches on by itself, as a share of the slave chain's mean
/// reference element length (theory manual (9.2)).
constexpr double kAutoSmoothingShare = 1e-3;

/// The mean length of a chain's segments at the reference state (0 for fewer than 2 nodes).
double mean_segment(const Model& m, const std::vector<int>& chain);

/// The membrane part that holds the first node of a chain, or −1.
int part_of_chain(const Model& m, const std::vector<int>& chain);

/// The contact pairs of step `step_index` (0-based) whose slave part and master part are active,
/// as the deck names them (reverse passes left out: they belong to their pair).
std::vector<int> contact_pairs_in_play(const Model& m, int step_index);

/// Pair `c` has a slave node within its chain's mean element length of its surface at u.
bool contact_near(const System& system, const Eigen::VectorXd& u, int c, int step_index);

/// The pairs (Model::contacts indices, reverse passes left out) whose penalty law Analysis smooths
/// after the increment failed at its smallest size with `last` (the last attempt) and u the last
/// converged state: the active set changed at kContactChatterIterations or more of the attempt's
/// iterations, and each pair returned is in play, has a slave node near its surface at u, no
/// `smoothing` of its own (ContactPair::auto_smoothing) and none yet. Empty: no retry.
std::vector<int> pairs_to_smooth(const System& system, const Eigen::VectorXd& u, int step_index,
                                 const NewtonResult& last);

/// The automatic smoothing width of pair `c`: kAutoSmoothingShare of its slave chain's mean
/// reference element length.
double auto_smoothing_width(const Model& m, int c);

}  // namespace tunica
