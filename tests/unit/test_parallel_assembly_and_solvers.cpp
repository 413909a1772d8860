// Parallel assembly (coloured element loops) and the linear solvers:
// - the colouring never puts two elements that share a node in one colour;
// - results are identical bit for bit with 1 and 2 threads;
// - every linear solver, and the symmetrized pressure stiffness, reach the same state;
// - `auto` picks CHOLMOD for a symmetric tangent and UMFPACK for a nonsymmetric one.
#include <gtest/gtest.h>
#include <omp.h>

#include <map>
#include <set>
#include <string>

#include "io/deck.hpp"
#include "solver/analysis.hpp"
#include "linalg/linear_solver.hpp"
#include "linalg/matrix_symmetry.hpp"

namespace tunica {
namespace {

std::string sphere_deck(const std::string& solver, const std::string& stiffness, const std::string& shape = "quad") {
  return R"(units: {length: mm, force: N}
materials:
  rubber: {type: neo_hookean, mu: 1 MPa}
parts:
  balloon:
    element: membrane
    material: rubber
    thickness: 0.01 mm
    mesh: {type: octant, radius: 1 mm, n: 6, shape: )" +
         shape + R"(}
boundary:
  sym_x: {node_set: balloon.x0, dofs: [x]}
  sym_y: {node_set: balloon.y0, dofs: [y]}
  sym_z: {node_set: balloon.z0, dofs: [z]}
loads:
  inflation: {type: pressure, part: balloon}
solver: {linear_solver: )" +
         solver + ", pressure_stiffness: " + stiffness + R"(}
steps:
  - {name: inflate, increments: 3, set: {inflation: 0.011 MPa}}
)";
}

/// A quarter tube loaded by pressure whose top ring is free: the load stiffness is not symmetric.
std::string open_tube_deck() {
  return R"(units: {length: mm, force: N}
materials:
  aorta: {type: fung, c: 61.163 kPa, a1: 0.68238, a2: 0.60558, a4: 0.1067}
parts:
  wall:
    element: membrane
    material: aorta
    thickness: 0.122 mm
    mesh: {type: tube, radius: 0.763 mm, length: 1 mm, sector: 90 deg, around: 4, along: 2}
    frame: {type: cylindrical, axis: [0, 0, 1]}
boundary:
  sym_x: {node_set: wall.x0, dofs: [x]}
  sym_y: {node_set: wall.y0, dofs: [y]}
  base: {node_set: wall.bottom, dofs: [z]}
loads:
  lumen: {type: pressure, part: wall}
steps:
  - {name: inflation, increments: 1, set: {lumen: 10 mmHg}}
)";
}

struct Log : AnalysisObserver {
  std::set<std::string> solvers;
  int iterations = 0;
  void on_iteration(const IncrementInfo&, const IterationRecord& r) override {
    if (!r.solver.empty()) {
      // The solver that factorized: a correction with a reused factorization, (7.11), counts as its.
      solvers.insert(r.solver.substr(0, r.solver.find(kReusedFactorization)));
      ++iterations;
    }
  }
};

Eigen::VectorXd solve(const std::string& deck, Log* log = nullptr, int threads = 0) {
  const int saved = omp_get_max_threads();
  if (threads > 0) omp_set_num_threads(threads);
  const Model model = read_deck_text(deck, "test.yaml");
  Analysis analysis(model);
  Log local;
  analysis.run(log ? *log : local);
  omp_set_num_threads(saved);
  return analysis.displacement();
}

TEST(Colouring, NoTwoRunsOfAColourShareANode) {
  for (const std::string shape : {"quad", "triangle"}) {
    const Model model = read_deck_text(sphere_deck("auto", "exact", shape), "test.yaml");
    for (const auto& part : model.parts)
      for (const auto& block : part.blocks) {
        BlockLayout layout;
        colour_elements(block, model.num_nodes(), layout);
        ASSERT_EQ(static_cast<int>(layout.order.size()), block.size());
        std::vector<int> seen(block.size(), 0);
        for (int e : layout.order) ++seen[e];
        for (int s : seen) EXPECT_EQ(s, 1);  // every element exactly once
        const int runs = static_cast<int>(layout.run_start.size()) - 1;
        EXPECT_EQ(layout.run_start.front(), 0);
        EXPECT_EQ(layout.run_start.back(), block.size());
        EXPECT_EQ(layout.colour_start.front(), 0);
        EXPECT_EQ(layout.colour_start.back(), runs);
        EXPECT_LE(layout.colour_start.size(), 20u) << shape;  // a handful of colours for a surface mesh
        // Each run: consecutive elements, ascending, at most colour_run_length of them.
        const int length = colour_run_length(block.size());
        for (int r = 0; r < runs; ++r) {
          EXPECT_LE(layout.run_start[r + 1] - layout.run_start[r], length);
          for (int k = layout.run_start[r] + 1; k < layout.run_start[r + 1]; ++k)
            EXPECT_EQ(layout.order[k], layout.order[k - 1] + 1);
        }
        // No node in two runs of a colour.
        for (std::size_t c = 0; c + 1 < layout.colour_start.size(); ++c) {
          std::map<int, int> run_of;  // node -> run
          for (int r = layout.colour_start[c]; r < layout.colour_start[c + 1]; ++r)
            for (int k = layout.run_start[r]; k < layout.run_start[r + 1]; ++k) {
              const int* en = block.element(layout.order[k]);
              for (int a = 0; a < nodes_per_element(block.kind); ++a) {
                const auto [it, added] = run_of.emplace(en[a], r);
                EXPECT_EQ(it->second, r) << "node " << en[a] << " in runs " << it->second << " and " << r;
              }
            }
        }
      }
  }
}

TEST(TransposeMap, DetectsAndRemovesAsymmetry) {
  Eigen::MatrixXd dense(3, 3);
  dense << 4, 1, 0, 1, 5, 2, 0, 2, 6;
  SparseMatrix K = dense.sparseView();
  K.makeCompressed();
  const TransposeMap map(K);
  EXPECT_TRUE(map.symmetric(K, kSymmetryTolerance));
  K.coeffRef(0, 1) = 1.5;
  EXPECT_FALSE(map.symmetric(K, kSymmetryTolerance));
  map.symmetrize(K);
  EXPECT_TRUE(map.symmetric(K, 0.0));
  EXPECT_DOUBLE_EQ(K.coeff(0, 1), 1.25);
  EXPECT_DOUBLE_EQ(K.coeff(1, 0), 1.25);
  EXPECT_DOUBLE_EQ(K.coeff(2, 2), 6.0);
}

TEST(ParallelAssembly, ResultsAreIdenticalWithOneAndTwoThreads) {
  // UMFPACK reads the full matrix expanded from both triangles, CHOLMOD the lower one alone.
  for (const std::string solver : {"umfpack", "cholmod"})
    for (const std::string shape : {"quad", "triangle"}) {
      const Eigen::VectorXd u1 = solve(sphere_deck(solver, "exact", shape), nullptr, 1);
      const Eigen::VectorXd u2 = solve(sphere_deck(solver, "exact", shape), nullptr, 2);
      ASSERT_EQ(u1.size(), u2.size());
      EXPECT_GT(u1.norm(), 0.1);
      for (Eigen::Index i = 0; i < u1.size(); ++i)
        ASSERT_EQ(u1(i), u2(i)) << solver << ", " << shape << " DOF " << i;  // bit for bit
    }
}

TEST(LinearSolvers, EverySolverReachesTheSameState) {
  Log reference_log;
  const Eigen::VectorXd ref = solve(sphere_deck("umfpack", "exact"), &reference_log);
  for (const std::string solver : {"auto", "cholmod", "sparse_lu"}) {
    Log log;
    const Eigen::VectorXd u = solve(sphere_deck(solver, "exact"), &log);
    EXPECT_LT((u - ref).norm(), 1e-10 * ref.norm()) << solver;
    EXPECT_EQ(log.iterations, reference_log.iterations) << solver;  // the same Newton path
  }
  Log sym;
  const Eigen::VectorXd u = solve(sphere_deck("auto", "symmetrized"), &sym);
  EXPECT_LT((u - ref).norm(), 1e-8 * ref.norm());
}

TEST(LinearSolvers, AutoUsesCholmodWhereTheTangentIsSymmetricAndUmfpackElsewhere) {
  // The octant's symmetry planes close the loaded surface: the assembled load stiffness is symmetric.
  Log closed;
  solve(sphere_deck("auto", "exact"), &closed);
  EXPECT_EQ(closed.solvers, std::set<std::string>{"cholmod"});
  // A tube whose top ring is free: the boundary term of the load stiffness along that edge
  // remains (it vanishes where the edge is held, or slides in one direction only).
  const Model model = read_deck_text(open_tube_deck(), "open.yaml");
  const System system(model);
  LoadState loads;
  loads.boundary.assign(model.boundaries.size(), 0.0);
  loads.pressure.assign(model.loads.size(), 0.002);
  loads.volume.assign(model.loads.size(), 0.0);
  Eigen::VectorXd u = 0.02 * Eigen::VectorXd::Random(model.num_dofs());
  system.apply_boundary(loads, u);
  Eigen::VectorXd R;
  TangentMatrix T = system.tangent(true);
  system.assemble(u, loads, R, &T);
  const SparseMatrix K = T.full();
  const TransposeMap map(K);
  EXPECT_FALSE(map.symmetric(K, kSymmetryTolerance));
  EXPECT_FALSE(T.symmetric(kSymmetryTolerance));  // the split storage's test, slot by slot
  auto solver = make_linear_solver("auto");
  ASSERT_TRUE(solver->factorize(T));
  EXPECT_STREQ(solver->used(), "umfpack");
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(K.rows());
  EXPECT_LT((K * solver->solve(b) - b).norm(), 1e-9 * b.norm());
  // Without the pressure the tangent is symmetric again.
  loads.pressure.assign(model.loads.size(), 0.0);
  system.assemble(u, loads, R, &T);
  EXPECT_TRUE(map.symmetric(T.full(), kSymmetryTolerance));
  EXPECT_TRUE(T.symmetric(kSymmetryTolerance));
}

}  // namespace
}  // namespace tunica
