#pragma once
// An axisymmetric membrane node on the axis (a pole, R = 0) whose radial DOF nothing holds. The
// membrane there has no hoop stiffness against leaving the axis (the hoop stretch r/R of its
// neighbouring Gauss points barely sees it), so the pole drifts off the axis by round-off and the
// stresses near it change with it; a pole must hold r (user guide §3.1).
#include <string>
#include <vector>

#include "model/model.hpp"

namespace tunica {

struct PoleMisfit {
  int part = -1;
  int node = -1;
  std::string message;  ///< names the node, its part and a node set to hold r on
};

/// One per node of an axisymmetric membrane part that lies on the axis (R ≤ 10⁻⁹ of the model's
/// size) and whose r no boundary condition prescribes.
std::vector<PoleMisfit> free_pole_warnings(const Model& m);

}  // namespace tunica
