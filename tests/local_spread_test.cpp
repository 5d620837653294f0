// stretch.local: the spread taken partly within soft geodesic regions. The
// regions are a partition of unity that follows the surface, not space; the
// term is the mix of the two spreads and never below the paper's (so bounded
// wherever it is); the direct global step (Woodbury) and CG both reach the
// step's minimiser; on a star-shaped body the limbs splay instead of lining up.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

#include "config/options.h"
#include "core/errors.h"
#include "energies/spread_regions.h"
#include "energies/stretch_energy.h"
#include "mesh/lumped_masses.h"
#include "pipeline/unfold_surface.h"
#include "shapes/articulated_shape.h"
#include "solvers/fiedler_value.h"
#include "solvers/quadratic_part.h"
#include "solvers/woodbury_update.h"
#include "test_meshes.h"
#include "test_problem.h"

namespace unfold {
namespace {

struct RegionGrid {
  TetMesh mesh = test::grid_tet_mesh(8, 3, 3);
  EdgeGraph graph = build_edge_graph(int(mesh.V.rows()), mesh.T);
  int n = int(mesh.V.rows());
};

TEST(SpreadRegions, AreAPartitionOfUnityEachPeakingSomewhere) {
  const RegionGrid g;
  const SpreadRegions r = spread_regions(g.mesh.V, g.graph, {0.5, 0.2, 6});
  ASSERT_EQ(r.count, 6);
  EXPECT_EQ(r.local, 0.5);
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(g.n);
  Eigen::MatrixXd W = Eigen::MatrixXd::Zero(g.n, r.count);
  for (const auto& t : r.weights) {
    EXPECT_GT(t.value(), 0);
    sum[t.row()] += t.value();
    W(t.row(), t.col()) = t.value();
  }
  EXPECT_LT((sum.array() - 1).abs().maxCoeff(), 1e-12);
  // Every region is the heaviest somewhere (at its landmark), and a narrow
  // radius leaves far vertices out of it.
  for (int k = 0; k < r.count; ++k) {
    int heaviest = 0;
    for (int i = 0; i < g.n; ++i) heaviest += W.row(i).maxCoeff() == W(i, k);
    EXPECT_GT(heaviest, 0) << "region " << k;
  }
  EXPECT_LT(r.weights.size(), size_t(g.n) * size_t(r.count));
}

// A hairpin strip: two arms 0.05 apart, joined at one end. Along the surface
// their free tips are two arm lengths apart, so no region holds both (a
// Euclidean ball around one would hold the other).
TEST(SpreadRegions, FollowTheSurfaceNotSpace) {
  std::vector<Eigen::Vector2d> path;
  for (int j = 20; j > 0; --j) path.emplace_back(0.025, 0.05 * j);
  for (int j = 0; j <= 4; ++j) {
    const double a = M_PI * j / 4;
    path.emplace_back(0.025 * std::cos(a), -0.025 * std::sin(a));
  }
  for (int j = 1; j <= 20; ++j) path.emplace_back(-0.025, 0.05 * j);
  const int m = int(path.size());
  Eigen::MatrixX3d V(2 * m, 3);
  Eigen::MatrixXi T(2 * (m - 1), 3);
  for (int j = 0; j < m; ++j) {
    V.row(j) << path[size_t(j)].x(), path[size_t(j)].y(), 0;
    V.row(m + j) << path[size_t(j)].x(), path[size_t(j)].y(), 0.05;
  }
  for (int j = 0; j + 1 < m; ++j) {
    T.row(2 * j) << j, j + 1, m + j;
    T.row(2 * j + 1) << j + 1, m + j + 1, m + j;
  }
  const EdgeGraph graph = build_edge_graph(2 * m, T);
  const SpreadRegions r = spread_regions(V, graph, {0.5, 0.1, 8});
  Eigen::MatrixXd W = Eigen::MatrixXd::Zero(2 * m, r.count);
  for (const auto& t : r.weights) W(t.row(), t.col()) = t.value();
  ASSERT_LT((V.row(0) - V.row(m - 1)).norm(), 0.051);
  EXPECT_LT(W.row(0).dot(W.row(m - 1)), 1e-3);
  EXPECT_GT(W.row(0).dot(W.row(1)), 0.1);  // neighbours along the strip share
}

TEST(SpreadRegions, AnEmptyGraphHasNone) {
  const SpreadRegions r =
      spread_regions(Eigen::MatrixX3d(0, 3), build_edge_graph(0, Eigen::MatrixXi(0, 3)), {});
  EXPECT_EQ(r.count, 0);
  EXPECT_TRUE(r.weights.empty());
}

TEST(SpreadRegions, BadOptionsNameTheirKey) {
  const RegionGrid g;
  const auto expect_error = [&](const SpreadRegionsOptions& o, const std::string& key) {
    try {
      spread_regions(g.mesh.V, g.graph, o);
      FAIL() << key;
    } catch (const UsageError& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    }
  };
  expect_error({1.0, 0.2, 4}, "stretch.local");
  expect_error({0.5, 0.0, 4}, "stretch.local_radius");
  expect_error({0.5, 0.2, 0}, "stretch.local_regions");
}

// -2M [(1 - t) sum_i m_i |q_i - c|^2 + t sum_k sum_i m_i w_ik |q_i - c_k|^2]
// + 2 sum_edges m_a m_b |q_a - q_b|^2, summed here directly.
TEST(LocalSpread, IsTheMixOfTheCentroidAndRegionSpreads) {
  const RegionGrid g;
  const auto graph = std::make_shared<const EdgeGraph>(g.graph);
  const double t = 0.7;
  const SpreadRegions r = spread_regions(g.mesh.V, g.graph, {t, 0.25, 5});
  Eigen::VectorXd m = lumped_masses(g.mesh.V, g.mesh.T);
  m *= g.n / m.sum();
  std::srand(3);
  const Eigen::MatrixX3d Q = g.mesh.V + 0.4 * Eigen::MatrixX3d::Random(g.n, 3);
  const Rotations R(size_t(g.n), Eigen::Matrix3d::Identity());
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(g.n, r.count);  // a_ik = m_i w_ik
  for (const auto& w : r.weights) A(w.row(), w.col()) = m[w.row()] * w.value();
  const Eigen::RowVector3d c = m.transpose() * Q / m.sum();
  double global = 0, local = 0, edges = 0;
  for (int i = 0; i < g.n; ++i) global += m[i] * (Q.row(i) - c).squaredNorm();
  for (int k = 0; k < r.count; ++k) {
    const Eigen::RowVector3d ck = A.col(k).transpose() * Q / A.col(k).sum();
    for (int i = 0; i < g.n; ++i) local += A(i, k) * (Q.row(i) - ck).squaredNorm();
  }
  for (int e = 0; e < graph->num_edges(); ++e) {
    const int a = graph->edges(e, 0), b = graph->edges(e, 1);
    edges += m[a] * m[b] * (Q.row(a) - Q.row(b)).squaredNorm();
  }
  const double expected = -2.0 * g.n * ((1 - t) * global + t * local) + 2 * edges;
  const double value = StretchEnergy(graph, 1.0, m, r).evaluate(Q, R, 1.0, nullptr);
  EXPECT_NEAR(value, expected, 1e-10 * std::abs(expected));
  // The law of total variance: within the regions there is less spread than
  // about the centroid, so the term is never below the paper's.
  EXPECT_LT(local, global);
  EXPECT_GT(value, StretchEnergy(graph, 1.0, m).evaluate(Q, R, 1.0, nullptr));
}

TEST(WoodburyUpdate, SolvesWithTheLowRankPartAndCountsItsInertia) {
  const int n = 30, k = 4;
  std::srand(11);
  const Eigen::MatrixXd G = Eigen::MatrixXd::Random(n, n);
  Eigen::MatrixXd dense = G * G.transpose() / n;
  dense.diagonal().array() -= 0.5;  // indefinite
  const Eigen::SparseMatrix<double> A = dense.sparseView();
  const Eigen::MatrixXd U = 2 * Eigen::MatrixXd::Random(n, k);
  SparseLdlt ldlt;
  ldlt.analyze(A);
  ldlt.factorize(A);
  WoodburyUpdate update;
  woodbury_precomputation(ldlt, U, &update);
  const Eigen::MatrixX3d b = Eigen::MatrixX3d::Random(n, 3);
  Eigen::MatrixX3d x;
  ldlt.solve(b, &x);
  woodbury_solve(update, &x);
  const Eigen::MatrixXd full = dense + U * U.transpose();
  EXPECT_LT((full * x - b).norm(), 1e-9 * b.norm());
  const Eigen::VectorXd eig = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(full).eigenvalues();
  EXPECT_EQ(ldlt.negative_pivots() - update.negative_eigenvalues, int((eig.array() < 0).count()));
}

// The region centroids are dense: the direct step adds them by Woodbury, CG to
// its products.
TEST(LocalSpread, BothSolversReachTheGlobalStepsMinimiser) {
  EnergyOptions energy;
  energy.stretch_masses = "lumped";
  energy.stretch_local = 0.8;
  energy.stretch_local_radius = 0.2;
  energy.stretch_local_regions = 8;
  TetMesh mesh = test::grid_tet_mesh(16, 4, 4);
  const test::ProblemFixture f(mesh, energy);
  Eigen::VectorXd masses = lumped_masses(f.mesh.V, f.mesh.T);
  masses *= f.n / masses.sum();
  const double beta = 1.25 * f.n / fiedler_value(beta_laplacian(f.problem), masses);
  test::expect_global_steps_reach_the_minimiser(f, beta);
  test::expect_energy_from_covariances_is_the_total(f, beta);
}

// The squared spread (configs/squared_spread.yaml, the default until
// 2026-12-04) lines the animal's legs up along its body, far from each other
// along the surface but near in space; configs/splayed.yaml spreads them out,
// so the canonical form's distances follow the surface's (lower E_geo) and its
// cells stay nearer their rest shape (lower E_rig).
TEST(LocalSpread, SplaysTheLimbsOfTheDemoAnimal) {
  const SurfaceMesh animal = make_articulated_shape(ShapePose::preset(1), 40);
  double E_geo[2], E_rig[2];
  for (const bool splayed : {false, true}) {
    Options options = load_options(UNFOLD_SOURCE_DIR "/configs/" +
                                   std::string(splayed ? "splayed" : "squared_spread") + ".yaml");
    options.metrics = {"E_rig", "E_geo"};
    const UnfoldResult r = unfold_surface(animal, options);
    E_geo[splayed] = r.metrics.E_geo;
    E_rig[splayed] = r.metrics.E_rig;
  }
  EXPECT_LT(E_geo[1], 0.9 * E_geo[0]) << "default " << E_geo[0] << ", splayed " << E_geo[1];
  EXPECT_LT(E_rig[1], E_rig[0]) << "default " << E_rig[0] << ", splayed " << E_rig[1];
}

}  // namespace
}  // namespace unfold
