#include "model/model.hpp"

#include <stdexcept>
#include <string>

namespace tunica {

int Model::find_node_set(const std::string& name) const {
  for (std::size_t i = 0; i < node_sets.size(); ++i)
    if (node_sets[i].name == name) return static_cast<int>(i);
  return -1;
}

int Model::find_part(const std::string& name) const {
  for (std::size_t i = 0; i < parts.size(); ++i)
    if (parts[i].name == name) return static_cast<int>(i);
  return -1;
}

void Model::number_slope_dofs() {
  slope_dof.clear();
  slope_ref.clear();
  num_slope_nodes = 0;
  bool any = false;
  for (const auto& part : parts) any = any || part.is_shell();
  if (!any) return;
  slope_dof.assign(num_nodes(), -1);
  slope_ref.assign(num_nodes(), Eigen::Vector2d::Zero());
  const int first = dofs_per_node() * num_nodes();
  for (const auto& part : parts) {
    if (!part.is_shell()) continue;
    for (std::size_t i = 0; i < part.nodes.size(); ++i) {
      const int n = part.nodes[i];
      if (slope_dof[n] < 0) slope_dof[n] = first + 2 * num_slope_nodes++;
      slope_ref[n] = part.tangents[i];
    }
  }
}

const std::vector<std::string>& vtk_field_names(Geometry g) {
  static const std::vector<std::string> axisymmetric = {
      "displacement", "contact_pressure", "lambda_hoop", "lambda_meridional", "lambda_thickness", "S_hoop",
      "S_meridional", "sigma_hoop", "sigma_meridional", "thickness", "part", "sigma_rr", "sigma_thetatheta",
      "sigma_zz", "sigma_rz", "hydrostatic_pressure", "J", "M_hoop", "M_meridional", "sigma_hoop_outer",
      "sigma_hoop_inner", "sigma_meridional_outer", "sigma_meridional_inner"};
  static const std::vector<std::string> three_d = {
      "displacement", "lambda_1", "lambda_2", "lambda_3", "E_1", "E_2", "E_12", "S_1", "S_2", "S_12", "sigma_1",
      "sigma_2", "sigma_max", "sigma_min", "thickness", "part", "direction_1", "direction_2", "cauchy_stress",
      "compressed"};
  return g == Geometry::axisymmetric ? axisymmetric : three_d;
}

}  // namespace tunica
