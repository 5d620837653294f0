// stretch.masses: lumped. The masses are the domain's shares of volume and
// area, the mass-weighted stretch term is Eq. 3 with every pair weighted by
// m_i m_j, its bound is lambda_2 of L x = lambda M x, both linear solvers
// reach the minimiser of the global step, and the canonical form depends less
// on where the mesh is dense.
#include "mesh/lumped_masses.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <random>

#include "core/errors.h"
#include "energies/stretch_energy.h"
#include "mesh/best_rotations.h"
#include "mesh/tet_volumes.h"
#include "metrics/pose_invariance.h"
#include "pipeline/unfold_surface.h"
#include "shapes/articulated_shape.h"
#include "solvers/cascade.h"
#include "solvers/fiedler_value.h"
#include "solvers/local_global.h"
#include "solvers/quadratic_part.h"
#include "solvers/smoothed_aggregation.h"
#include "stages/setup_cascade.h"
#include "test_meshes.h"
#include "test_problem.h"

namespace unfold {
namespace {

// A grid whose spacing grows along x: the masses differ from vertex to vertex.
TetMesh graded_grid(int nx, int ny, int nz) {
  TetMesh mesh = test::grid_tet_mesh(nx, ny, nz);
  for (Eigen::Index i = 0; i < mesh.V.rows(); ++i) mesh.V(i, 0) = std::pow(mesh.V(i, 0), 1.5);
  return mesh;
}

EnergyOptions lumped() {
  EnergyOptions energy;
  energy.stretch_masses = "lumped";
  return energy;
}

// The fixture's lambda_2 with the problem's masses (mean 1), as the pipeline takes it.
struct LumpedFixture : test::ProblemFixture {
  Eigen::VectorXd masses;
  explicit LumpedFixture(TetMesh mesh) : ProblemFixture(std::move(mesh), lumped()) {
    masses = lumped_masses(this->mesh.V, this->mesh.T);
    masses *= n / masses.sum();
    lambda2 = fiedler_value(beta_laplacian(problem), masses);
  }
};

TEST(LumpedMasses, AreTheSharesOfTheVolumeAndOfTheArea) {
  const TetMesh grid = graded_grid(4, 2, 2);
  const Eigen::VectorXd m = lumped_masses(grid.V, grid.T);
  EXPECT_NEAR(m.sum(), tet_volumes(grid.V, grid.T).cwiseAbs().sum(), 1e-12);
  EXPECT_GT(m.maxCoeff(), 3 * m.minCoeff());  // graded
  const SurfaceMesh sphere = test::uv_sphere(8, 12, 2.0);
  const Eigen::VectorXd a = lumped_masses(sphere.V, triangulate_faces(sphere));
  EXPECT_NEAR(a.sum(), surface_area(sphere), 1e-12);
  // A vertex in no element has no mass: refused by name.
  TetMesh extra = grid;
  extra.V.conservativeResize(extra.V.rows() + 1, 3);
  extra.V.bottomRows<1>().setZero();
  EXPECT_THROW(lumped_masses(extra.V, extra.T), InputError);
}

TEST(LumpedStretch, IsTheMassWeightedSumOverNonNeighbourPairs) {
  const TetMesh grid = graded_grid(3, 2, 2);
  const auto graph =
      std::make_shared<const EdgeGraph>(build_edge_graph(int(grid.V.rows()), grid.T));
  const int n = graph->num_vertices;
  Eigen::VectorXd m = lumped_masses(grid.V, grid.T);
  const StretchEnergy term(graph, 1.0, m);
  m *= n / m.sum();
  std::srand(3);
  const Eigen::MatrixX3d Q = Eigen::MatrixX3d::Random(n, 3);
  double brute = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      bool neighbour = false;
      for (int k = graph->offsets[size_t(i)]; k < graph->offsets[size_t(i) + 1]; ++k)
        neighbour |= graph->neighbors[size_t(k)] == j;
      if (!neighbour) brute -= m[i] * m[j] * (Q.row(i) - Q.row(j)).squaredNorm();
    }
  const Rotations none;
  EXPECT_NEAR(term.evaluate(Q, none, 1.0, nullptr), brute, 1e-9 * std::abs(brute));
  // Translation invariant, and the masses' scale does not matter (they are taken at mean 1).
  EXPECT_NEAR(term.evaluate(Q.rowwise() + Eigen::RowVector3d(5, -1, 2), none, 1.0, nullptr), brute,
              1e-9 * std::abs(brute));
  EXPECT_NEAR(StretchEnergy(graph, 1.0, 7 * m).evaluate(Q, none, 1.0, nullptr), brute,
              1e-9 * std::abs(brute));
  EXPECT_THROW(StretchEnergy(graph, 1.0, Eigen::VectorXd::Ones(n - 1)), UsageError);
  EXPECT_THROW(StretchEnergy(graph, 1.0, Eigen::VectorXd::Zero(n)), UsageError);
}

// stretch.mass_power p: the masses are the shares to p, at mean 1, both where the
// pipeline sets the cascade up and where the energy terms take the mesh's own.
TEST(LumpedStretch, AMassPowerRaisesTheSharesToIt) {
  const TetMesh grid = graded_grid(4, 2, 2);
  const int n = int(grid.V.rows());
  const EdgeGraph graph = build_edge_graph(n, grid.T);
  const Eigen::VectorXd share = lumped_masses(grid.V, grid.T);
  for (const double power : {1.0, 0.5, 0.0}) {
    CascadeSetupOptions options;
    options.energy = lumped();
    options.energy.stretch_mass_power = power;
    const CascadeSetup setup = setup_cascade(graph, grid, SurfaceMesh{}, options);
    const auto* set_up = dynamic_cast<const StretchEnergy*>(setup.problem->terms[0].get());
    const EnergyTerms terms =
        make_energy_terms(grid, std::make_shared<const EdgeGraph>(graph), options.energy);
    const auto* own = dynamic_cast<const StretchEnergy*>(terms[0].get());
    ASSERT_TRUE(set_up && own);
    double sum = 0;
    for (int i = 0; i < n; ++i) {
      sum += set_up->mass(i);
      const double expected = std::pow(share[i] / share[0], power);
      EXPECT_NEAR(set_up->mass(i) / set_up->mass(0), expected, 1e-12 * expected) << power;
      EXPECT_NEAR(own->mass(i) / own->mass(0), expected, 1e-12 * expected) << power;
    }
    EXPECT_NEAR(sum, n, 1e-9 * n);
  }
}

// Power 0 weighs every vertex alike: the paper's canonical form with uniform masses.
TEST(LumpedStretch, AMassPowerOfZeroIsUniformMasses) {
  const SurfaceMesh shape = make_articulated_shape(ShapePose::preset(1), 40);
  Eigen::MatrixX3d canonical[2];
  for (const bool lumped_at_zero : {false, true}) {
    Options options = load_options(UNFOLD_SOURCE_DIR "/configs/paper.yaml");
    options.tet.quality = 0;
    if (lumped_at_zero) {
      options.energy.stretch_masses = "lumped";
      options.energy.stretch_mass_power = 0;
    }
    canonical[lumped_at_zero] = unfold_surface(shape, options).canonical.V;
  }
  const double radius = canonical[0].rowwise().norm().maxCoeff();
  EXPECT_LT((canonical[1] - canonical[0]).cwiseAbs().maxCoeff(), 1e-6 * radius);
}

TEST(LumpedStretch, FiedlerValueIsThatOfTheGeneralizedProblem) {
  const TetMesh grid = graded_grid(5, 3, 2);
  const Eigen::SparseMatrix<double> L =
      graph_laplacian(build_edge_graph(int(grid.V.rows()), grid.T));
  const Eigen::VectorXd m = lumped_masses(grid.V, grid.T);
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> dense(Eigen::MatrixXd(L),
                                                                  Eigen::MatrixXd(m.asDiagonal()));
  EXPECT_NEAR(dense.eigenvalues()[0], 0, 1e-9);
  EXPECT_NEAR(fiedler_value(L, m), dense.eigenvalues()[1], 1e-9 * dense.eigenvalues()[1]);
  // Uniform masses c: the ordinary lambda_2 over c.
  EXPECT_NEAR(fiedler_value(L, Eigen::VectorXd::Constant(m.size(), 4.0)), fiedler_value(L) / 4,
              1e-9 * fiedler_value(L));
  // LOBPCG with the diagonal B agrees (an irregular mesh of more than 100 vertices).
  const TetMesh big = graded_grid(24, 8, 8);
  const Eigen::SparseMatrix<double> Lb =
      graph_laplacian(build_edge_graph(int(big.V.rows()), big.T));
  const Eigen::VectorXd mb = lumped_masses(big.V, big.T);
  AmgData amg;
  amg_precomputation(Lb, AmgOptions{}, &amg);
  EXPECT_NEAR(fiedler_value(Lb, amg, mb), fiedler_value(Lb, mb), 1e-8 * fiedler_value(Lb, mb));
  // A sliver's vertex can have a tiny mass: the shift must not follow it (the
  // dense solver is too ill-conditioned there to compare with; LOBPCG is not).
  Eigen::VectorXd sliver = mb;
  sliver[7] *= 1e-9;
  EXPECT_NEAR(fiedler_value(Lb, sliver), fiedler_value(Lb, amg, sliver),
              1e-8 * fiedler_value(Lb, amg, sliver));
  EXPECT_THROW(fiedler_value(L, Eigen::VectorXd::Zero(m.size())), UsageError);
}

// The energy is bounded exactly above n / lambda_2 - 1 with lambda_2 of L x =
// lambda M x (M = diag(m), mean 1), the same rule as the paper's with M = I.
TEST(LumpedStretch, BoundIsTheGeneralizedFiedlerValue) {
  const LumpedFixture f(graded_grid(6, 2, 2));
  const double bound = f.n / f.lambda2;
  EXPECT_TRUE(quadratic_part_bounded(f.problem, 1.01 * bound));
  EXPECT_FALSE(quadratic_part_bounded(f.problem, 0.97 * bound));
  // The uniform rule would be off: the graded grid's masses move the bound.
  const test::ProblemFixture uniform(graded_grid(6, 2, 2));
  EXPECT_GT(std::abs(uniform.n / uniform.lambda2 - bound), 0.05 * bound);
}

// The direct step solves A x = b without the rank-one m m^T (its solution is
// the minimiser up to a translation); CG adds it to its products. Both zero
// the energy's gradient at fixed rotations and end the cascade alike.
TEST(LumpedStretch, BothSolversReachTheGlobalStepsMinimiser) {
  const LumpedFixture f(graded_grid(16, 5, 5));
  const double beta = 1.5 * f.n / f.lambda2;
  test::expect_global_steps_reach_the_minimiser(f, beta);
  test::expect_energy_from_covariances_is_the_total(f, beta);
  CascadeOptions options;
  options.beta = beta;
  const auto cascade = [&](const char* method) {
    LocalGlobalBackend backend(f.problem, LinearSolverOptions{method});
    return run_cascade(f.problem, backend, options);
  };
  const CascadeResult direct = cascade("direct"), iterative = cascade("iterative");
  EXPECT_EQ(iterative.cascades, direct.cascades);
  EXPECT_LT((iterative.positions - direct.positions).cwiseAbs().maxCoeff(),
            1e-3 * direct.positions.cwiseAbs().maxCoeff());
  test::expect_energy_non_increasing_within_cascades(direct);
}

// The demo animal, and the same surface with every triangle above its median
// height split at its centroid twice (nine times the density there, the
// original vertices first): with lumped masses the paper's canonical form of
// the refined mesh, on the original vertices, is closer to the unrefined one's
// (measured 0.042 against 0.057 at unit area).
SurfaceMesh refined_at_one_end(const SurfaceMesh& mesh) {
  SurfaceMesh out = mesh;
  const Eigen::Index axis = 2;
  Eigen::VectorXd heights = mesh.V.col(axis);
  std::nth_element(heights.data(), heights.data() + heights.size() / 2,
                   heights.data() + heights.size());
  const double middle = heights[heights.size() / 2];
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<std::vector<int>> faces;
    for (const auto& f : out.faces) {
      Eigen::RowVector3d c = Eigen::RowVector3d::Zero();
      for (int v : f) c += out.V.row(v) / double(f.size());
      if (f.size() != 3 || c[axis] < middle) {
        faces.push_back(f);
        continue;
      }
      out.V.conservativeResize(out.V.rows() + 1, 3);
      out.V.bottomRows<1>() = c;
      const int m = int(out.V.rows()) - 1;
      for (int k = 0; k < 3; ++k) faces.push_back({f[size_t(k)], f[size_t(k + 1) % 3], m});
    }
    out.faces = faces;
  }
  return out;
}

TEST(LumpedStretch, TheCanonicalFormDependsLessOnWhereTheMeshIsDense) {
  const SurfaceMesh coarse = make_articulated_shape(ShapePose::preset(0), 40);
  const SurfaceMesh refined = refined_at_one_end(coarse);
  ASSERT_GT(refined.V.rows(), 2 * coarse.V.rows());
  const Eigen::Index n = coarse.V.rows();
  const Eigen::MatrixX3i F = triangulate_faces(coarse);
  double distance[2];
  for (const bool with_masses : {false, true}) {
    Options options = load_options(UNFOLD_SOURCE_DIR "/configs/paper.yaml");
    options.energy.stretch_masses = with_masses ? "lumped" : "uniform";
    options.tet.quality = 0;  // the refined end's slivers would take TetGen long to refine
    const UnfoldResult a = unfold_surface(coarse, options), b = unfold_surface(refined, options);
    distance[with_masses] = pose_distance(a.canonical.V, b.canonical.V.topRows(n), F);
  }
  EXPECT_LT(distance[1], 0.85 * distance[0])
      << "uniform " << distance[0] << ", lumped " << distance[1];
}

}  // namespace
}  // namespace unfold
