// stretch.distance: the spread by distances between clusters. Its clusters are
// connected graph-Voronoi cells; the term is the pair sum it names, concave so
// that its tangent lies above it; the local-global solver takes that tangent in
// the global step and its plain steps still lower the energy.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include "config/options.h"
#include "core/errors.h"
#include "energies/distance_clusters.h"
#include "energies/distance_spread_energy.h"
#include "mesh/lumped_masses.h"
#include "pipeline/unfold_surface.h"
#include "shapes/articulated_shape.h"
#include "solvers/cascade.h"
#include "stages/setup_cascade.h"
#include "test_meshes.h"
#include "test_problem.h"

namespace unfold {
namespace {

TEST(DistanceClusters, AreConnectedCellsOfTheCountAsked) {
  const TetMesh mesh = test::grid_tet_mesh(10, 4, 3);
  const EdgeGraph graph = build_edge_graph(int(mesh.V.rows()), mesh.T);
  int cells = 0;
  const std::vector<int> cell = distance_clusters(mesh.V, graph, 7, &cells);
  ASSERT_EQ(cells, 7);
  std::vector<int> size(7, 0);
  for (const int c : cell) ++size[size_t(c)];
  for (int c = 0; c < 7; ++c) EXPECT_GT(size[size_t(c)], 0) << "cell " << c;
  // Each cell is connected: a flood fill within it from one vertex reaches all.
  for (int c = 0; c < 7; ++c) {
    std::vector<int> stack;
    std::set<int> seen;
    for (int i = 0; i < graph.num_vertices && stack.empty(); ++i)
      if (cell[size_t(i)] == c) stack.push_back(i), seen.insert(i);
    while (!stack.empty()) {
      const int v = stack.back();
      stack.pop_back();
      for (int k = graph.offsets[size_t(v)]; k < graph.offsets[size_t(v) + 1]; ++k) {
        const int u = graph.neighbors[size_t(k)];
        if (cell[size_t(u)] == c && seen.insert(u).second) stack.push_back(u);
      }
    }
    EXPECT_EQ(int(seen.size()), size[size_t(c)]) << "cell " << c;
  }
}

TEST(DistanceClusters, SeedEveryPartAndRefuseTooManyParts) {
  // Two triangles apart: two parts, one cell each with two seeds, refused with one.
  Eigen::MatrixX3d V(6, 3);
  V << 0, 0, 0, 1, 0, 0, 0, 1, 0, 5, 0, 0, 6, 0, 0, 5, 1, 0;
  const Eigen::MatrixXi F = (Eigen::MatrixXi(2, 3) << 0, 1, 2, 3, 4, 5).finished();
  const EdgeGraph graph = build_edge_graph(6, F);
  int cells = 0;
  const std::vector<int> cell = distance_clusters(V, graph, 2, &cells);
  EXPECT_EQ(cells, 2);
  EXPECT_NE(cell[0], cell[3]);
  EXPECT_EQ(cell[0], cell[2]);
  EXPECT_THROW(distance_clusters(V, graph, 1, &cells), InputError);
  EXPECT_THROW(distance_clusters(V, graph, 0, &cells), UsageError);
}

// The farthest-point seeds as the definition picks them, each the first vertex
// of largest distance along the edges from the seeds so far (a whole scan per
// seed), cells by one Dijkstra from all seeds: what distance_clusters must give,
// whatever shortcut it takes to the farthest vertex.
std::vector<int> clusters_by_definition(const Eigen::MatrixX3d& V, const EdgeGraph& graph,
                                        int count) {
  const int n = graph.num_vertices;
  std::vector<double> nearest(size_t(n), std::numeric_limits<double>::infinity());
  std::vector<int> cell(size_t(n), -1);
  for (int made = 0, seed = 0; made < count; ++made) {
    nearest[size_t(seed)] = 0;
    cell[size_t(seed)] = made;
    // Relax until nothing changes (Bellman-Ford: slow, and plainly right).
    for (bool changed = true; changed;) {
      changed = false;
      for (int v = 0; v < n; ++v)
        for (int k = graph.offsets[size_t(v)]; k < graph.offsets[size_t(v) + 1]; ++k) {
          const int u = graph.neighbors[size_t(k)];
          const double d = nearest[size_t(v)] + (V.row(v) - V.row(u)).norm();
          if (d < nearest[size_t(u)]) {
            nearest[size_t(u)] = d;
            cell[size_t(u)] = cell[size_t(v)];
            changed = true;
          }
        }
    }
    seed = int(std::max_element(nearest.begin(), nearest.end()) - nearest.begin());
  }
  return cell;
}

// Over several blocks of the farthest-vertex search (256 vertices each), on a
// grid moved at random so that no two distances tie: the same seeds, the same cells.
TEST(DistanceClusters, SeedsAreTheFarthestVerticesAsDefined) {
  TetMesh mesh = test::grid_tet_mesh(16, 7, 6);
  ASSERT_GT(mesh.V.rows(), 3 * 256);
  std::srand(5);
  mesh.V += 0.3 * Eigen::MatrixX3d::Random(mesh.V.rows(), 3);
  const EdgeGraph graph = build_edge_graph(int(mesh.V.rows()), mesh.T);
  for (const int count : {1, 40, 200}) {
    int cells = 0;
    EXPECT_EQ(distance_clusters(mesh.V, graph, count, &cells),
              clusters_by_definition(mesh.V, graph, count))
        << count << " seeds";
    EXPECT_EQ(cells, count);
  }
}

// The soft joints' setup takes the first setup's clusters (the same mesh) and
// starts lambda_2 from its vector: the same clusters object, and the lambda_2
// and beta a setup made from nothing finds.
TEST(DistanceClusters, ALaterSetupOnTheSameMeshSharesThem) {
  const TetMesh mesh = test::grid_tet_mesh(10, 3, 2);
  const EdgeGraph graph = build_edge_graph(int(mesh.V.rows()), mesh.T);
  CascadeSetupOptions options;
  options.backend.linear_solver.method = "direct";
  options.energy = Options().energy;  // the default's: the spread by distances, lumped masses
  ASSERT_GT(options.energy.stretch_distance, 0);
  const CascadeSetup first = setup_cascade(graph, mesh, SurfaceMesh{}, options);
  ASSERT_TRUE(first.problem->distance_clusters);
  const EarlierSetup earlier{first.problem->distance_clusters, first.fiedler_vector};
  std::vector<double> factors(size_t(graph.num_edges()), 1.0);
  for (int e = 0; e < graph.num_edges(); ++e)
    if (std::min(mesh.V(graph.edges(e, 0), 0), mesh.V(graph.edges(e, 1), 0)) < 5 &&
        std::max(mesh.V(graph.edges(e, 0), 0), mesh.V(graph.edges(e, 1), 0)) >= 5)
      factors[size_t(e)] = 0.4;
  const CascadeSetup later =
      setup_cascade(graph, mesh, SurfaceMesh{}, options, factors, {}, &earlier);
  const CascadeSetup fresh = setup_cascade(graph, mesh, SurfaceMesh{}, options, factors);
  EXPECT_EQ(later.problem->distance_clusters, first.problem->distance_clusters);
  EXPECT_EQ(later.problem->distance_clusters->cell_of, fresh.problem->distance_clusters->cell_of);
  EXPECT_LT(later.lambda2, first.lambda2);
  EXPECT_NEAR(later.lambda2, fresh.lambda2, 1e-10 * fresh.lambda2);
  EXPECT_NEAR(later.beta.start, fresh.beta.start, 1e-9 * fresh.beta.start);
  // Clusters of another mesh are refused.
  const DistanceClusters wrong{{0, 0, 0}, 1};
  EXPECT_THROW(make_energy_terms(mesh, std::make_shared<const EdgeGraph>(graph), options.energy, {},
                                 {}, &wrong),
               UsageError);
}

struct SpreadSetup {
  TetMesh mesh = test::grid_tet_mesh(4, 3, 2, 0.7);
  EdgeGraph graph = build_edge_graph(int(mesh.V.rows()), mesh.T);
  int n = int(mesh.V.rows());
  Eigen::VectorXd masses = lumped_masses(mesh.V, mesh.T);
  Eigen::MatrixX3d Q;
  SpreadSetup() {
    std::srand(11);
    masses *= n / masses.sum();
    Q = mesh.V + 0.3 * Eigen::MatrixX3d::Random(n, 3);
  }
  DistanceSpreadEnergy term(int count) const {
    int cells = 0;
    std::vector<int> cell = distance_clusters(mesh.V, graph, count, &cells);
    return DistanceSpreadEnergy(std::move(cell), cells, masses, 1.0);
  }
};

// With a cluster a vertex it is the pair sum over vertices; with fewer, over
// the clusters' mass-weighted centroids.
TEST(DistanceSpread, IsThePairSumItNames) {
  const SpreadSetup s;
  const Rotations R;
  for (const int count : {s.n, 5}) {
    int cells = 0;
    const std::vector<int> cell = distance_clusters(s.mesh.V, s.graph, count, &cells);
    const DistanceSpreadEnergy term(cell, cells, s.masses, 1.0);
    Eigen::MatrixX3d C = Eigen::MatrixX3d::Zero(cells, 3);
    Eigen::VectorXd M = Eigen::VectorXd::Zero(cells);
    for (int i = 0; i < s.n; ++i) {
      C.row(cell[size_t(i)]) += s.masses[i] * s.Q.row(i);
      M[cell[size_t(i)]] += s.masses[i];
    }
    C.array().colwise() /= M.array();
    double expected = 0;
    for (int a = 0; a < cells; ++a)
      for (int b = a + 1; b < cells; ++b) expected -= M[a] * M[b] * (C.row(a) - C.row(b)).norm();
    EXPECT_NEAR(term.evaluate(s.Q, R, 1.0, nullptr), expected, 1e-12 * std::abs(expected))
        << count << " clusters";
  }
}

// Concave: the tangent at any Q lies above the term everywhere, touching at Q,
// and add_tangent is -1/2 the gradient there.
TEST(DistanceSpread, TangentLiesAboveAndIsHalfTheGradient) {
  const SpreadSetup s;
  const DistanceSpreadEnergy term = s.term(6);
  const Rotations R;
  Eigen::MatrixX3d grad = Eigen::MatrixX3d::Zero(s.n, 3);
  const double at = term.evaluate(s.Q, R, 1.0, &grad);
  Eigen::MatrixX3d B = Eigen::MatrixX3d::Zero(s.n, 3);
  term.add_tangent(s.Q, 2.0, &B);
  EXPECT_LT((B + grad).norm(), 1e-12 * grad.norm());
  for (unsigned seed = 0; seed < 20; ++seed) {
    std::srand(seed);
    const Eigen::MatrixX3d other = s.Q + (0.2 + seed) * Eigen::MatrixX3d::Random(s.n, 3);
    const double tangent = at + (grad.array() * (other - s.Q).array()).sum();
    EXPECT_LE(term.evaluate(other, R, 1.0, nullptr), tangent + 1e-12 * std::abs(tangent))
        << "seed " << seed;
  }
}

TEST(DistanceSpread, RefusesBadClustersAndMasses) {
  const Eigen::VectorXd masses = Eigen::VectorXd::Ones(3);
  EXPECT_THROW(DistanceSpreadEnergy({0, 1, 3}, 3, masses, 1.0), UsageError);  // out of range
  EXPECT_THROW(DistanceSpreadEnergy({0, 0, 1}, 3, masses, 1.0), UsageError);  // cluster 2 empty
  EXPECT_THROW(DistanceSpreadEnergy({0, 1, 1}, 2, -masses, 1.0), UsageError);
  EXPECT_THROW(DistanceSpreadEnergy({0, 1, 1}, 2, Eigen::VectorXd::Ones(2), 1.0), UsageError);
}

struct SpreadProblem {
  EnergyOptions energy;
  SpreadProblem() {
    energy.stretch_masses = "lumped";
    energy.stretch_distance = 1.0;
    energy.stretch_distance_clusters = 12;
  }
};

// The global step minimises the quadratic part plus the tangent at its start:
// there the total gradient is the term's change of gradient since the start,
// energy_after_global_step is the total energy, and that energy is lower.
TEST(DistanceSpread, GlobalStepMinimisesTheTangentMajorizer) {
  const test::ProblemFixture f(test::grid_tet_mesh(8, 3, 3), SpreadProblem().energy);
  const EnergyTerm& term = *f.problem.terms[1];
  ASSERT_EQ(term.name(), "stretch_distance");
  const double beta = 1.25 * f.n / f.lambda2;
  Rotations R;
  Eigen::MatrixX3d bent = test::bent_pose(f, &R);
  bent.rowwise() -= bent.colwise().mean();
  for (const char* method : {"direct", "iterative"}) {
    LocalGlobalData data;
    test::exact_global_steps(f, method, beta, &data);
    Eigen::MatrixX3d Q = bent;
    global_step(data, R, &Q);
    Eigen::MatrixX3d grad, term_at_start = Eigen::MatrixX3d::Zero(f.n, 3),
                           term_at_end = Eigen::MatrixX3d::Zero(f.n, 3);
    const double energy = total_energy(f.problem, Q, R, beta, &grad);
    term.evaluate(bent, R, term.weight(beta), &term_at_start);
    term.evaluate(Q, R, term.weight(beta), &term_at_end);
    EXPECT_LT((grad - (term_at_end - term_at_start)).norm(), 1e-8 * grad.norm()) << method;
    EXPECT_NEAR(energy_after_global_step(data, R, Q), energy, 1e-9 * std::abs(energy)) << method;
    EXPECT_LT(energy, total_energy(f.problem, bent, R, beta)) << method;
  }
  test::expect_energy_from_covariances_is_the_total(f, beta);
}

TEST(DistanceSpread, PlainIterationsLowerTheEnergy) {
  const test::ProblemFixture f(test::grid_tet_mesh(8, 3, 3), SpreadProblem().energy);
  CascadeOptions options;
  options.beta = 1.25 * f.n / f.lambda2;
  options.num_cascades = 1;
  options.k_iter = 40;
  options.epsilon = 0;                 // no convergence stop
  options.edge_ratio_band = {-1, -1};  // nor a band stop
  options.anderson = 0;
  Eigen::MatrixX3d start = f.mesh.V;
  for (int i = 0; i < f.n; ++i) start(i, 2) += 0.3 * std::sin(start(i, 0));
  LocalGlobalBackend backend(f.problem);
  const CascadeResult result = run_cascade(f.problem, backend, options, &start);
  ASSERT_GE(result.history.size(), 10u);
  test::expect_energy_non_increasing_within_cascades(result);
  EXPECT_LT(result.history.back().energy, result.history.front().energy);
}

// The squared spread lines the animal's legs up along its body
// (configs/squared_spread.yaml); with most of the spread by distances (the
// default) they splay, so the canonical form's distances follow the surface's:
// lower E_geo.
TEST(DistanceSpread, SplaysTheLimbsOfTheDemoAnimal) {
  const SurfaceMesh animal = make_articulated_shape(ShapePose::preset(1), 40);
  double E_geo[2];
  for (const bool distance : {false, true}) {
    Options options = load_options(UNFOLD_SOURCE_DIR "/configs/" +
                                   std::string(distance ? "default" : "squared_spread") + ".yaml");
    options.metrics = {"E_geo"};
    E_geo[distance] = unfold_surface(animal, options).metrics.E_geo;
  }
  EXPECT_LT(E_geo[1], 0.9 * E_geo[0]) << "default " << E_geo[0] << ", distance " << E_geo[1];
}

}  // namespace
}  // namespace unfold
