// The local-global solver: rotation fit, global step optimality, monotone
// energy within a cascade, and the beta bound.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <cmath>

#include "core/errors.h"
#include "energies/user_pairs_energy.h"
#include "geometry/best_rotation.h"
#include "mesh/best_rotations.h"
#include "solvers/cascade.h"
#include "solvers/fiedler_value.h"
#include "solvers/local_global.h"
#include "test_meshes.h"
#include "test_problem.h"

namespace unfold {
namespace {

TEST(SolverRotation, RecoversKnownRotationExactly) {
  const TetMesh mesh = test::grid_tet_mesh(3, 2, 2);
  const EdgeGraph g = build_edge_graph(int(mesh.V.rows()), mesh.T);
  const Eigen::Matrix3d R0 = test::random_rotation(7);
  const Eigen::MatrixX3d Q = (mesh.V * R0.transpose()).rowwise() + Eigen::RowVector3d(1, -2, 3);
  Rotations R;
  best_rotations(g, mesh.V, Q, &R);
  for (const auto& Ri : R) EXPECT_LT((Ri - R0).norm(), 1e-12);
}

TEST(SolverRotation, NeverReturnsAReflection) {
  const TetMesh mesh = test::grid_tet_mesh(2, 2, 2);
  const EdgeGraph g = build_edge_graph(int(mesh.V.rows()), mesh.T);
  Eigen::MatrixX3d Q = mesh.V;
  Q.col(0) *= -1;  // a mirror image: the best proper rotation is not the mirror
  Rotations R;
  best_rotations(g, mesh.V, Q, &R);
  for (const auto& Ri : R) {
    EXPECT_NEAR(Ri.determinant(), 1.0, 1e-12);
    EXPECT_LT((Ri * Ri.transpose() - Eigen::Matrix3d::Identity()).norm(), 1e-12);
  }
}

// cov = H R0^T with H symmetric positive definite: the best rotation is R0.
Eigen::Matrix3d covariance_for(const Eigen::Matrix3d& R0, unsigned seed) {
  std::srand(seed);
  const Eigen::Matrix3d A = Eigen::Matrix3d::Random();
  const Eigen::Matrix3d H = A * A.transpose() + 0.2 * Eigen::Matrix3d::Identity();
  return H * R0.transpose();
}

TEST(SolverRotation, RefinedFromAGuessAgreesWithTheColdFit) {
  for (unsigned seed = 1; seed <= 20; ++seed) {
    const Eigen::Matrix3d R0 = test::random_rotation(seed);
    const Eigen::Matrix3d cov = covariance_for(R0, seed + 100);
    ASSERT_LT((best_rotation(cov) - R0).norm(), 1e-12);
    // Near guesses (Newton), a far one and the opposite critical point (fallback).
    for (const double angle : {1e-4, 0.05, 0.4, 3.0, M_PI}) {
      const Eigen::Matrix3d turn =
          Eigen::AngleAxisd(angle, Eigen::Vector3d(1, 2, -1).normalized()).toRotationMatrix();
      EXPECT_LT((best_rotation(cov, R0 * turn) - R0).norm(), 1e-11)
          << "seed " << seed << ", guess " << angle << " rad off";
    }
  }
}

// cov = H R0^T with H symmetric of eigenvalues 3, 1 and `weakest` along random
// axes: 0 is a flat cell (all its edges in a plane), below 0 a reflected one.
// The best rotation is still R0 (Y = H, G = tr(H) I - H positive definite).
TEST(SolverRotation, FlatAndReflectedCellsFromAGuessOrAtAnotherCriticalPoint) {
  for (const double weakest : {0.0, -0.2, 1e-9}) {
    for (unsigned seed = 1; seed <= 10; ++seed) {
      const Eigen::Matrix3d R0 = test::random_rotation(seed);
      const Eigen::Matrix3d Q = test::random_rotation(seed + 50);
      const Eigen::Matrix3d H = Q * Eigen::Vector3d(3, 1, weakest).asDiagonal() * Q.transpose();
      const Eigen::Matrix3d cov = H * R0.transpose();
      ASSERT_LT((best_rotation(cov) - R0).norm(), 1e-12) << "weakest " << weakest;
      for (const double angle : {1e-4, 0.05, 0.4}) {
        const Eigen::Matrix3d turn =
            Eigen::AngleAxisd(angle, Eigen::Vector3d(1, 2, -1).normalized()).toRotationMatrix();
        EXPECT_LT((best_rotation(cov, R0 * turn) - R0).norm(), 1e-11)
            << "weakest " << weakest << ", seed " << seed << ", guess " << angle << " rad off";
      }
      // The other critical points, R0 turned by pi about a principal axis: Y
      // is symmetric there too, but G is not positive definite.
      for (int axis = 0; axis < 3; ++axis) {
        Eigen::Vector3d flip = -Eigen::Vector3d::Ones();
        flip(axis) = 1;
        const Eigen::Matrix3d critical = R0 * Q * flip.asDiagonal() * Q.transpose();
        EXPECT_LT((best_rotation(cov, critical) - R0).norm(), 1e-11)
            << "weakest " << weakest << ", seed " << seed << ", axis " << axis;
      }
    }
  }
}

// A packet mixes cells Newton settles, far guesses and critical points that
// fall back to the cold fit, and flat cells: each lane's rotation is the one
// of that cell refined alone, bit for bit, whatever the other lanes hold.
TEST(SolverRotation, APacketsCellsAreEachRefinedAsAlone) {
  std::vector<Eigen::Matrix3d> cov, guess, expected, alone;
  for (unsigned seed = 1; seed <= 3 * kRotationPacket; ++seed) {
    const Eigen::Matrix3d R0 = test::random_rotation(seed);
    const Eigen::Matrix3d Q = test::random_rotation(seed + 50);
    const double weakest = seed % 3 == 0 ? 0.0 : 0.5;
    cov.push_back(Q * Eigen::Vector3d(3, 1, weakest).asDiagonal() * Q.transpose() * R0.transpose());
    const double angle = std::vector<double>{1e-4, 0.05, 3.0, 0.4}[seed % 4];
    guess.push_back(
        R0 * Eigen::AngleAxisd(angle, Eigen::Vector3d(1, 2, -1).normalized()).toRotationMatrix());
    expected.push_back(R0);
    alone.push_back(best_rotation(cov.back(), guess.back()));
  }
  for (int count = 1; count <= kRotationPacket; ++count)
    for (size_t first = 0; first + size_t(count) <= cov.size(); first += size_t(count)) {
      std::vector<Eigen::Matrix3d> R(guess.begin() + long(first),
                                     guess.begin() + long(first) + count);
      std::vector<const Eigen::Matrix3d*> c;
      std::vector<Eigen::Matrix3d*> r;
      for (int k = 0; k < count; ++k) {
        c.push_back(&cov[first + size_t(k)]);
        r.push_back(&R[size_t(k)]);
      }
      best_rotations_from_guesses(c.data(), r.data(), count);
      for (int k = 0; k < count; ++k) {
        EXPECT_EQ(R[size_t(k)], alone[first + size_t(k)]) << "cell " << first + size_t(k);
        EXPECT_LT((R[size_t(k)] - expected[first + size_t(k)]).norm(), 1e-11);
      }
    }
}

TEST(SolverFiedler, MatchesDenseEigenvalues) {
  const TetMesh mesh = test::grid_tet_mesh(5, 3, 2);
  const EdgeGraph g = build_edge_graph(int(mesh.V.rows()), mesh.T);
  const Eigen::SparseMatrix<double> L = graph_laplacian(g);
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> dense{Eigen::MatrixXd(L)};
  EXPECT_NEAR(dense.eigenvalues()(0), 0.0, 1e-10);
  EXPECT_NEAR(fiedler_value(L), dense.eigenvalues()(1), 1e-9);
}

// Started from the vector of the graph before some edges were weakened (soft
// joints), lambda_2 of the reweighted graph is the one found without a start.
TEST(SolverFiedler, StartedFromANearbyProblemsVectorFindsTheSameValue) {
  const TetMesh mesh = test::grid_tet_mesh(12, 3, 2);
  const EdgeGraph g = build_edge_graph(int(mesh.V.rows()), mesh.T);
  const Eigen::SparseMatrix<double> L = graph_laplacian(g);
  Eigen::VectorXd masses = Eigen::VectorXd::LinSpaced(L.rows(), 0.5, 2.0);
  const FiedlerPair before = fiedler_pair(L, masses);
  EXPECT_DOUBLE_EQ(before.value, fiedler_value(L, masses));
  ASSERT_EQ(before.vector.size(), L.rows());
  // Edges across the middle at half their weight.
  std::vector<Eigen::Triplet<double>> weakened;
  for (int e = 0; e < g.num_edges(); ++e) {
    const int i = g.edges(e, 0), j = g.edges(e, 1);
    const bool middle =
        std::min(mesh.V(i, 0), mesh.V(j, 0)) < 6 && std::max(mesh.V(i, 0), mesh.V(j, 0)) >= 6;
    const double w = middle ? 0.5 : 1.0;
    weakened.insert(weakened.end(), {{i, i, w}, {j, j, w}, {i, j, -w}, {j, i, -w}});
  }
  Eigen::SparseMatrix<double> L2(L.rows(), L.cols());
  L2.setFromTriplets(weakened.begin(), weakened.end());
  const FiedlerPair started = fiedler_pair(L2, masses, before.vector);
  const double fresh = fiedler_value(L2, masses);
  EXPECT_LT(fresh, before.value);
  EXPECT_NEAR(started.value, fresh, 1e-10 * fresh);
  // The vector found is an eigenvector: M^{-1/2} L2 M^{-1/2} v = lambda v.
  const Eigen::VectorXd s = masses.cwiseSqrt().cwiseInverse();
  const Eigen::VectorXd v = started.vector.normalized();
  EXPECT_LT((s.asDiagonal() * (L2 * (s.asDiagonal() * v)) - started.value * v).norm(),
            1e-6 * started.value);
  EXPECT_THROW(fiedler_pair(L2, masses, Eigen::VectorXd::Ones(3)), UsageError);
}

struct Fixture : test::ProblemFixture {
  Fixture() : ProblemFixture(test::grid_tet_mesh(6, 2, 2, 0.5)) {}
};

TEST(SolverGlobalStep, ZeroesTheEnergyGradientAtFixedRotations) {
  Fixture f;
  const double beta = 1.5 * f.n / f.lambda2;
  LocalGlobalData data;
  local_global_precomputation(f.problem, &data);
  local_global_set_beta(beta, &data);
  // Rotations from a bent pose, so that the global step has work to do.
  Eigen::MatrixX3d bent = f.mesh.V;
  for (int i = 0; i < f.n; ++i) bent(i, 1) += 0.3 * bent(i, 0) * bent(i, 0);
  Rotations R;
  best_rotations(*f.graph, f.mesh.V, bent, &R);
  Eigen::MatrixX3d Q;
  global_step(data, R, &Q);
  Eigen::MatrixX3d grad;
  total_energy(f.problem, Q, R, beta, &grad);
  Eigen::MatrixX3d grad_at_bent;
  total_energy(f.problem, bent, R, beta, &grad_at_bent);
  EXPECT_LT(grad.norm(), 1e-9 * grad_at_bent.norm());
  EXPECT_LT(Q.colwise().mean().norm(), 1e-12);
}

// The energy from the local step's covariances is the residuals' sum, with the
// paper's uniform masses (whose 1 1^T part A leaves out) and with user pairs
// (a linear part free of the rotations).
TEST(SolverEnergy, FromTheCovariancesIsTheTotal) {
  Fixture f;
  test::expect_energy_from_covariances_is_the_total(f, 1.5 * f.n / f.lambda2);
  std::vector<UserPair> pairs = {{0, f.n - 1, Eigen::Vector3d(4, 1, 0)},
                                 {3, 7, Eigen::Vector3d(0, 0, 1)}};
  f.problem.terms.push_back(std::make_unique<UserPairsEnergy>(pairs, f.n, 1.0));
  test::expect_energy_from_covariances_is_the_total(f, 2.0 * f.n / f.lambda2);
}

TEST(SolverGlobalStep, GlobalStepIsTheMinimiserAlongRandomDirections) {
  Fixture f;
  const double beta = 2.0 * f.n / f.lambda2;
  LocalGlobalData data;
  local_global_precomputation(f.problem, &data);
  local_global_set_beta(beta, &data);
  Rotations R(size_t(f.n), test::random_rotation(3));
  Eigen::MatrixX3d Q;
  global_step(data, R, &Q);
  const double e0 = total_energy(f.problem, Q, R, beta);
  std::srand(11);
  for (int trial = 0; trial < 5; ++trial) {
    const Eigen::MatrixX3d D = 1e-2 * Eigen::MatrixX3d::Random(f.n, 3);
    EXPECT_GT(total_energy(f.problem, Q + D, R, beta), e0);
  }
}

TEST(SolverBetaBound, QuadraticPartIndefiniteBelowTheBound) {
  Fixture f;
  const double threshold = f.n / f.lambda2 - 1.0;  // (beta + 1) lambda_2 = n
  LocalGlobalData data;
  local_global_precomputation(f.problem, &data);
  local_global_set_beta(1.01 * threshold, &data);
  EXPECT_TRUE(energy_bounded(data));
  EXPECT_EQ(data.negative_pivots, 1);
  local_global_set_beta(0.99 * threshold, &data);
  EXPECT_FALSE(energy_bounded(data));

  // Below the bound the Fiedler direction lowers the energy without limit.
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> dense{Eigen::MatrixXd(graph_laplacian(*f.graph))};
  const Eigen::VectorXd fiedler = dense.eigenvectors().col(1);
  Eigen::MatrixX3d D = Eigen::MatrixX3d::Zero(f.n, 3);
  D.col(0) = fiedler;
  const Rotations R(size_t(f.n), Eigen::Matrix3d::Identity());
  auto energy_along = [&](double beta, double t) {
    return total_energy(f.problem, f.mesh.V + t * D, R, beta);
  };
  const double below = 0.99 * threshold, above = 1.01 * threshold;
  EXPECT_LT(energy_along(below, 1e4), energy_along(below, 1e3));
  EXPECT_GT(energy_along(above, 1e4), energy_along(above, 1e3));
}

TEST(SolverCascade, EnergyNeverIncreasesWithinACascade) {
  Fixture f;
  CascadeOptions options;
  options.beta = 1.5 * f.n / f.lambda2;
  options.edge_ratio_band = {-1, -1};  // run every cascade to its end
  LocalGlobalBackend backend(f.problem);
  const CascadeResult result = run_cascade(f.problem, backend, options);
  ASSERT_GT(result.iterations, 4);
  test::expect_energy_non_increasing_within_cascades(result);
}

TEST(SolverCascade, BreakInBandStopsAtTheFirstIterateInsideElseTheCascadeFinishes) {
  Fixture f;
  CascadeOptions options;
  options.beta = 1.5 * f.n / f.lambda2;
  options.anderson = 0;
  options.edge_ratio_band = {-1, -1};
  const auto run = [&] {  // a fresh backend: the local step warm-starts from its rotations
    LocalGlobalBackend backend(f.problem);
    return run_cascade(f.problem, backend, options);
  };
  const CascadeResult free = run();
  ASSERT_GT(free.history.size(), 3u);
  ASSERT_EQ(free.history[2].cascade, 1);
  // A band around the second and third iterates of the first cascade.
  const double a = free.history[1].edge_ratio, b = free.history[2].edge_ratio;
  options.edge_ratio_band = {std::min(a, b), std::max(a, b)};
  options.break_in_band = true;
  const CascadeResult stopped = run();
  EXPECT_TRUE(stopped.reached_band);
  EXPECT_EQ(stopped.iterations, 2);
  options.break_in_band = false;
  const CascadeResult finished = run();
  EXPECT_GT(finished.iterations, 3);
  for (int k = 0; k < 3; ++k)
    EXPECT_EQ(finished.history[size_t(k)].edge_ratio, free.history[size_t(k)].edge_ratio);
  EXPECT_EQ(finished.reached_band, finished.edge_ratio >= options.edge_ratio_band[0] &&
                                       finished.edge_ratio <= options.edge_ratio_band[1]);
}

TEST(SolverCascade, RigidInputStaysRigidAndSpreads) {
  // A straight bar is already unfolded: the cascade keeps it close to rigid.
  Fixture f;
  CascadeOptions options;
  options.beta = 1.5 * f.n / f.lambda2;
  LocalGlobalBackend backend(f.problem);
  const CascadeResult result = run_cascade(f.problem, backend, options);
  EXPECT_TRUE(result.bounded);
  EXPECT_GT(result.edge_ratio, 0.95);
  EXPECT_LT(result.edge_ratio, 1.3);
}

TEST(SolverCascade, WarmStartFromItsSolutionStaysThere) {
  // A converged solve, then the same solve from its solution: the energy is
  // already stationary, so the second stops at once where the first ended.
  Fixture f;
  CascadeOptions options;
  options.beta = 1.5 * f.n / f.lambda2;
  options.num_cascades = 1;
  options.k_iter = 3000;
  options.epsilon = 1e-12;
  options.break_in_band = false;
  LocalGlobalBackend backend(f.problem);
  const CascadeResult cold = run_cascade(f.problem, backend, options);
  ASSERT_GT(cold.iterations, 5);
  const CascadeResult warm = run_cascade(f.problem, backend, options, &cold.positions);
  EXPECT_LE(warm.iterations, 3);
  EXPECT_LT((warm.positions - cold.positions).cwiseAbs().maxCoeff(),
            1e-5 * cold.positions.cwiseAbs().maxCoeff());
  EXPECT_NEAR(warm.final_energy, cold.final_energy, 1e-9 * std::abs(cold.final_energy));
  const Eigen::MatrixX3d too_few = cold.positions.topRows(2);
  EXPECT_THROW(run_cascade(f.problem, backend, options, &too_few), UsageError);
}

}  // namespace
}  // namespace unfold
