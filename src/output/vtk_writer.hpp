#pragma once
// ParaView output. Axisymmetric models: the meridian as line cells in the
// (x = r, z) plane (solid parts: their quadrilaterals), and the model revolved
// about the z axis: membranes as a 3-D surface of quadrilaterals, solids as
// hexahedra; cell data include the cylindrical Cauchy components for all parts. 3-D models: the membrane surface (triangles and
// quadrilaterals) with cell-averaged strains and stresses in the material frame,
// the principal Cauchy stresses, the Cauchy tensor and the material directions.
// One .vtu per increment and a .pvd series of each.
#include <string>
#include <vector>

#include "solver/analysis.hpp"

namespace tunica {

/// The meridian (lines; solids: quadrilaterals) at the current state as VTK XML UnstructuredGrid text.
std::string meridian_vtu(const Analysis& analysis);
/// The revolved model (membrane quads, solid hexahedra, `segments` around the axis) as VTK XML text.
std::string surface_vtu(const Analysis& analysis, int segments);

/// The surface of a 3-D model at the current state as VTK XML text.
std::string surface3d_vtu(const Analysis& analysis);

/// A ParaView .pvd collection that lists one dataset per time value.
class PvdSeries {
public:
  explicit PvdSeries(std::string path) : path_(std::move(path)) {}
  /// Lists datasets already written (when a run resumes) without rewriting the .pvd.
  void preload(double time, const std::string& relative_file) { entries_.emplace_back(time, relative_file); }
  /// Adds a dataset (path relative to the .pvd) and rewrites the .pvd atomically.
  void add(double time, const std::string& relative_file);

private:
  std::string path_;
  std::vector<std::pair<double, std::string>> entries_;
};

}  // namespace tunica
