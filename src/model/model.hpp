#pragma once
// The analysis model built from a deck: nodes, parts (element type, material,
// thickness, connectivity), node sets, prescribed displacements, loads, steps
// and output requests. Axisymmetric models have two DOFs per node (u_r, u_z).
#include <Eigen/Dense>
#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "io/units.hpp"
#include "materials/membrane_material.hpp"

namespace tunica {

constexpr int kDofsPerNode = 2;  ///< axisymmetric: (u_r, u_z)

struct Part {
  std::string name;
  std::string element;                     ///< element type name
  const MembraneMaterial* material = nullptr;
  std::string material_name;
  double thickness = 0;                    ///< reference thickness H
  std::vector<std::array<int, 2>> elements;  ///< global node numbers
  std::vector<int> nodes;                  ///< global node numbers along the meridian
};

struct NodeSet {
  std::string name;
  std::vector<int> nodes;
};

/// Prescribed displacement of some DOFs of a node set; its value is ramped
/// linearly within a step towards the target the step sets (0 until set).
struct Boundary {
  std::string name;
  int node_set = -1;
  std::vector<int> dofs;  ///< 0 = r, 1 = z
  SourceLocation where;
};

/// Follower pressure on the surface of a part; its magnitude is ramped like a boundary value.
struct PressureLoad {
  std::string name;
  int part = -1;
  double sign = 1;  ///< −1 when the deck flips the side it acts on
  SourceLocation where;
};

/// Newton and increment-control settings.
struct SolverSettings {
  int max_iterations = 12;
  double residual_tolerance = 1e-9;  ///< on ‖R‖/‖R₀‖
  double energy_tolerance = 1e-15;   ///< on |Δu·R| relative to the first iteration
  int max_cutbacks = 5;
  std::string linear_solver = "umfpack";
};

struct Step {
  std::string name;
  int increments = 1;
  std::map<std::string, double> targets;  ///< boundary or load name → value at the end of the step
  SolverSettings solver;
};

enum class Reduce { mean, min, max, sum };

/// One history column.
struct HistoryRequest {
  std::string column;   ///< name with unit suffix
  std::string quantity;
  int part = -1, node_set = -1, load = -1;
  Reduce reduce = Reduce::mean;
  std::string unit;     ///< output unit ("" = dimensionless)
  Dimension dim = Dimension::dimensionless;
};

struct OutputSettings {
  std::vector<HistoryRequest> history;
  bool vtk = true;
  int vtk_segments = 48;  ///< hoop subdivisions of the revolved surface
};

struct Model {
  std::string deck_file;
  std::string title;
  UnitSystem units;
  std::vector<Eigen::Vector2d> X;  ///< reference node positions (r, z)
  std::map<std::string, std::unique_ptr<MembraneMaterial>> materials;
  std::vector<Part> parts;
  std::vector<NodeSet> node_sets;
  std::vector<Boundary> boundaries;
  std::vector<PressureLoad> loads;
  std::vector<Step> steps;
  OutputSettings output;

  int num_nodes() const { return static_cast<int>(X.size()); }
  int num_dofs() const { return kDofsPerNode * num_nodes(); }
  int find_node_set(const std::string& name) const;
  int find_part(const std::string& name) const;
};

}  // namespace tunica
