#pragma once
// The history quantities (`output.history`): one table pairing each name with what it is
// recorded over (a part's Gauss points, a node set, a load, a contact pair's slave nodes), its
// dimension, its meaning, where it applies, its default reduction and its evaluator. The deck
// reader checks requests against it (io/deck.cpp), history.csv evaluates it
// (output/history.cpp) and the deck reference lists it (io/reference.cpp).
#include <Eigen/Dense>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "assembly/system.hpp"

namespace tunica {

/// The converged state quantities are evaluated at.
struct QuantityState {
  const System& system;
  const Eigen::VectorXd& u;          ///< displacements, all DOFs
  const Eigen::VectorXd& reactions;  ///< all DOFs
  const LoadState& loads;
  double time = 0;                   ///< step − 1 + fraction of the step done
};

/// What a quantity is recorded over: the deck key that names it ("" for none).
enum class QuantityTarget { none, part, node_set, load, contact };
const char* target_key(QuantityTarget t);

struct HistoryQuantity {
  std::string name;
  QuantityTarget target = QuantityTarget::none;
  Dimension dim = Dimension::dimensionless;
  std::string doc;
  Reduce reduce = Reduce::mean;       ///< default reduction over the target's points, nodes or slave nodes
  std::optional<Geometry> geometry;   ///< only models of this geometry
  bool shells_only = false;           ///< only axisymmetric_shell parts (part), only shell nodes (node_set)
  // The evaluator of its target (the others empty):
  std::function<double(const QuantityState&)> global;               ///< none
  std::function<double(const QuantityState&, int)> at;              ///< load: the load's index; node_set: a node
  std::function<double(const MembranePoint&)> membrane;             ///< part: membrane and shell points (empty: not on them)
  /// part: a value of all of the part's membrane and shell points at once (its `reduce` unused)
  std::function<double(const std::vector<MembranePoint>&)> membrane_whole;
  std::function<double(const SolidPoint&)> solid;                   ///< part: solid points (empty: not on solids)
  std::function<double(const ContactNodeState&)> contact;           ///< contact: a slave node
};

/// Every history quantity, in the order of the deck reference.
const std::vector<HistoryQuantity>& history_quantities();
/// The quantity of that name, or nullptr.
const HistoryQuantity* find_history_quantity(const std::string& name);

/// For a name that writes the direction of a directional quantity by its usual name rather than
/// by its number in the part's frame (S_z, lambda_theta, sigma_hoop_outer, cauchy_axial,
/// E_theta_z; 1 = circumferential, 2 = axial or meridional, 3 = the thickness): "; did you mean
/// 'S_2' (direction 2 of the part's frame: …)?", the direction described for models of
/// `geometry`. "" for a name that does not map so onto a quantity.
std::string direction_name_suggestion(const std::string& name, Geometry geometry);

}  // namespace tunica
