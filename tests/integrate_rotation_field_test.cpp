// Integrating a rotation field (integrate: in the config): rotations are
// recovered, scale is dropped, and the result turns with its input.
#include "solvers/integrate_rotation_field.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <utility>
#include <vector>

#include "core/errors.h"
#include "metrics/rigid_alignment.h"
#include "solvers/fiedler_value.h"
#include "test_meshes.h"

namespace unfold {
namespace {

struct Grid {
  explicit Grid(int length = 6) : mesh(test::grid_tet_mesh(length, 3, 3)) {}
  TetMesh mesh;
  EdgeGraph graph = build_edge_graph(int(mesh.V.rows()), mesh.T);
  double lambda2 = fiedler_value(graph_laplacian(graph));
  Eigen::MatrixX3d centred() const { return mesh.V.rowwise() - mesh.V.colwise().mean(); }
};

IntegrateOptions steps(int iterations) {
  IntegrateOptions options;
  options.iterations = iterations;
  return options;
}

TEST(IntegrateRotationField, RecoversARigidMotion) {
  const Grid g;
  const Eigen::Matrix3d R = test::random_rotation(3);
  const Eigen::MatrixX3d Q = (g.mesh.V * R.transpose()).rowwise() + Eigen::RowVector3d(4, 5, 6);
  const Eigen::MatrixX3d X = integrate_rotation_field(g.graph, g.mesh.V, Q, g.lambda2, steps(5));
  EXPECT_LT((X - g.centred() * R.transpose()).cwiseAbs().maxCoeff(), 1e-8);
}

// An inflated, rotated copy (as a converged low-beta solve is): the
// integration keeps the orientation and drops the inflation.
TEST(IntegrateRotationField, DropsAUniformScale) {
  const Grid g;
  const Eigen::Matrix3d R = test::random_rotation(11);
  const Eigen::MatrixX3d Q = 3.0 * g.mesh.V * R.transpose();
  const Eigen::MatrixX3d X = integrate_rotation_field(g.graph, g.mesh.V, Q, g.lambda2, steps(1));
  EXPECT_LT((X - g.centred() * R.transpose()).cwiseAbs().maxCoeff(), 1e-8);
}

// A bar bent along an arc, then its cross-sections inflated 1.6 times: the
// result keeps the bend (much nearer the bent bar than the straight one) and
// drops the inflation.
TEST(IntegrateRotationField, KeepsABendAndDropsTheInflation) {
  const Grid g;
  const auto bend = [&](double puff) {
    Eigen::MatrixX3d X = g.mesh.V;
    const double radius = 5;
    for (int i = 0; i < X.rows(); ++i) {
      const double t = g.mesh.V(i, 0) / radius, y = g.mesh.V(i, 1) - 1.5;
      const double z = g.mesh.V(i, 2) - 1.5;
      X(i, 0) = (radius - puff * z) * std::sin(t);
      X(i, 1) = puff * y;
      X(i, 2) = radius - (radius - puff * z) * std::cos(t);
    }
    return X;
  };
  const Eigen::MatrixX3d bent = bend(1.0), puffed = bend(1.6);
  const Eigen::MatrixX3d X =
      integrate_rotation_field(g.graph, g.mesh.V, puffed, g.lambda2, steps(20));
  const double to_bent = aligned_distance(X, bent), to_straight = aligned_distance(X, g.mesh.V);
  EXPECT_LT(to_bent, 0.5 * to_straight) << to_bent << " vs " << to_straight;
  EXPECT_LT(to_bent, 0.25 * aligned_distance(puffed, bent));
}

// The anchored steps' report: with a cap of two steps and no tolerance, two
// and not converged; with room and a tolerance, fewer than the cap and
// converged; without anchored steps, none and converged.
TEST(IntegrateRotationField, AnchoredStepsReportTheirCountAndConvergence) {
  const Grid g;
  Eigen::MatrixX3d Q = 1.5 * g.mesh.V;  // inflated, and its bar waved
  Q.col(1) += 0.4 * g.mesh.V.col(0).array().sin().matrix();
  const auto run = [&](int iterations, double tolerance) {
    IntegrateOptions options = steps(iterations);
    options.tolerance = tolerance;
    ArapSolveReport report;
    anchored_steps(g.graph, g.mesh.V, integrate_rotations(g.graph, g.mesh.V, Q, g.lambda2, options),
                   &report);
    return report;
  };
  const ArapSolveReport capped = run(3, 0);
  EXPECT_EQ(capped.steps, 2);
  EXPECT_FALSE(capped.converged);
  const ArapSolveReport room = run(500, 1e-6);
  EXPECT_GT(room.steps, 0);
  EXPECT_LT(room.steps, 499);
  EXPECT_TRUE(room.converged);
  const ArapSolveReport none = run(1, 1e-6);
  EXPECT_EQ(none.steps, 0);
  EXPECT_TRUE(none.converged);
}

IntegrateOptions pulled(int iterations, double pose_pull) {
  IntegrateOptions options = steps(iterations);
  options.pose_pull = pose_pull;
  return options;
}

// Q a similarity of the rest shape: the integration recovers its rotation, the
// fitted Q is the integrated field itself, and a pull changes nothing.
TEST(IntegrateRotationField, APosePullTowardASimilarityOfTheResultChangesNothing) {
  const Grid g;
  const Eigen::Matrix3d R = test::random_rotation(7);
  const Eigen::MatrixX3d Q =
      (2.5 * g.mesh.V * R.transpose()).rowwise() + Eigen::RowVector3d(1, 2, 3);
  const Eigen::MatrixX3d X =
      integrate_rotation_field(g.graph, g.mesh.V, Q, g.lambda2, pulled(5, 1));
  EXPECT_LT((X - g.centred() * R.transpose()).cwiseAbs().maxCoeff(), 1e-8);
}

// Q that similarity with noise at every vertex: the steps start from the pull
// low-pass filtered, so a full pull ends far nearer the rest shape than Q's own
// shape is (an unfiltered full pull would end at Q's shape); so too with the
// anchor shared by stiffness, whose filter weighs each vertex's pull by its anchor.
TEST(IntegrateRotationField, APosePullFiltersOutTheSolvesNoise) {
  const Grid g(12);
  const Eigen::Matrix3d R = test::random_rotation(9);
  const Eigen::MatrixX3d noise = 0.3 * Eigen::MatrixX3d::Random(g.mesh.V.rows(), 3);
  const Eigen::MatrixX3d Q = 2.0 * (g.mesh.V + noise) * R.transpose();
  const Eigen::MatrixX3d rest = g.centred() * R.transpose();
  for (const char* shared : {"uniform", "stiffness"}) {
    IntegrateOptions options = pulled(20, 1);
    options.anchor_weights = shared;
    const Eigen::MatrixX3d X = integrate_rotation_field(g.graph, g.mesh.V, Q, g.lambda2, options);
    EXPECT_LT(aligned_distance(X, rest), 0.3 * aligned_distance(Q / 2.0, rest)) << shared;
  }
}

// The pull acts through the anchored steps' filter: with no anchored steps
// (one step, or no anchor) there is none, and the result is the pull-free one.
TEST(IntegrateRotationField, APosePullWithoutAnchoredStepsIsNoPull) {
  const Grid g;
  const Eigen::MatrixX3d Q = 1.5 * g.mesh.V + 0.3 * Eigen::MatrixX3d::Random(g.mesh.V.rows(), 3);
  IntegrateOptions unanchored = pulled(6, 0.5);
  unanchored.anchor = 0;
  for (IntegrateOptions options : {pulled(1, 0.5), unanchored}) {
    const Eigen::MatrixX3d pulled_x =
        integrate_rotation_field(g.graph, g.mesh.V, Q, g.lambda2, options);
    options.pose_pull = 0;
    const Eigen::MatrixX3d x = integrate_rotation_field(g.graph, g.mesh.V, Q, g.lambda2, options);
    EXPECT_EQ((pulled_x - x).cwiseAbs().maxCoeff(), 0.0);
  }
  // With anchored steps the same pull moves the result.
  const Eigen::MatrixX3d pulled_x =
      integrate_rotation_field(g.graph, g.mesh.V, Q, g.lambda2, pulled(6, 0.5));
  const Eigen::MatrixX3d x = integrate_rotation_field(g.graph, g.mesh.V, Q, g.lambda2, steps(6));
  EXPECT_GT((pulled_x - x).cwiseAbs().maxCoeff(), 1e-3);
}

TEST(IntegrateRotationField, TurnsWithItsInput) {
  const Grid g;
  Eigen::MatrixX3d Q = g.mesh.V + 0.3 * Eigen::MatrixX3d::Random(g.mesh.V.rows(), 3);
  const Eigen::Matrix3d R = test::random_rotation(5);
  const Eigen::MatrixX3d X = integrate_rotation_field(g.graph, g.mesh.V, Q, g.lambda2, steps(8));
  const Eigen::MatrixX3d Y =
      integrate_rotation_field(g.graph, g.mesh.V, Q * R.transpose(), g.lambda2, steps(8));
  EXPECT_LT((Y - X * R.transpose()).cwiseAbs().maxCoeff(), 1e-6);
}

// The steps renumbered in locality order (as from 100k vertices) end where
// they do in the caller's order, to rounding, with every option that touches
// the vertices' or edges' order: edge factors, a pull, the anchor by stiffness.
TEST(IntegrateRotationField, RenumberingChangesOnlyTheRounding) {
  const Grid g(10);
  Eigen::MatrixX3d Q = 1.4 * g.mesh.V;
  Q.col(1) += 0.5 * g.mesh.V.col(0).array().sin().matrix();
  std::vector<double> factors(size_t(g.graph.num_edges()));
  for (size_t e = 0; e < factors.size(); ++e) factors[e] = 0.5 + double(e % 7) / 7;
  IntegrateOptions options = pulled(12, 0.5);
  options.anchor_weights = "stiffness";
  options.lbfgs = 5;
  ArapSolveReport in_order, renumbered;
  const Eigen::MatrixX3d X = anchored_steps(
      g.graph, g.mesh.V, integrate_rotations(g.graph, g.mesh.V, Q, g.lambda2, options, factors),
      &in_order);
  options.locality_order_vertices = 0;
  IntegratedRotations r = integrate_rotations(g.graph, g.mesh.V, Q, g.lambda2, options, factors);
  ASSERT_TRUE(r.reordered);
  const std::vector<int>& order = r.reordered->order;
  EXPECT_EQ(order[0], 0);  // the held vertex
  EXPECT_FALSE(std::is_sorted(order.begin(), order.end()));
  const Eigen::MatrixX3d Y = anchored_steps(g.graph, g.mesh.V, std::move(r), &renumbered);
  EXPECT_LT((X - Y).cwiseAbs().maxCoeff(), 1e-8);
  EXPECT_GT((X - g.centred()).cwiseAbs().maxCoeff(), 0.1);  // the steps moved it
  EXPECT_EQ(in_order.steps, renumbered.steps);
}

// From options.multigrid_vertices the anchored steps (L-BFGS) use a V-cycle
// for their factor and CG for the pull's filter: no factor is made, and run to
// a tight tolerance they end where the factor's steps do.
TEST(IntegrateRotationField, AMultigridEndsWhereTheFactorDoes) {
  const Grid g(40);  // 656 vertices: a hierarchy of two levels
  Eigen::MatrixX3d Q = 1.4 * g.mesh.V;
  Q.col(1) += 2 * (0.1 * g.mesh.V.col(0)).array().sin().matrix();
  IntegrateOptions options = pulled(2000, 0.5);
  options.anchor_weights = "stiffness";
  options.lbfgs = 5;
  options.tolerance = 1e-9;
  ArapSolveReport by_factor, by_multigrid;
  const Eigen::MatrixX3d X = anchored_steps(
      g.graph, g.mesh.V, integrate_rotations(g.graph, g.mesh.V, Q, g.lambda2, options), &by_factor);
  options.multigrid_vertices = 0;
  IntegratedRotations r = integrate_rotations(g.graph, g.mesh.V, Q, g.lambda2, options);
  EXPECT_TRUE(r.anchored_multigrid.valid());
  EXPECT_FALSE(r.anchored_factor.valid());
  const Eigen::MatrixX3d Y = anchored_steps(g.graph, g.mesh.V, std::move(r), &by_multigrid);
  EXPECT_TRUE(by_factor.converged);
  EXPECT_TRUE(by_multigrid.converged);
  EXPECT_LT((X - Y).cwiseAbs().maxCoeff(), 1e-5);
  EXPECT_GT((X - g.centred()).cwiseAbs().maxCoeff(), 0.1);  // the steps moved it
  options.lbfgs = 0;                                        // local-global steps need the factor
  EXPECT_TRUE(
      integrate_rotations(g.graph, g.mesh.V, Q, g.lambda2, options).anchored_factor.valid());
}

TEST(IntegrateRotationField, RefusesBadOptions) {
  const Grid g;
  EXPECT_THROW(integrate_rotation_field(g.graph, g.mesh.V, g.mesh.V, g.lambda2, steps(-1)),
               UsageError);
  EXPECT_THROW(integrate_rotation_field(g.graph, g.mesh.V, g.mesh.V, 0.0, steps(2)), UsageError);
  EXPECT_THROW(
      integrate_rotation_field(g.graph, g.mesh.V.topRows(5), g.mesh.V, g.lambda2, steps(2)),
      UsageError);
  IntegrateOptions cotangent = steps(2);
  cotangent.weights = "cotangent";
  EXPECT_THROW(integrate_rotation_field(g.graph, g.mesh.V, g.mesh.V, g.lambda2, cotangent),
               UsageError);
  IntegrateOptions shared = steps(2);
  shared.anchor_weights = "mass";
  EXPECT_THROW(integrate_rotation_field(g.graph, g.mesh.V, g.mesh.V, g.lambda2, shared),
               UsageError);
  IntegrateOptions pull = steps(2);
  pull.pose_pull = 1.5;
  EXPECT_THROW(integrate_rotation_field(g.graph, g.mesh.V, g.mesh.V, g.lambda2, pull), UsageError);
}

}  // namespace
}  // namespace unfold
