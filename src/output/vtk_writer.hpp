#pragma once
// ParaView output. Axisymmetric models: the meridian as line cells in the
// (x = r, z) plane (solid parts: their quadrilaterals), and the model revolved
// about the z axis: membranes as a 3-D surface of quadrilaterals, solids as
// hexahedra; cell data include the cylindrical Cauchy components for all parts. 3-D models: the membrane surface (triangles and
// quadrilaterals) with cell-averaged strains and stresses in the material frame,
// the principal Cauchy stresses, the Cauchy tensor and the material directions.
// One .vtu per frame (output.vtk_every) and a .pvd series of each.
#include <string>
#include <vector>

#include "solver/analysis.hpp"

namespace tunica {

/// The meridian (lines; solids: quadrilaterals) at the current state as VTK XML UnstructuredGrid text.
std::string meridian_vtu(const Analysis& analysis, VtkFormat format = VtkFormat::compressed);
/// The revolved model (membrane quads, solid hexahedra, `segments` around the axis) as VTK XML text.
std::string surface_vtu(const Analysis& analysis, int segments, VtkFormat format = VtkFormat::compressed);

/// The surface of a 3-D model at the current state as VTK XML text.
std::string surface3d_vtu(const Analysis& analysis, VtkFormat format = VtkFormat::compressed);

/// A ParaView .pvd collection is pvd_head(), one pvd_entry per dataset, pvd_tail(): the series
/// grows by writing the new entry and the tail over the old tail (output/append_file.hpp).
std::string pvd_head();
std::string pvd_tail();
/// One dataset (path relative to the .pvd) at `time`.
std::string pvd_entry(double time, const std::string& relative_file);

}  // namespace tunica
