#include "contact/rigid_surface.hpp"

namespace tunica {

ContactPoint rigid_cylinder_contact(const RigidCylinder& cylinder, const Eigen::Vector2d& xs, double area,
                                    const ContactLaw& law, Eigen::Vector2d& f, Eigen::Matrix2d* K) {
  const double sigma = cylinder.side == CylinderSide::outside ? 1.0 : -1.0;
  const Eigen::Vector2d n(sigma, 0.0);
  ContactPoint p;
  p.gap = sigma * (xs(0) - cylinder.radius) - law.offset;
  p.normal = n;
  p.active = law.touching(p.gap);
  f.setZero();
  if (K) K->setZero();
  if (!p.active) return p;
  p.pressure = law.pressure(p.gap);
  p.energy = law.energy(p.gap) * area;
  f = -p.pressure * area * n;
  if (K) *K = law.stiffness(p.gap) * area * n * n.transpose();
  return p;
}

ContactPoint rigid_polyline_contact(const RigidPolyline& tool, const Eigen::Vector2d& xs, double area,
                                    const ContactLaw& law, Eigen::Vector2d& f, Eigen::Matrix2d* K,
                                    ChainProjection* where) {
  const Eigen::Matrix2Xd chain = tool.current();
  const ChainProjection proj = project_on_chain(xs, chain);
  if (where) *where = proj;
  ContactVector6 f6;
  ContactMatrix6 K6;
  const ContactPoint p = chain_contact(xs, chain, proj, area, law, f6, K ? &K6 : nullptr);
  f = f6.head<2>();
  if (K) *K = K6.topLeftCorner<2, 2>();
  return p;
}

}  // namespace tunica
