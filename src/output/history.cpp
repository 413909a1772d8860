#include "output/history.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace tunica {

namespace {

double reduce(const std::vector<double>& v, Reduce how) {
  if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
  switch (how) {
    case Reduce::min: return *std::min_element(v.begin(), v.end());
    case Reduce::max: return *std::max_element(v.begin(), v.end());
    case Reduce::sum: {
      double s = 0;
      for (double x : v) s += x;
      return s;
    }
    case Reduce::mean: break;
  }
  double s = 0;
  for (double x : v) s += x;
  return s / static_cast<double>(v.size());
}

/// Axisymmetric cylindrical quantities of a membrane point (its Cauchy tensor in the meridian
/// plane θ = 0: x = r, y = hoop, z = z); `found` is false if `q` is not one of them.
double cylindrical_value(const Eigen::Matrix3d& c, const std::string& q, bool& found) {
  found = true;
  if (q == "sigma_rr") return c(0, 0);
  if (q == "sigma_thetatheta") return c(1, 1);
  if (q == "sigma_zz") return c(2, 2);
  if (q == "sigma_rz") return c(0, 2);
  if (q == "hydrostatic_pressure") return -c.trace() / 3.0;
  if (q == "volume_ratio") return 1.0;
  found = false;
  return 0;
}

double point_value(const SolidPoint& p, const std::string& q) {
  if (q == "sigma_rr") return p.sigma(0);
  if (q == "sigma_zz") return p.sigma(1);
  if (q == "sigma_thetatheta") return p.sigma(2);
  if (q == "sigma_rz") return p.sigma(3);
  if (q == "hydrostatic_pressure") return -(p.sigma(0) + p.sigma(1) + p.sigma(2)) / 3.0;
  if (q == "volume_ratio") return p.J;
  if (q == "radius") return p.r;
  throw std::logic_error("unknown solid quantity " + q);
}

double point_value(const MembranePoint& p, const std::string& q) {
  bool cylindrical = false;
  if (const double v = cylindrical_value(p.cauchy, q, cylindrical); cylindrical) return v;
  if (q == "lambda_1") return p.lambda(0);
  if (q == "lambda_2") return p.lambda(1);
  if (q == "lambda_3") return p.lambda(2);
  if (q == "E_1") return p.E(0);
  if (q == "E_2") return p.E(1);
  if (q == "E_12") return p.E(2);
  if (q == "S_1") return p.S(0);
  if (q == "S_2") return p.S(1);
  if (q == "S_12") return p.S(2);
  if (q == "sigma_1") return p.sigma(0);
  if (q == "sigma_2") return p.sigma(1);
  if (q == "sigma_max") return p.sigma_principal(0);
  if (q == "sigma_min") return p.sigma_principal(1);
  if (q == "thickness") return p.thickness;
  if (q == "radius") return p.r;
  if (q == "M_1") return p.moment(0);
  if (q == "M_2") return p.moment(1);
  if (q == "sigma_1_outer") return p.sigma_outer(0);
  if (q == "sigma_1_inner") return p.sigma_inner(0);
  if (q == "sigma_2_outer") return p.sigma_outer(1);
  if (q == "sigma_2_inner") return p.sigma_inner(1);
  throw std::logic_error("unknown element quantity " + q);
}

/// Node quantities `<what>_<dof>`: position, displacement, reaction; shell nodes also slope_<r|z>
/// (x′ = X′ + u′) and reaction_slope_<r|z> (the reaction of a prescribed slope unknown).
double node_value(const Analysis& a, int node, const std::string& q) {
  const Model& m = a.model();
  if (const auto s = q.find("slope_"); s != std::string::npos) {
    const int c = q.back() == 'r' ? 0 : 1;
    const int d = m.node_dof(node, m.dofs_per_node() + c);
    return s == 0 ? m.slope_ref[node](c) + a.displacement()(d) : a.reactions()(d);
  }
  const auto names = m.dof_names();
  const std::string dof = q.substr(q.rfind('_') + 1);
  const int c = static_cast<int>(std::find(names.begin(), names.end(), dof) - names.begin());
  if (c >= static_cast<int>(names.size())) throw std::logic_error("no DOF " + dof + " in this model");
  const int d = m.dofs_per_node() * node + c;
  const Eigen::VectorXd& u = a.displacement();
  if (q.rfind("position_", 0) == 0) return m.X[node](c) + u(d);
  if (q.rfind("displacement_", 0) == 0) return u(d);
  if (q.rfind("reaction_", 0) == 0) return a.reactions()(d);
  throw std::logic_error("unknown node quantity " + q);
}

}  // namespace

std::vector<double> history_values(const Analysis& a, const IncrementInfo& info) {
  const Model& m = a.model();
  std::vector<double> out;
  std::vector<std::vector<MembranePoint>> points(m.parts.size());
  std::vector<std::vector<SolidPoint>> solid_points(m.parts.size());
  for (const auto& r : m.output.history) {
    double v = 0;
    if (r.quantity == "time") {
      v = info.time;
    } else if (r.load >= 0) {
      v = r.quantity == "volume" ? a.loads().volume[r.load] : a.loads().pressure[r.load];
    } else if (r.contact >= 0) {
      std::vector<double> vals;
      for (const auto& c : a.system().contact_states(a.displacement(), r.contact, a.loads().step))
        vals.push_back(r.quantity == "contact_force"         ? c.force
                       : r.quantity == "contact_penetration" ? std::max(-c.point.gap, 0.0)
                                                             : c.pressure);
      v = reduce(vals, r.reduce);
    } else if (r.part >= 0 && m.parts[r.part].is_solid()) {
      if (solid_points[r.part].empty()) solid_points[r.part] = a.system().solid_points(a.displacement(), r.part);
      std::vector<double> vals;
      for (const auto& p : solid_points[r.part]) vals.push_back(point_value(p, r.quantity));
      v = reduce(vals, r.reduce);
    } else if (r.part >= 0) {
      if (points[r.part].empty()) points[r.part] = a.system().points(a.displacement(), r.part);
      std::vector<double> vals;
      for (const auto& p : points[r.part]) vals.push_back(point_value(p, r.quantity));
      v = reduce(vals, r.reduce);
    } else {
      std::vector<double> vals;
      for (int n : m.node_sets[r.node_set].nodes) vals.push_back(node_value(a, n, r.quantity));
      v = reduce(vals, r.reduce);
    }
    out.push_back(m.units.from_internal(v, r.unit, r.dim));
  }
  return out;
}

}  // namespace tunica
