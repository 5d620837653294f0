// The supernodal LL^T backend of SparseLdlt (what arap_solve factorizes its
// positive definite systems with): the same solution as the LDL^T backends on
// a positive definite matrix, and a NumericalError, not a wrong answer, on one
// that is not. Solves, by the backends' own sweeps, give the known solution.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>

#include "core/errors.h"
#include "mesh/edge_graph.h"
#include "solvers/sparse_ldlt.h"
#include "test_meshes.h"

namespace unfold {
namespace {

// The tet-mesh Laplacian of a bar plus `shift` I: positive definite for shift > 0,
// singular at 0 (the constant vector), indefinite below.
Eigen::SparseMatrix<double> shifted_laplacian(double shift, int nx = 12, int ny = 4, int nz = 4) {
  const TetMesh mesh = test::grid_tet_mesh(nx, ny, nz, 0.5);
  Eigen::SparseMatrix<double> L = graph_laplacian(build_edge_graph(int(mesh.V.rows()), mesh.T));
  Eigen::SparseMatrix<double> I(L.rows(), L.cols());
  I.setIdentity();
  return L + shift * I;
}

TEST(SparseCholesky, SolvesLikeTheLdltBackends) {
  const Eigen::SparseMatrix<double> A = shifted_laplacian(1e-3);
  std::mt19937 random(7);
  std::normal_distribution<double> normal;
  Eigen::MatrixX3d b(A.rows(), 3);
  for (Eigen::Index i = 0; i < b.size(); ++i) b.data()[i] = normal(random);
  Eigen::MatrixX3d x_llt, x_ldlt;
  SparseLdlt llt(SparseLdlt::Backend::kCholmodCholesky), ldlt(SparseLdlt::Backend::kCholmod);
  llt.analyze(A);
  llt.factorize(A);
  llt.solve(b, &x_llt);
  ldlt.analyze(A);
  ldlt.factorize(A);
  ldlt.solve(b, &x_ldlt);
  EXPECT_LT((A * x_llt - b).norm(), 1e-9 * b.norm());
  EXPECT_LT((x_llt - x_ldlt).norm(), 1e-9 * x_ldlt.norm());
  EXPECT_EQ(llt.negative_pivots(), 0);
  // Eigen's backend too.
  SparseLdlt eigen(SparseLdlt::Backend::kEigen);
  eigen.analyze(A);
  eigen.factorize(A);
  Eigen::MatrixX3d x_eigen;
  eigen.solve(b, &x_eigen);
  EXPECT_LT((x_eigen - x_ldlt).norm(), 1e-9 * x_ldlt.norm());
  // A new factorization with the same pattern (the analysis reused).
  const Eigen::SparseMatrix<double> A2 = shifted_laplacian(1.0);
  llt.factorize(A2);
  llt.solve(b, &x_llt);
  EXPECT_LT((A2 * x_llt - b).norm(), 1e-9 * b.norm());
}

// The CHOLMOD backends' own sweeps (three columns in one pass, through a
// fill-reducing permutation; by subtrees from 20,000 rows) give the solution
// of A x = b for a known x, column by column: a swapped or stale column would
// be off by O(1). (Known rather than Eigen's solve: its factorization was most
// of the test's time, and its own error is of the order of the backends'.)
TEST(SparseCholesky, LargeSolvesGiveTheKnownSolution) {
  const Eigen::SparseMatrix<double> A = shifted_laplacian(1e-3, 40, 25, 20);  // 22k rows
  std::mt19937 random(11);
  std::normal_distribution<double> normal;
  Eigen::MatrixX3d expected(A.rows(), 3);
  for (Eigen::Index i = 0; i < expected.size(); ++i) expected.data()[i] = normal(random);
  const Eigen::MatrixX3d b = A * expected;
  for (const auto backend :
       {SparseLdlt::Backend::kCholmodCholesky, SparseLdlt::Backend::kCholmod}) {
    SparseLdlt ldlt(backend);
    ldlt.analyze(A);
    ldlt.factorize(A);
    Eigen::MatrixX3d x;
    ldlt.solve(b, &x);
    EXPECT_LT((A * x - b).norm(), 1e-9 * b.norm());
    for (int k = 0; k < 3; ++k)
      EXPECT_LT((x.col(k) - expected.col(k)).norm(), 1e-9 * expected.col(k).norm())
          << "column " << k;
  }
}

// An indefinite matrix through the LDL^T sweeps (negative D entries).
TEST(SparseCholesky, LdltSolvesAnIndefiniteMatrix) {
  const Eigen::SparseMatrix<double> A = shifted_laplacian(-0.37);
  const Eigen::MatrixX3d b = Eigen::MatrixX3d::Random(A.rows(), 3);
  SparseLdlt ldlt(SparseLdlt::Backend::kCholmod);
  ldlt.analyze(A);
  ldlt.factorize(A);
  EXPECT_GT(ldlt.negative_pivots(), 0);
  Eigen::MatrixX3d x;
  ldlt.solve(b, &x);
  EXPECT_LT((A * x - b).norm(), 1e-9 * b.norm());
}

TEST(SparseCholesky, RefusesAMatrixThatIsNotPositiveDefinite) {
  const Eigen::SparseMatrix<double> A = shifted_laplacian(-0.5);
  SparseLdlt llt(SparseLdlt::Backend::kCholmodCholesky);
  llt.analyze(A);
  EXPECT_THROW(llt.factorize(A), NumericalError);
}

// Each factor is turned simplicial for the solves and the next factorization
// starts again from the supernodal analysis: factorizations after a good one
// and after a refused one are each the solution of their own matrix.
TEST(SparseCholesky, FactorizesAgainAfterAGoodAndARefusedFactorization) {
  const Eigen::SparseMatrix<double> A = shifted_laplacian(1e-2), B = shifted_laplacian(2.0),
                                    bad = shifted_laplacian(-0.5);
  Eigen::MatrixX3d b = Eigen::MatrixX3d::Random(A.rows(), 3), x;
  SparseLdlt llt(SparseLdlt::Backend::kCholmodCholesky);
  llt.analyze(A);
  for (const Eigen::SparseMatrix<double>* M : {&A, &B, &bad, &A}) {
    if (M == &bad) {
      EXPECT_THROW(llt.factorize(*M), NumericalError);
      continue;
    }
    llt.factorize(*M);
    llt.solve(b, &x);
    EXPECT_LT((*M * x - b).norm(), 1e-9 * b.norm());
  }
}

}  // namespace
}  // namespace unfold
