// The assembled residual and tangent (System) of a model with a deformable contact
// pair, against central differences: a sheet (slave) pressed onto a rotated, kinked
// membrane chain (master: an ordered node set, reversed), every slave node active —
// on segments (mid-segment and within 3–4 % of a segment's end) and in the region
// of a convex corner (node to vertex) — with the faceted master and with the smooth
// one (contact/smooth_chain.hpp), with prescribed DOFs on the master and on
// the slave, and a follower pressure on the slave.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "../support/capture.hpp"
#include "../support/system_fd.hpp"
#include "assembly/system.hpp"
#include "contact/contact_search.hpp"

using namespace tunica;
using namespace tunica::test;

namespace {

const std::string kDeck = R"(title: sheet on a rotated, kinked deformable chain
units: {length: mm, force: N}
materials:
  soft: {type: neo_hookean, mu: 0.1}
  stiff: {type: neo_hookean, mu: 1}
parts:
  floor:
    element: axisymmetric_membrane
    material: stiff
    thickness: 0.1
    mesh: {type: line, from: [0.8, 0], to: [2.2, 0], elements: 5}
  sheet:
    element: axisymmetric_membrane
    material: soft
    thickness: 0.1
    mesh: {type: line, from: [1, 0.05], to: [2, 0.05], elements: 6}
node_sets:
  floor_chain: {part: floor, nodes: [0, 1, 2, 3, 4, 5]}
boundary:
  master_r: {node_set: floor.start, dofs: [r]}
  master_z: {node_set: floor.start, dofs: [z]}
  slave_r: {node_set: sheet.end, dofs: [r]}
loads:
  push: {type: pressure, part: sheet}
contact:
  touch: {slave: sheet, master: floor_chain, master_orientation: reversed, penalty: 10, offset: 0.02}
steps:
  - {name: press, increments: 1, set: {push: 0.001}}
)";

struct Target {
  bool vertex;  // at the corner v = segment + 1 (else on the segment)
  int segment;  // of the (reversed) master chain
  double xi;    // on the segment
};

}  // namespace

TEST(DeformableContactAssembly, TangentMatchesFiniteDifferencesInASlidingShearedState) {
 for (const std::string surface : {"faceted", "smooth"}) {
  SCOPED_TRACE("master_surface: " + surface);
  const Model m = read_deck_text(replace(kDeck, "offset: 0.02}", "offset: 0.02, master_surface: " + surface + "}"), "fd.yaml");
  ASSERT_EQ(m.contacts.size(), 1u);
  const ContactPair& pair = m.contacts[0];
  ASSERT_EQ(pair.master.size(), 6u);
  const System sys(m);
  const Part& floor = m.parts[0];
  const Part& sheet = m.parts[1];

  // The master: rotated by 10° about its held node 0, with kinks (a convex peak at node 3).
  Eigen::VectorXd u = Eigen::VectorXd::Zero(m.num_dofs());
  const double th = 10.0 * std::numbers::pi / 180.0;
  const double kink[6] = {0, 0.01, -0.005, 0.03, 0.0, 0.01};
  const Eigen::Vector2d X0 = m.X[floor.nodes[0]].head<2>();
  for (int j = 0; j < 6; ++j) {
    const Eigen::Vector2d d = m.X[floor.nodes[j]].head<2>() - X0;
    const Eigen::Vector2d x = X0 + Eigen::Vector2d(std::cos(th) * d(0) - std::sin(th) * d(1),
                                                   std::sin(th) * d(0) + std::cos(th) * d(1)) +
                              Eigen::Vector2d(0, kink[j]);
    u.segment<2>(2 * floor.nodes[j]) = x - m.X[floor.nodes[j]].head<2>();
  }
  Eigen::Matrix2Xd chain(2, 6);
  for (int k = 0; k < 6; ++k) chain.col(k) = m.X[pair.master[k]].head<2>() + u.segment<2>(2 * pair.master[k]);

  // The slave nodes: penetrating by 3–9 µm beyond the offset, at chosen places of the chain
  // (reversed: segment 0 is at the large-r end).
  const Target where[7] = {{false, 4, 0.6}, {false, 3, 0.97}, {false, 3, 0.04}, {true, 1, 0},
                           {false, 1, 0.5}, {false, 0, 0.97}, {false, 0, 0.1}};
  const double c = pair.law.offset;
  for (int i = 0; i < 7; ++i) {
    const Target& t = where[i];
    const double gN = -0.003 * (1 + i % 3);
    Eigen::Vector2d x;
    if (t.vertex) {
      const int v = t.segment + 1;
      const Eigen::Vector2d b = segment_normal(chain.col(v - 1), chain.col(v)) + segment_normal(chain.col(v), chain.col(v + 1));
      x = chain.col(v) + (c + gN) * b.normalized();
    } else {
      const Eigen::Vector2d a = chain.col(t.segment), e = chain.col(t.segment + 1);
      x = a + t.xi * (e - a) + (c + gN) * segment_normal(a, e);
    }
    u.segment<2>(2 * sheet.nodes[i]) = x - m.X[sheet.nodes[i]].head<2>();
    const ChainProjection p = project_on_chain(x, chain);
    ASSERT_EQ(p.feature, t.vertex ? ChainFeature::vertex : ChainFeature::segment) << "slave node " << i;
    ASSERT_EQ(p.segment, t.segment) << "slave node " << i;
    EXPECT_NEAR(p.gap(c), gN, 1e-12) << "slave node " << i;
  }

  LoadState loads;
  loads.boundary.assign(m.boundaries.size(), 0.0);
  loads.boundary[2] = u(2 * sheet.nodes.back());  // slave_r: the slave's last r DOF is prescribed where it is
  loads.pressure.assign(m.loads.size(), 0.001);
  loads.volume.assign(m.loads.size(), 0.0);
  sys.apply_boundary(loads, u);

  Eigen::VectorXd R;
  SparseMatrix K;
  int active = 0;
  sys.assemble_full(u, loads, R, K, nullptr, &active);
  EXPECT_EQ(active, 7);
  const Eigen::MatrixXd Kd(K);
  ActiveRange perturbed;  // every slave node stays active in every perturbed state
  const double worst = fd_tangent_error(sys, loads, u, Kd, 1e-7, &perturbed);
  ASSERT_EQ(perturbed.fewest, 7);
  ASSERT_EQ(perturbed.most, 7);
  const double size = Kd.cwiseAbs().maxCoeff();
  EXPECT_LT(worst, 1e-6 * size);

  // Without the follower pressure the tangent is the Hessian of an energy: symmetric.
  loads.pressure.assign(m.loads.size(), 0.0);
  sys.assemble_full(u, loads, R, K);
  const Eigen::MatrixXd K0(K);
  const double asym = (K0 - K0.transpose()).cwiseAbs().maxCoeff();
  EXPECT_LT(asym, 1e-12 * size);
  // The contact forces balance: the slave's force is the opposite of the master's, so Σ R_z is
  // zero (the membranes' internal forces balance in z element by element; no pressure).
  double total = 0;
  for (int n = 0; n < m.num_nodes(); ++n) total += R(2 * n + 1);
  EXPECT_LT(std::abs(total), 1e-12 * R.cwiseAbs().maxCoeff());
  std::printf("deformable pair: FD of the assembled residual vs K: %.2e (max |K| %.2e); |K − Kᵀ| %.1e; |Σ R_z| %.1e\n",
              worst, size, asym, std::abs(total));
 }
}
