// The ARAP steps' matrix as a multigrid hierarchy (solvers/arap_multigrid.h):
// its CG solve is the factor's, one V-cycle is a symmetric approximation of
// it, and steps with either end where the factor's steps do.
#include "solvers/arap_multigrid.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/errors.h"
#include "test_meshes.h"

namespace unfold {
namespace {

// A 17 x 9 x 9 grid: over the hierarchy's coarse size, so the V-cycle has
// levels and is not the dense inverse.
struct Grid {
  TetMesh mesh = test::grid_tet_mesh(16, 8, 8);
  EdgeGraph graph = build_edge_graph(int(mesh.V.rows()), mesh.T);
};

ArapSolveOptions anchored() {
  ArapSolveOptions options;
  options.anchor = 0.1;
  options.anchor_by_stiffness = true;
  options.inverse_length_weights = true;
  options.max_iterations = 2000;
  options.tolerance = 1e-9;
  options.lbfgs = 5;
  return options;
}

// The grid bent about the y axis and shaken: what the steps straighten.
Eigen::MatrixX3d bent(const Eigen::MatrixX3d& V) {
  Eigen::MatrixX3d X = V;
  for (int i = 0; i < X.rows(); ++i) {
    const double a = 0.08 * V(i, 0);
    X(i, 0) = std::cos(a) * V(i, 0) - std::sin(a) * V(i, 2);
    X(i, 2) = std::sin(a) * V(i, 0) + std::cos(a) * V(i, 2);
  }
  return X + 0.05 * Eigen::MatrixX3d::Random(X.rows(), 3);
}

TEST(ArapMultigrid, CgSolvesAsTheFactorDoesAndAVcycleIsSymmetric) {
  const Grid g;
  const ArapSolveOptions options = anchored();
  const auto multigrid = arap_multigrid_precomputation(g.graph, g.mesh.V, options);
  ASSERT_GT(multigrid->amg.levels.size(), 1u);
  const int m = int(g.mesh.V.rows()) - 1;
  ASSERT_EQ(multigrid->matrix.rows(), m);
  const Eigen::MatrixX3d b = Eigen::MatrixX3d::Random(m, 3);
  Eigen::MatrixX3d exact, solved, cycled, other;
  arap_factorization(g.graph, g.mesh.V, options)->solve(b, &exact);
  arap_multigrid_solve(*multigrid, b, &solved, 1e-10);
  EXPECT_LT((solved - exact).norm(), 1e-8 * exact.norm());
  // The default tolerance: each column's residual within 1e-6 of its right side's.
  arap_multigrid_solve(*multigrid, b, &solved);
  const Eigen::MatrixX3d residual = multigrid->matrix * solved - b;
  for (int c = 0; c < 3; ++c) EXPECT_LE(residual.col(c).norm(), 1e-6 * b.col(c).norm()) << c;
  EXPECT_GT((solved - exact).norm(), 1e-12 * exact.norm());  // not solved to rounding
  // One V-cycle: near the solution, not at it, and symmetric (to float rounding).
  arap_multigrid_vcycle(*multigrid, b, &cycled);
  EXPECT_LT((cycled - exact).norm(), 0.5 * exact.norm());
  EXPECT_GT((cycled - exact).norm(), 1e-6 * exact.norm());
  const Eigen::MatrixX3d c = Eigen::MatrixX3d::Random(m, 3);
  arap_multigrid_vcycle(*multigrid, c, &other);
  const double bc = b.reshaped().dot(other.reshaped()), cb = c.reshaped().dot(cycled.reshaped());
  EXPECT_NEAR(bc, cb, 1e-4 * std::abs(bc));
}

// L-BFGS steps (a V-cycle their initial inverse Hessian) and local-global ones
// (each solved by CG) end where the factor's steps do.
TEST(ArapMultigrid, StepsWithAMultigridEndWhereTheFactorsDo) {
  const Grid g;
  const Eigen::MatrixX3d start = bent(g.mesh.V);
  for (const int lbfgs : {5, 0}) {
    ArapSolveOptions options = anchored();
    options.lbfgs = lbfgs;
    ArapSolveReport by_factor, by_multigrid;
    const Eigen::MatrixX3d X = arap_solve(g.graph, g.mesh.V, start, options, nullptr, &by_factor);
    const auto multigrid = arap_multigrid_precomputation(g.graph, g.mesh.V, options);
    const Eigen::MatrixX3d Y =
        arap_solve(g.graph, g.mesh.V, start, options, nullptr, &by_multigrid, multigrid.get());
    EXPECT_TRUE(by_factor.converged) << lbfgs;
    EXPECT_TRUE(by_multigrid.converged) << lbfgs;
    const double radius =
        std::sqrt((X.rowwise() - X.colwise().mean()).rowwise().squaredNorm().mean());
    EXPECT_LT((X - Y).rowwise().norm().maxCoeff(), 1e-5 * radius) << lbfgs;
    EXPECT_GT((X - start).rowwise().norm().maxCoeff(), 0.05) << lbfgs;  // the steps moved it
  }
}

// The integration's one step: the Laplacian with one vertex held and no anchor
// (nearly singular), solved by CG as by the factor.
TEST(ArapMultigrid, OneUnanchoredStepSolvesAsTheFactorDoes) {
  const Grid g;
  ArapSolveOptions options;
  options.max_iterations = 1;
  options.inverse_length_weights = true;
  const Eigen::MatrixX3d start = 1.5 * bent(g.mesh.V);
  const Eigen::MatrixX3d X = arap_solve(g.graph, g.mesh.V, start, options);
  const auto multigrid = arap_multigrid_precomputation(g.graph, g.mesh.V, options);
  const Eigen::MatrixX3d Y =
      arap_solve(g.graph, g.mesh.V, start, options, nullptr, nullptr, multigrid.get());
  EXPECT_LT((X - Y).cwiseAbs().maxCoeff(), 1e-6);
  EXPECT_GT((X - start).cwiseAbs().maxCoeff(), 0.5);
}

TEST(ArapMultigrid, RefusedWithAFactorOrForAnotherGraph) {
  const Grid g;
  const ArapSolveOptions options = anchored();
  const auto multigrid = arap_multigrid_precomputation(g.graph, g.mesh.V, options);
  const auto factor = arap_factorization(g.graph, g.mesh.V, options);
  EXPECT_THROW(
      arap_solve(g.graph, g.mesh.V, g.mesh.V, options, factor.get(), nullptr, multigrid.get()),
      UsageError);
  ArapSolveOptions two_held = options;
  two_held.num_fixed = 2;
  EXPECT_THROW(arap_solve(g.graph, g.mesh.V, g.mesh.V, two_held, nullptr, nullptr, multigrid.get()),
               UsageError);
  EXPECT_THROW(arap_multigrid_precomputation(g.graph, g.mesh.V.topRows(10), options), UsageError);
}

}  // namespace
}  // namespace unfold
