#include "model/frame_axis_check.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <cmath>

namespace tunica {

std::vector<FrameMisfit> frame_axis_warnings(const Model& m) {
  std::vector<FrameMisfit> out;
  if (m.geometry == Geometry::axisymmetric) return out;
  for (int index = 0; index < static_cast<int>(m.parts.size()); ++index) {
    const Part& part = m.parts[index];
    if (part.frame.type != FrameRule::Type::cylindrical || !part.material || part.material->isotropic()) continue;
    const Eigen::Vector3d a = part.frame.axis, p = part.frame.point;
    double area = 0, off = 0;
    Eigen::Matrix3d normals = Eigen::Matrix3d::Zero();  // Σ A n nᵀ
    for (const ElementBlock& b : part.blocks) {
      if (!is_surface_kind(b.kind)) continue;
      const int corners = corner_nodes(b.kind);
      for (int e = 0; e < b.size(); ++e) {
        const int* n = b.element(e);
        // Area vector of the corners' polygon (a triangle, or a quadrilateral by its diagonals).
        const Eigen::Vector3d av = corners == 4 ? 0.5 * (m.X[n[2]] - m.X[n[0]]).cross(m.X[n[3]] - m.X[n[1]])
                                                : 0.5 * (m.X[n[1]] - m.X[n[0]]).cross(m.X[n[2]] - m.X[n[0]]);
        const double A = av.norm();
        if (!(A > 0)) continue;
        const Eigen::Vector3d normal = av / A;
        Eigen::Vector3d centre = Eigen::Vector3d::Zero();
        for (int k = 0; k < corners; ++k) centre += m.X[n[k]];
        centre /= corners;
        const Eigen::Vector3d c = a.cross(centre - p);
        const bool out_of_plane = c.norm() > 0 && std::abs(c.normalized().dot(normal)) > 0.5;  // sin 30°
        const bool along_normal = std::abs(a.dot(normal)) > std::sqrt(3.0) / 2;                 // cos 30°
        area += A;
        if (out_of_plane || along_normal) off += A;
        normals += A * normal * normal.transpose();
      }
    }
    if (!(area > 0) || off <= 0.2 * area) continue;
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(normals);
    Eigen::Vector3d best = eig.eigenvectors().col(0);
    if (best(best.cwiseAbs().maxCoeff() == std::abs(best.x()) ? 0 : best.cwiseAbs().maxCoeff() == std::abs(best.y()) ? 1 : 2) < 0)
      best = -best;
    const auto round = [](double v) { return std::abs(v) < 5e-4 ? 0.0 : v; };
    out.push_back({index, fmt::format(
        "part '{}': its cylindrical frame (axis [{:.4g}, {:.4g}, {:.4g}] through ({:.4g}, {:.4g}, {:.4g})) does not fit the "
        "surface over {:.0f} % of its area: there the circumferential direction about that axis stands more than 30° out "
        "of the surface, or the axis within 30° of the normal, so the fibre directions are not the ones meant. The "
        "surface's normals are most nearly perpendicular to [{:.3g}, {:.3g}, {:.3g}] (a tube's axis): give the vessel's "
        "axis as `axis` and a point on it as `point`",
        part.name, a.x(), a.y(), a.z(), p.x(), p.y(), p.z(), 100 * off / area, round(best.x()), round(best.y()),
        round(best.z()))});
  }
  return out;
}

}  // namespace tunica
