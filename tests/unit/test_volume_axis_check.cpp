// model/volume_axis_check.hpp: a load's `volume_axis` must fit the open ends of its surface, or
// ½∫(x − p₀)⊥·n dA (theory manual (6.6)) is not the enclosed volume. A tube along z measured
// about x reported half its lumen without a word; now the deck is refused at `volume_axis`.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "../support/capture.hpp"
#include "../support/cli.hpp"
#include "../support/deck_files.hpp"
#include "../support/sphere_octant.hpp"
#include "assembly/system.hpp"
#include "io/deck.hpp"
#include "model/volume_axis_check.hpp"

using namespace tunica;
using namespace tunica::test;

namespace {

/// A closed tube about z, R = 4 mm, length 10 mm, 24 × 10 quads, its lumen's volume in history,
/// the load given as `load`.
std::string full_tube(const std::string& load) {
  return "units: {length: mm, force: N}\n"
         "materials:\n  rubber: {type: neo_hookean, mu: 1 MPa}\n"
         "parts:\n  wall:\n    element: membrane\n    material: rubber\n    thickness: 0.1 mm\n"
         "    mesh: {type: tube, radius: 4 mm, length: 10 mm, around: 24, along: 10}\n"
         "boundary:\n  ends: {node_set: wall.bottom, dofs: [x, y, z]}\n  top: {node_set: wall.top, dofs: [x, y, z]}\n"
         "loads:\n  " + load + "\n"
         "steps:\n  - {name: inflate, increments: 1, set: {lumen: 1 kPa}}\n"
         "output:\n  history:\n    - {quantity: volume, load: lumen, unit: mm^3}\n";
}

VolumeMeasure about(const Eigen::Vector3d& axis, const Eigen::Vector3d& point = Eigen::Vector3d::Zero()) {
  VolumeMeasure v;
  v.about_axis = true;
  v.axis = axis.normalized();
  v.point = point;
  return v;
}

}  // namespace

TEST(VolumeAxisCheck, AnAxisAcrossTheTubeIsRefusedAtItsKeyWithTheTubesAxis) {
  const std::string text = full_tube("lumen: {type: pressure, part: wall, volume_axis: [1, 0, 0]}");
  const Outcome o = expect_check_error(
      "tunica-volume-axis", "across", text, "volume_axis: [1, 0, 0]", "loads.lumen.volume_axis",
      "the axis [1, 0, 0] through p₀ = (0, 0, 0) does not fit the open edge loop of 24 edge(s) around (0, 0, 10)");
  // The end z = 0 passes (the axis runs through its middle); the end z = 10 mm misses its cap's
  // share ½ A·10 mm, A the 24-gon's area, and the fix is the loops' normal.
  const double area = 0.5 * 24 * 16 * std::sin(2 * std::numbers::pi / 24);
  EXPECT_NE(o.output.find(fmt::format("this loop's cap would add {:.6g} mm³", 0.5 * area * 10)), std::string::npos)
      << o.output;
  EXPECT_NE(o.output.find("The surface's normals are most nearly perpendicular to [0, 0, 1] (a tube's axis), which "
                          "fits: `volume_axis: [0, 0, 1]`"),
            std::string::npos)
      << o.output;
}

TEST(VolumeAxisCheck, WhereTheAxisPassesDoesNotMatterForEndsNormalToIt) {
  // Caps normal to the axis have y⊥·n = 0 wherever the axis is: an axis parallel to the tube's,
  // even outside it, measures the same volume.
  const Model on = read_deck_text(full_tube("lumen: {type: pressure, part: wall, volume_axis: [0, 0, 1]}"), "on.yaml");
  const Model off = read_deck_text(
      full_tube("lumen: {type: pressure, part: wall, volume_axis: [0, 0, 1], volume_point: [5 mm, 3 mm, 0]}"), "off.yaml");
  const Eigen::VectorXd u0 = Eigen::VectorXd::Zero(System(on).num_dofs());
  const double v_on = System(on).volume(u0, 0), v_off = System(off).volume(u0, 0);
  EXPECT_NEAR(v_off, v_on, 1e-10 * v_on);
  EXPECT_NEAR(v_on, 0.5 * 24 * 16 * std::sin(2 * std::numbers::pi / 24) * 10, 1e-9 * v_on);
}

TEST(VolumeAxisCheck, SymmetryPlanesThatHoldTheAxisCloseTheSurface) {
  // The 3-D rat aorta's quarter tube and the sphere octant: their open edges on the symmetry
  // planes through the axis need no cap, and their other ends are normal to it.
  std::string quarter = read_text(std::string(TUNICA_SOURCE_DIR) + "/examples/rat-aorta-3d.yaml");
  const Model q = read_deck_text(quarter, "quarter.yaml");
  EXPECT_EQ(volume_axis_misfit(q, 0, about({0, 0, 1})), "");
  // About x, the quarter tube's end z = 1 mm has a share (its x = 0 plane does not hold x, so
  // the loop runs round both ends and that plane, in no plane); its axis is proposed.
  const std::string why = volume_axis_misfit(q, 0, about({1, 0, 0}));
  EXPECT_NE(why.find("The loop does not lie in a plane"), std::string::npos) << why;
  EXPECT_NE(why.find("(a tube's axis), which fits: `volume_axis: [0, 0, 1]`"), std::string::npos) << why;
  const Model octant = read_deck_text(sphere_octant_deck("octant", 8, "", 1), "octant.yaml");
  for (const Eigen::Vector3d& a : {Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0)})
    EXPECT_EQ(volume_axis_misfit(octant, 0, about(a)), "") << a.transpose();
}

TEST(VolumeAxisCheck, ObliqueEndsFitAnAxisThroughTheirMiddles) {
  // The tube's ends cut by planes tilted about y (z' = z + k x (1 − 2z/L): the two ends tilted
  // opposite ways): the axis z through the origin passes through both ends' middles (x̄ = 0), so
  // their caps have no share; moved off to x = 2 mm it misfits, and no normal of one end fits the
  // other, but the line through the two middles does.
  Model m = read_deck_text(full_tube("lumen: {type: pressure, part: wall}"), "oblique.yaml");
  for (Eigen::Vector3d& x : m.X) x.z() += 0.3 * x.x() * (1 - 2 * x.z() / 10);
  EXPECT_EQ(volume_axis_misfit(m, 0, about({0, 0, 1})), "");
  const std::string why = volume_axis_misfit(m, 0, about({0, 0, 1}, {2, 0, 0}));
  EXPECT_NE(why.find("The line through the middles of the two open ends fits both: `volume_axis: [0, 0, 1], "
                     "volume_point: [0 mm, 0 mm, 0 mm]`"),
            std::string::npos)
      << why;
  // Both ends tilted the same way (z' = z + k x): the planes are parallel, their normal fits.
  Model p = read_deck_text(full_tube("lumen: {type: pressure, part: wall}"), "parallel.yaml");
  for (Eigen::Vector3d& x : p.X) x.z() += 0.3 * x.x();
  const std::string tilted = volume_axis_misfit(p, 0, about({0, 0, 1}, {2, 0, 0}));
  EXPECT_NE(tilted.find("`volume_axis: [-0.2873, 0, 0.9578]`"), std::string::npos) << tilted;
}

TEST(VolumeAxisCheck, AnEndThatIsNotPlaneIsSaidSo) {
  // The top ring tilted and made wavy (z = 10 + ½ cos θ + cos 2θ mm) and the axis moved off the
  // tube's to x = 2 mm: the tilt's cap has a share, and no plane holds the ring.
  Model m = read_deck_text(full_tube("lumen: {type: pressure, part: wall}"), "wavy.yaml");
  for (Eigen::Vector3d& x : m.X)
    if (x.z() == 10) {
      const double t = std::atan2(x.y(), x.x());
      x.z() += 0.5 * std::cos(t) + std::cos(2 * t);
    }
  const std::string why = volume_axis_misfit(m, 0, about({0, 0, 1}, {2, 0, 0}));
  EXPECT_NE(why.find("around (0, 0, 10)"), std::string::npos) << why;
  EXPECT_NE(why.find("The loop does not lie in a plane (its nodes stand up to"), std::string::npos) << why;
  // The axis through the middles of the two ends (nearly the tube's: the wavy end's middle is
  // that of its mean plane) fits.
  EXPECT_NE(why.find("The line through the middles of the two open ends fits both: `volume_axis: ["),
            std::string::npos)
      << why;
  // A wave alone, about the tube's own axis, leaves no share: any cap fanned from the axis closes
  // it for ½∫(x − p₀)⊥·n dA, and the deck is measured as it is.
  Model wave = read_deck_text(full_tube("lumen: {type: pressure, part: wall}"), "wave.yaml");
  for (Eigen::Vector3d& x : wave.X)
    if (x.z() == 10) x.z() += std::cos(2 * std::atan2(x.y(), x.x()));
  EXPECT_EQ(volume_axis_misfit(wave, 0, about({0, 0, 1})), "");
}
