#include "model/wall_thickness_check.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "model/meridian_curvature.hpp"
#include "model/surface_curvature.hpp"

namespace tunica {

std::vector<ThicknessMisfit> wall_thickness_misfits(const Model& m) {
  std::vector<ThicknessMisfit> out;
  const std::string unit = m.units.display_unit(Dimension::length);
  const auto in_unit = [&](double v) { return m.units.from_internal(v, unit, Dimension::length); };
  for (std::size_t p = 0; p < m.parts.size(); ++p) {
    const Part& part = m.parts[p];
    if (part.is_solid() || !(part.thickness > 0)) continue;
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
    for (int n : part.nodes) {
      lo = lo.cwiseMin(m.X[n]);
      hi = hi.cwiseMax(m.X[n]);
    }
    if (part.nodes.empty() || !(hi(0) >= lo(0))) continue;
    // An axisymmetric meridian's surface of revolution spans r from −r_max to r_max.
    if (m.geometry == Geometry::axisymmetric) lo(0) = -hi(0);
    const double extent = (hi - lo).norm();
    std::string file;
    for (const ElementBlock& b : part.blocks)
      if (!b.file.empty()) file = b.file;
    const std::string mesh = file.empty() ? "its mesh" : "its mesh (" + file + ")";
    if (part.thickness >= extent) {
      // A mesh file may be in another unit; a generated mesh has the deck's, so the thickness is the suspect.
      const std::string likely =
          file.empty()
              ? std::string("Check the thickness's value and unit (e.g. a wall of 100 µm is `100 um` or `0.1 mm`, "
                            "not `100 mm`): the mesh is generated from the deck's own lengths")
              : fmt::format("Likely {} is written in another length unit than the deck's `units: {{length: {}}}` (a "
                            "mesh in metres read as {} is a thousand times too small): convert the mesh to {}, or "
                            "write the deck in the mesh's unit; else check the thickness's value and unit",
                            mesh, unit, unit, unit);
      out.push_back({static_cast<int>(p), true,
                     fmt::format("part '{}': the thickness {:.4g} {} is at least the whole part's extent, {:.4g} {} "
                                 "(the diagonal of its bounding box{}): no membrane is that thick. {}",
                                 part.name, in_unit(part.thickness), unit, in_unit(extent), unit,
                                 m.geometry == Geometry::axisymmetric ? ", revolved" : "", likely)});
      continue;
    }
    std::vector<double> curvature;
    const auto surface = element_mean_curvature(m, part), meridian = meridian_mean_curvature(m, part);
    for (const auto* all : {&surface, &meridian})
      for (const auto& block : *all)
        for (double h : block)
          if (h != 0) curvature.push_back(std::abs(h));
    if (curvature.empty()) continue;
    const auto mid = curvature.begin() + static_cast<long>(curvature.size() / 2);
    std::nth_element(curvature.begin(), mid, curvature.end());
    const double radius = 1.0 / (2.0 * *mid);  // a tube's radius: H = 1/(2R)
    if (part.thickness > radius)
      out.push_back({static_cast<int>(p), false,
                     fmt::format("part '{}': the thickness {:.4g} {} is {:.2g} times the part's typical radius of "
                                 "curvature, {:.4g} {} (a tube's radius; half a sphere's): a {} model assumes "
                                 "a wall thin against its radius (its error is of order H/2R) where it carries the "
                                 "load. Check the thickness and the mesh's length unit; a thick wall wants a solid "
                                 "model (`axisymmetric_solid`)",
                                 part.name, in_unit(part.thickness), unit, part.thickness / radius, in_unit(radius),
                                 unit, part.is_shell() ? "shell (Kirchhoff–Love)" : "membrane")});
  }
  return out;
}

}  // namespace tunica
