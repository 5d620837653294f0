// The solves of a simplicial factor by disjoint subtrees of its elimination
// tree: A x = b solved (L L^T and L D L^T, with a permutation) whatever the
// number of groups and threads, the same bits on any threads, a forest split
// with nothing serial, and a factor that does not start its columns with the
// diagonal refused.
#include "solvers/subtree_parallel_solve.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <numeric>
#include <random>
#include <utility>
#include <vector>

#include "core/errors.h"
#include "mesh/edge_graph.h"
#include "test_meshes.h"

namespace unfold {
namespace {

// A positive definite matrix: a tet grid's Laplacian plus a small shift.
Eigen::SparseMatrix<double> shifted_laplacian(int nx, int ny, int nz) {
  const TetMesh mesh = test::grid_tet_mesh(nx, ny, nz, 0.5);
  Eigen::SparseMatrix<double> A = graph_laplacian(build_edge_graph(int(mesh.V.rows()), mesh.T));
  for (int i = 0; i < A.rows(); ++i) A.coeffRef(i, i) += 1e-3;
  return A;
}

// A's Cholesky factor in the order `order` gives (row k of P A P^T is row
// order[k] of A), in compressed columns, diagonal first (Eigen's simplicial
// layout); as L D L^T (unit L, D on the diagonal) if asked.
struct TestFactor {
  Eigen::SparseMatrix<double> L;
  std::vector<int> order;

  SubtreeParallelSolve::Factor factor(bool cholesky) {
    if (!cholesky) {  // L D L^T = (L S^-1) S^2 (L S^-1)^T, S = diag(L)
      for (int j = 0; j < L.cols(); ++j) {
        const double s = L.valuePtr()[L.outerIndexPtr()[j]];
        for (int p = L.outerIndexPtr()[j]; p < L.outerIndexPtr()[j + 1]; ++p) L.valuePtr()[p] /= s;
        L.valuePtr()[L.outerIndexPtr()[j]] = s * s;
      }
    }
    SubtreeParallelSolve::Factor f;
    f.n = int(L.cols());
    f.column_start = L.outerIndexPtr();
    f.row = L.innerIndexPtr();
    f.value = L.valuePtr();
    f.permutation = order.data();
    f.cholesky = cholesky;
    return f;
  }
};

TestFactor factor_of(const Eigen::SparseMatrix<double>& A, std::vector<int> order) {
  const int n = int(A.rows());
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> P(n);
  for (int k = 0; k < n; ++k) P.indices()[order[size_t(k)]] = k;  // row order[k] goes to k
  const Eigen::SparseMatrix<double> B = (P * A * P.transpose()).eval();
  Eigen::SimplicialLLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::NaturalOrdering<int>> llt(
      B);
  EXPECT_EQ(llt.info(), Eigen::Success);
  TestFactor t{llt.matrixL(), std::move(order)};
  t.L.makeCompressed();
  return t;
}

// A fill-reducing order (AMD, as Eigen's Cholesky picks it).
std::vector<int> fill_reducing_order(const Eigen::SparseMatrix<double>& A) {
  const Eigen::SimplicialLLT<Eigen::SparseMatrix<double>> llt(A);
  const auto& P = llt.permutationP().indices();  // row i of A goes to row P[i]
  std::vector<int> order(size_t(A.rows()));
  for (int i = 0; i < A.rows(); ++i) order[size_t(P[i])] = i;
  return order;
}

TEST(SubtreeParallelSolve, SolvesWhateverTheGroupsAndThreads) {
  const Eigen::SparseMatrix<double> A = shifted_laplacian(10, 6, 5);
  const int n = int(A.rows());
  // A random order makes a chain of the tree (nothing to split), AMD a bushy one.
  std::vector<int> shuffled(static_cast<size_t>(n));
  std::iota(shuffled.begin(), shuffled.end(), 0);
  std::mt19937 random(3);
  std::shuffle(shuffled.begin(), shuffled.end(), random);
  std::normal_distribution<double> normal;
  Eigen::MatrixX3d b(n, 3);
  for (Eigen::Index i = 0; i < b.size(); ++i) b.data()[i] = normal(random);
  const int threads = omp_get_max_threads();
  for (const bool amd : {true, false}) {
    for (const bool cholesky : {true, false}) {
      TestFactor t = factor_of(A, amd ? fill_reducing_order(A) : shuffled);
      const SubtreeParallelSolve::Factor f = t.factor(cholesky);
      Eigen::MatrixX3d first;
      for (const int groups : {1, 2, 3, 5}) {
        const SubtreeParallelSolve solver(f, groups);
        if (groups == 1) {
          EXPECT_EQ(solver.serial_share(), 1);
        } else if (amd) {
          EXPECT_LT(solver.serial_share(), 0.5) << groups << " groups";
        }
        Eigen::MatrixX3d on_one;
        for (const int run_on : {1, 2}) {
          omp_set_num_threads(run_on);
          Eigen::MatrixX3d x;
          solver.solve(b, &x);
          omp_set_num_threads(threads);
          EXPECT_LT((A * x - b).norm(), 1e-9 * b.norm())
              << (amd ? "AMD, " : "random order, ") << (cholesky ? "LL^T, " : "LDL^T, ") << groups
              << " groups on " << run_on << " threads";
          if (first.size() == 0) first = x;
          EXPECT_LT((x - first).norm(), 1e-12 * first.norm()) << groups << " groups";
          // The sums run in an order the groups fix: the same bits on any threads.
          if (on_one.size() == 0) on_one = x;
          EXPECT_EQ((x - on_one).cwiseAbs().maxCoeff(), 0) << groups << " groups";
        }
      }
    }
  }
}

// Two blocks with no entry between them: two trees, one a group, nothing serial.
TEST(SubtreeParallelSolve, SplitsAForestWithNothingSerial) {
  const Eigen::SparseMatrix<double> block = shifted_laplacian(4, 3, 3);
  const int m = int(block.rows());
  std::vector<Eigen::Triplet<double>> entries;
  for (int j = 0; j < m; ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(block, j); it; ++it) {
      entries.emplace_back(int(it.row()), j, it.value());
      entries.emplace_back(int(it.row()) + m, j + m, it.value());
    }
  Eigen::SparseMatrix<double> A(2 * m, 2 * m);
  A.setFromTriplets(entries.begin(), entries.end());
  std::vector<int> identity(static_cast<size_t>(2 * m));
  std::iota(identity.begin(), identity.end(), 0);
  TestFactor t = factor_of(A, identity);
  const SubtreeParallelSolve solver(t.factor(true), 2);
  EXPECT_EQ(solver.serial_share(), 0);
  const Eigen::MatrixX3d b = Eigen::MatrixX3d::Random(2 * m, 3);
  Eigen::MatrixX3d x;
  solver.solve(b, &x);
  EXPECT_LT((A * x - b).norm(), 1e-9 * b.norm());
}

TEST(SubtreeParallelSolve, RefusesAColumnNotStartingWithItsDiagonal) {
  // Column 0 holds rows 1 and 0, in that order.
  const int start[] = {0, 2, 3}, row[] = {1, 0, 1}, order[] = {0, 1};
  const double value[] = {0.5, 2, 1};
  SubtreeParallelSolve::Factor f;
  f.n = 2;
  f.column_start = start;
  f.row = row;
  f.value = value;
  f.permutation = order;
  EXPECT_THROW(SubtreeParallelSolve(f, 2), UsageError);
}

}  // namespace
}  // namespace unfold
