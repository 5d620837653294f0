// The iterative linear solver for large meshes: the AMG V-cycle is a symmetric
// positive definite preconditioner that converges, projected CG solves the
// global system to its tolerance and notices an unbounded energy, LOBPCG finds
// the smallest Laplacian eigenvalues, and the cascade on the iterative solver
// ends where the direct one does.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>

#include "energies/user_pairs_energy.h"
#include "shapes/articulated_shape.h"
#include "solvers/cascade.h"
#include "solvers/fiedler_value.h"
#include "solvers/lobpcg.h"
#include "solvers/local_global.h"
#include "solvers/projected_cg.h"
#include "solvers/smoothed_aggregation.h"
#include "solvers/sparse_ldlt.h"
#include "test_meshes.h"
#include "test_problem.h"
#include "tetra/tetrahedralize.h"

namespace unfold {
namespace {

// 17 x 6 x 6 = 612 vertices: enough for an AMG hierarchy of two levels.
TetMesh bar() { return test::grid_tet_mesh(16, 5, 5, 0.5); }

RowMatrixX3d random_zero_mean(int n, unsigned seed) {
  std::mt19937 random(seed);
  std::normal_distribution<double> normal;
  RowMatrixX3d X(n, 3);
  for (Eigen::Index i = 0; i < X.size(); ++i) X.data()[i] = normal(random);
  remove_column_means(&X);
  return X;
}

struct LaplacianFixture {
  EdgeGraph graph;
  Eigen::SparseMatrix<double> L;
  AmgData amg;
  int n = 0;
  explicit LaplacianFixture(const TetMesh& mesh)
      : graph(build_edge_graph(int(mesh.V.rows()), mesh.T)), L(graph_laplacian(graph)) {
    n = graph.num_vertices;
    amg_precomputation(L, AmgOptions{}, &amg);
  }
};

// In double the V-cycle is symmetric to roundoff; in float (the default) to
// float rounding, and within that of the double one.
TEST(Amg, VCycleIsSymmetricAndPositiveDefiniteOnZeroMeanBlocks) {
  const LaplacianFixture f(bar());
  ASSERT_GE(f.amg.levels.size(), 2u);
  EXPECT_LT(f.amg.levels[1].A.rows(), f.n / 4);  // it really coarsens
  AmgOptions double_options;
  double_options.single_precision = false;
  AmgData double_amg;
  amg_precomputation(f.L, double_options, &double_amg);
  ASSERT_TRUE(double_amg.single_levels.empty());
  ASSERT_EQ(f.amg.single_levels.size(), f.amg.levels.size());
  const RowMatrixX3d x = random_zero_mean(f.n, 1), y = random_zero_mean(f.n, 2);
  for (const AmgData* amg : {static_cast<const AmgData*>(&double_amg), &f.amg}) {
    const double tolerance = amg == &double_amg ? 1e-10 : 1e-5;
    RowMatrixX3d Bx, By;
    amg_vcycle(*amg, x, &Bx);
    amg_vcycle(*amg, y, &By);
    const Eigen::Array3d yBx = column_dots(y, Bx), xBy = column_dots(x, By);
    const Eigen::Array3d xBx = column_dots(x, Bx);
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(yBx[k], xBy[k], tolerance * xBx[k]);
      EXPECT_GT(xBx[k], 0);
    }
  }
  RowMatrixX3d single, exact;
  amg_vcycle(f.amg, x, &single);
  amg_vcycle(double_amg, x, &exact);
  EXPECT_LT((single - exact).norm(), 1e-5 * exact.norm());
  EXPECT_GT((single - exact).norm(), 0);  // the float cycle really runs
}

// Every smoothing degree keeps the cycle symmetric (the same Chebyshev
// polynomial before and after the coarse correction), degree 1 and 3 included.
TEST(Amg, VCycleIsSymmetricForEverySmoothingDegree) {
  const LaplacianFixture f(bar());
  const RowMatrixX3d x = random_zero_mean(f.n, 4), y = random_zero_mean(f.n, 5);
  for (const int degree : {1, 2, 3}) {
    AmgOptions options;
    options.single_precision = false;
    options.smoothing_degree = degree;
    AmgData amg;
    amg_precomputation(f.L, options, &amg);
    RowMatrixX3d Bx, By;
    amg_vcycle(amg, x, &Bx);
    amg_vcycle(amg, y, &By);
    const Eigen::Array3d yBx = column_dots(y, Bx), xBy = column_dots(x, By);
    const Eigen::Array3d xBx = column_dots(x, Bx);
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(yBx[k], xBy[k], 1e-10 * xBx[k]) << "degree " << degree;
      EXPECT_GT(xBx[k], 0) << "degree " << degree;
    }
  }
}

// With gershgorin_lambda_max every level's smoother bound is at or above the
// largest eigenvalue of D^-1 A (computed densely), where the power steps'
// estimate is below Gershgorin's bound; the cycle stays symmetric.
TEST(Amg, AGershgorinBoundIsNeverBelowTheLargestEigenvalue) {
  const LaplacianFixture f(bar());
  AmgOptions options;
  options.single_precision = false;
  options.gershgorin_lambda_max = true;
  AmgData amg;
  amg_precomputation(f.L, options, &amg);
  ASSERT_EQ(amg.levels.size(), f.amg.levels.size());
  for (size_t l = 0; l < amg.levels.size(); ++l) {
    const Eigen::MatrixXd A(amg.levels[l].A);
    const Eigen::VectorXd s = amg.levels[l].inverse_diagonal.cwiseSqrt();
    // D^-1 A is similar to D^-1/2 A D^-1/2, which is symmetric.
    const Eigen::MatrixXd scaled = s.asDiagonal() * A * s.asDiagonal();
    const double largest =
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(scaled).eigenvalues().maxCoeff();
    EXPECT_GE(amg.levels[l].lambda_max, largest * (1 - 1e-12)) << "level " << l;
    EXPECT_GE(amg.levels[l].lambda_max, f.amg.levels[l].lambda_max) << "level " << l;
  }
  EXPECT_GT(amg.levels[0].lambda_max, f.amg.levels[0].lambda_max);  // not the estimate
  const RowMatrixX3d x = random_zero_mean(f.n, 6), y = random_zero_mean(f.n, 7);
  RowMatrixX3d Bx, By;
  amg_vcycle(amg, x, &Bx);
  amg_vcycle(amg, y, &By);
  const Eigen::Array3d yBx = column_dots(y, Bx), xBy = column_dots(x, By), xBx = column_dots(x, Bx);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(yBx[k], xBy[k], 1e-10 * xBx[k]);
    EXPECT_GT(xBx[k], 0);
  }
}

TEST(Amg, AsAStationaryIterationItConverges) {
  const LaplacianFixture f(bar());
  const RowMatrixX3d b = random_zero_mean(f.n, 3);
  // The exact zero-mean solution, from the dense pseudo-inverse.
  const Eigen::MatrixXd pinv =
      Eigen::MatrixXd(f.L).completeOrthogonalDecomposition().pseudoInverse();
  const RowMatrixX3d exact = pinv * Eigen::MatrixX3d(b);
  RowMatrixX3d x = RowMatrixX3d::Zero(f.n, 3), r, correction;
  const CsrView L = CsrView::of_symmetric(f.L);
  double previous = (x - exact).norm();
  for (int cycle = 0; cycle < 6; ++cycle) {
    residual(L, b, x, &r);
    amg_vcycle(f.amg, r, &correction);
    x += correction;
    remove_column_means(&x);
    const double error = (x - exact).norm();
    EXPECT_LT(error, 0.75 * previous) << "cycle " << cycle;
    previous = error;
  }
}

// The global matrix of the paper's energy, (beta + 1) L - n I.
Eigen::SparseMatrix<double> global_matrix(const LaplacianFixture& f, double beta) {
  Eigen::SparseMatrix<double> A = (beta + 1) * f.L;
  A.diagonal().array() -= f.n;
  A.makeCompressed();
  return A;
}

TEST(ProjectedCg, MatchesTheDirectSolveToItsTolerance) {
  const LaplacianFixture f(bar());
  const double beta = 1.5 * f.n / fiedler_value(f.L);
  const Eigen::SparseMatrix<double> A = global_matrix(f, beta);
  const RowMatrixX3d b = random_zero_mean(f.n, 4);
  SparseLdlt ldlt;
  ldlt.analyze(A);
  ldlt.factorize(A);
  Eigen::MatrixX3d direct;
  ldlt.solve(Eigen::MatrixX3d(b), &direct);
  direct.rowwise() -= direct.colwise().mean();

  RowMatrixX3d x = RowMatrixX3d::Zero(f.n, 3);
  const CgResult r = projected_cg(CsrView::of_symmetric(A), f.amg, b, &x, CgOptions{1e-11, 0, 200});
  EXPECT_TRUE(r.converged);
  EXPECT_FALSE(r.negative_curvature);
  EXPECT_LT(r.iterations, 40);
  EXPECT_LT((Eigen::MatrixX3d(x) - direct).norm(), 1e-9 * direct.norm());

  // From the solution there is nothing left to do.
  const CgResult again =
      projected_cg(CsrView::of_symmetric(A), f.amg, b, &x, CgOptions{1e-9, 0, 200});
  EXPECT_EQ(again.iterations, 0);
}

TEST(ProjectedCg, ForcingStopsAtAReductionOfTheWarmStartsResidual) {
  const LaplacianFixture f(bar());
  const double beta = 1.5 * f.n / fiedler_value(f.L);
  const Eigen::SparseMatrix<double> A = global_matrix(f, beta);
  const RowMatrixX3d b = random_zero_mean(f.n, 5);
  RowMatrixX3d tight = RowMatrixX3d::Zero(f.n, 3), loose = tight;
  const CgResult t =
      projected_cg(CsrView::of_symmetric(A), f.amg, b, &tight, CgOptions{1e-12, 0, 200});
  const CgResult l =
      projected_cg(CsrView::of_symmetric(A), f.amg, b, &loose, CgOptions{1e-12, 1e-3, 200});
  EXPECT_TRUE(l.converged);
  EXPECT_LT(l.iterations, t.iterations);
  EXPECT_LE(l.relative_residual, 1e-3);  // the warm start (0) had relative residual 1
  EXPECT_GT(l.relative_residual, 1e-12);
}

TEST(ProjectedCg, NoticesNegativeCurvatureBelowTheBound) {
  const LaplacianFixture f(bar());
  const double bound = f.n / fiedler_value(f.L) - 1;  // (beta + 1) lambda_2 = n
  const Eigen::SparseMatrix<double> A = global_matrix(f, 0.5 * bound);
  RowMatrixX3d x = RowMatrixX3d::Zero(f.n, 3);
  const CgResult r =
      projected_cg(CsrView::of_symmetric(A), f.amg, random_zero_mean(f.n, 6), &x, CgOptions{});
  EXPECT_TRUE(r.negative_curvature);
  EXPECT_FALSE(r.converged);
}

TEST(Lobpcg, SmallestEigenvaluesMatchTheDenseOnes) {
  const LaplacianFixture f(test::grid_tet_mesh(13, 7, 5, 0.3));  // no repeated eigenvalues
  const LobpcgResult r = lobpcg_smallest(CsrView::of_symmetric(f.L), f.amg, LobpcgOptions{1e-10});
  ASSERT_TRUE(r.converged);
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> dense{Eigen::MatrixXd(f.L)};
  EXPECT_NEAR(r.values[0], dense.eigenvalues()[1], 1e-10 * dense.eigenvalues()[1]);
  // The other two are only helpers, converged more loosely.
  EXPECT_NEAR(r.values[1], dense.eigenvalues()[2], 1e-4 * dense.eigenvalues()[2]);
  EXPECT_NEAR(r.values[2], dense.eigenvalues()[3], 1e-4 * dense.eigenvalues()[3]);
  EXPECT_LT(r.vectors.colwise().sum().norm(), 1e-10);
  EXPECT_LT((r.vectors.transpose() * r.vectors - Eigen::Matrix3d::Identity()).norm(), 1e-10);
}

TEST(FiedlerValue, LobpcgAgreesWithShiftInvertLanczos) {
  // An irregular mesh: the demo animal, tetrahedralized.
  const TetMesh tets =
      tetrahedralize(make_articulated_shape(ShapePose::preset(1), 32), TetOptions{});
  const LaplacianFixture f(tets);
  const double direct = fiedler_value(f.L), iterative = fiedler_value(f.L, f.amg);
  EXPECT_NEAR(iterative, direct, 1e-9 * direct);
}

// The auto choice rests on the predicted cost of a factorization: it grows
// faster than n on a volume-filling mesh, never undercuts what the solver's
// own ordering achieves, and moves auto from direct to iterative.
TEST(LinearSolverChoice, FollowsThePredictedFactorizationCost) {
  const auto laplacian = [](int k) {
    const TetMesh mesh = test::grid_tet_mesh(k, k, k);
    return graph_laplacian(build_edge_graph(int(mesh.V.rows()), mesh.T));
  };
  const Eigen::SparseMatrix<double> small = laplacian(8), large = laplacian(16);
  const double small_flops = predicted_factorization_flops(small);
  const double large_flops = predicted_factorization_flops(large);
  EXPECT_GT(large_flops, 20 * small_flops);  // 8x the vertices
  SparseLdlt ldlt;
  ldlt.analyze(large);
  EXPECT_LE(ldlt.factor_flops(), large_flops * (1 + 1e-12));
  LinearSolverOptions options;
  options.direct_max_gflop = 2e-9 * large_flops;
  EXPECT_FALSE(use_iterative_solver(options, large));
  options.direct_max_gflop = 0.5e-9 * large_flops;
  EXPECT_TRUE(use_iterative_solver(options, large));
  options.method = "direct";
  EXPECT_FALSE(use_iterative_solver(options, large));
}

// A bar bent into an arc: the cascade has real work to do.
struct BentBar : test::ProblemFixture {
  explicit BentBar(const EnergyOptions& energy = {}) : ProblemFixture(bent(), energy) {}
  static TetMesh bent() {
    TetMesh mesh = bar();
    for (Eigen::Index i = 0; i < mesh.V.rows(); ++i) {
      const double angle = 0.35 * mesh.V(i, 0), radius = 3 + mesh.V(i, 1);
      mesh.V.row(i) << radius * std::sin(angle), radius * std::cos(angle), mesh.V(i, 2);
    }
    return mesh;
  }
};

CascadeResult cascade_with(const BentBar& f, const LinearSolverOptions& solver) {
  CascadeOptions options;
  options.beta = 1.5 * f.n / f.lambda2;
  LocalGlobalBackend backend(f.problem, solver);
  EXPECT_EQ(backend.data().iterative, solver.method == "iterative");
  return run_cascade(f.problem, backend, options);
}

TEST(IterativeCascade, EndsWhereTheDirectSolverEnds) {
  const BentBar f;
  const CascadeResult direct = cascade_with(f, LinearSolverOptions{"direct"});
  const double scale = direct.positions.cwiseAbs().maxCoeff();
  // Default tolerances: each global step to 1e-2 of its warm start's residual.
  const CascadeResult fast = cascade_with(f, LinearSolverOptions{"iterative"});
  EXPECT_EQ(fast.cascades, direct.cascades);
  EXPECT_NEAR(fast.iterations, direct.iterations, 2);
  EXPECT_LT((fast.positions - direct.positions).cwiseAbs().maxCoeff(), 1e-3 * scale);
  EXPECT_NEAR(fast.edge_ratio, direct.edge_ratio, 1e-3);
  // Every global step solved tightly: the same iterates as the direct solver.
  LinearSolverOptions tight{"iterative"};
  tight.cg_tolerance = 1e-12;
  tight.cg_forcing = 0;
  const CascadeResult exact = cascade_with(f, tight);
  EXPECT_EQ(exact.iterations, direct.iterations);
  EXPECT_LT((exact.positions - direct.positions).cwiseAbs().maxCoeff(), 1e-8 * scale);
}

// The AMG is built from the beta Laplacian whatever the terms: cotangent
// weights, and user pairs, whose long-range edges join the graph.
TEST(IterativeCascade, AgreesWithTheDirectSolverForOtherTerms) {
  EnergyOptions cotangent;
  cotangent.arap_weights = "cotangent";
  BentBar with_pairs;
  UserPair ends;
  ends.j = with_pairs.n - 1;  // the bar's far corner
  ends.t = Eigen::Vector3d(-12, 0, 0);
  with_pairs.problem.terms.push_back(
      std::make_unique<UserPairsEnergy>(std::vector{ends}, with_pairs.n, 1.0));
  with_pairs.lambda2 = fiedler_value(beta_laplacian(with_pairs.problem));
  const BentBar cotangent_bar(cotangent);
  for (const BentBar* f : std::initializer_list<const BentBar*>{&with_pairs, &cotangent_bar}) {
    const CascadeResult direct = cascade_with(*f, LinearSolverOptions{"direct"});
    const CascadeResult fast = cascade_with(*f, LinearSolverOptions{"iterative"});
    EXPECT_EQ(fast.cascades, direct.cascades);
    EXPECT_LT((fast.positions - direct.positions).cwiseAbs().maxCoeff(),
              1e-3 * direct.positions.cwiseAbs().maxCoeff());
  }
}

TEST(IterativeCascade, EnergyNeverIncreasesWithinACascade) {
  const BentBar f;
  const CascadeResult result = cascade_with(f, LinearSolverOptions{"iterative"});
  ASSERT_GT(result.iterations, 4);
  test::expect_energy_non_increasing_within_cascades(result);
}

TEST(GlobalStepEnergy, EqualsTheSumOfTheTermsBothSolvers) {
  const BentBar f;
  const double beta = 2 * f.n / f.lambda2;
  for (const char* method : {"direct", "iterative"}) {
    LocalGlobalData data;
    local_global_precomputation(f.problem, &data, LinearSolverOptions{method});
    local_global_set_beta(beta, &data);
    Eigen::MatrixX3d Q = f.mesh.V;
    Q.rowwise() -= Q.colwise().mean();
    Rotations R;
    for (int k = 0; k < 3; ++k) {
      fit_rotations(f.problem, Q, beta, &R);
      global_step(data, R, &Q);
      const double swept = total_energy(f.problem, Q, R, beta);
      EXPECT_NEAR(energy_after_global_step(data, R, Q), swept, 1e-10 * std::abs(swept)) << method;
    }
  }
}

}  // namespace
}  // namespace unfold
