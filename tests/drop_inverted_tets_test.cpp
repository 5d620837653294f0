// Tets inverted (or, with a quality bound, flat) at their rest positions are
// dropped, but never those the mesh needs to stay connected.
#include "mesh/drop_inverted_tets.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "core/errors.h"
#include "core/union_find.h"
#include "mesh/tet_quality.h"
#include "mesh/tet_volumes.h"
#include "test_meshes.h"

namespace unfold {
namespace {

// Parts of the vertices used by T, as a root per vertex (-1: in no tet).
std::vector<int> parts(int n, const Eigen::MatrixX4i& T) {
  UnionFind sets(n);
  std::vector<char> used(size_t(n), 0);
  for (Eigen::Index t = 0; t < T.rows(); ++t)
    for (int k = 0; k < 4; ++k) {
      sets.unite(T(t, 0), T(t, k));
      used[size_t(T(t, k))] = 1;
    }
  std::vector<int> root(static_cast<size_t>(n));
  for (int v = 0; v < n; ++v) root[size_t(v)] = used[size_t(v)] ? sets.find(v) : -1;
  return root;
}

// The same partition of the vertices (roots may differ).
bool same_parts(const std::vector<int>& a, const std::vector<int>& b) {
  for (size_t i = 0; i < a.size(); ++i)
    for (size_t j = i + 1; j < a.size(); ++j)
      if ((a[i] < 0) != (b[i] < 0) || (a[i] >= 0 && (a[i] == a[j]) != (b[i] == b[j]))) return false;
  return true;
}

TEST(DropInvertedTets, KeepsEveryTetWhereNoneIsInverted) {
  const TetMesh grid = test::grid_tet_mesh(3, 3, 3);
  Eigen::MatrixX4i T = grid.T;
  const Eigen::MatrixX3d moved = 2.0 * grid.V * test::random_rotation(3).transpose();
  EXPECT_EQ(drop_inverted_tets(grid.V, moved, &T).dropped(), 0);
  EXPECT_EQ(T, grid.T);
}

// Mirrored, every tet is inverted: what is left is exactly what joins the
// vertices, the first of two copies of a tet and the one that holds vertex 4.
TEST(DropInvertedTets, KeepsInvertedTetsTheMeshNeedsConnected) {
  Eigen::MatrixX3d P(5, 3);
  P << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1;
  Eigen::MatrixX4i T(3, 4);
  T << 0, 1, 2, 3, 0, 1, 2, 3, 1, 2, 3, 4;
  Eigen::MatrixX3d mirrored = P;
  mirrored.col(0) *= -1;
  const DroppedTets dropped = drop_inverted_tets(P, mirrored, &T);
  EXPECT_EQ(dropped.inverted, 1);
  EXPECT_EQ(dropped.flat, 0);
  EXPECT_EQ(dropped.kept_inverted, 2);
  Eigen::MatrixX4i expected(2, 4);
  expected << 0, 1, 2, 3, 1, 2, 3, 4;
  EXPECT_EQ(T, expected);
}

// A tet mesh with its vertices shaken until about a tenth of its tets turn
// over: every tet left over is upright or needed for the parts, every tet
// dropped was inverted, and the vertices are joined as before.
TEST(DropInvertedTets, DropsOnlyInvertedTetsAndKeepsTheParts) {
  const TetMesh grid = test::grid_tet_mesh(6, 5, 4);
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 0.3);
  Eigen::MatrixX3d shaken = grid.V;
  for (Eigen::Index i = 0; i < shaken.size(); ++i) shaken(i) += noise(rng);
  const int inverted = count_inverted_tets(grid.V, shaken, grid.T);
  ASSERT_GT(inverted, grid.T.rows() / 20);
  Eigen::MatrixX4i T = grid.T;
  const DroppedTets counts = drop_inverted_tets(grid.V, shaken, &T);
  const int dropped = counts.dropped();
  EXPECT_EQ(counts.flat, 0);
  EXPECT_EQ(T.rows() + dropped, grid.T.rows());
  EXPECT_GT(dropped, 0);
  EXPECT_EQ(count_inverted_tets(grid.V, shaken, T), inverted - dropped);
  EXPECT_EQ(counts.kept_inverted, inverted - dropped);
  const int n = int(grid.V.rows());
  EXPECT_TRUE(same_parts(parts(n, T), parts(n, grid.T)));
  // Each inverted tet left over is needed: without it the parts change.
  const Eigen::VectorXd before = tet_volumes(grid.V, T), after = tet_volumes(shaken, T);
  for (Eigen::Index t = 0; t < T.rows(); ++t) {
    if (before[t] * after[t] > 0) continue;
    Eigen::MatrixX4i without(T.rows() - 1, 4);
    without << T.topRows(t), T.bottomRows(T.rows() - t - 1);
    EXPECT_FALSE(same_parts(parts(n, without), parts(n, T))) << "inverted tet " << t;
  }
}

// A grid's middle layer pressed almost onto the one below: the tets between
// them are upright but flat. With a quality bound they are dropped but for
// a few the parts need, and no tet of good shape is; without one, none is
// dropped.
TEST(DropInvertedTets, DropsFlatTetsWithAQualityBound) {
  const TetMesh grid = test::grid_tet_mesh(4, 4, 2);
  Eigen::MatrixX3d pressed = grid.V;
  const double low = grid.V.col(2).minCoeff(), high = grid.V.col(2).maxCoeff();
  const double middle = (low + high) / 2;
  for (Eigen::Index i = 0; i < pressed.rows(); ++i)
    if (std::abs(grid.V(i, 2) - middle) < 1e-9) pressed(i, 2) = low + 0.01 * (middle - low);
  Eigen::MatrixX4i T = grid.T;
  EXPECT_EQ(drop_inverted_tets(grid.V, pressed, &T, nullptr, 0.0).dropped(), 0);
  const double bound = 0.1;
  const Eigen::VectorXd q = tet_quality(pressed, grid.T);
  int flat = 0;
  for (Eigen::Index t = 0; t < q.size(); ++t) flat += q[t] < bound;
  ASSERT_GT(flat, 0);
  ASSERT_LT(flat, grid.T.rows());
  T = grid.T;
  const DroppedTets counts = drop_inverted_tets(grid.V, pressed, &T, nullptr, bound);
  EXPECT_EQ(counts.inverted, 0);
  const int dropped = counts.flat;
  EXPECT_GT(dropped, 0);
  EXPECT_LE(dropped, flat);
  EXPECT_EQ(T.rows() + dropped, grid.T.rows());
  const int n = int(grid.V.rows());
  EXPECT_TRUE(same_parts(parts(n, T), parts(n, grid.T)));
  // Each flat tet put back joins a vertex that no tet of good shape has, so
  // there are at most as many as such vertices (the bottom layer's).
  std::vector<char> in_good(size_t(n), 0);
  for (Eigen::Index t = 0; t < q.size(); ++t)
    if (q[t] >= bound)
      for (int k = 0; k < 4; ++k) in_good[size_t(grid.T(t, k))] = 1;
  const int loose = int(std::count(in_good.begin(), in_good.end(), 0));
  const Eigen::VectorXd left = tet_quality(pressed, T);
  const int kept_flat = int((left.array() < bound).count());
  EXPECT_GT(loose, 0);
  EXPECT_LE(kept_flat, loose);
  EXPECT_EQ(kept_flat + dropped, flat);
}

TEST(DropInvertedTets, RefusesMismatchedPositionsAndCorners) {
  const TetMesh grid = test::grid_tet_mesh(2, 2, 2);
  Eigen::MatrixX4i T = grid.T;
  EXPECT_THROW(drop_inverted_tets(grid.V, grid.V.topRows(3), &T), UsageError);
  T(0, 0) = int(grid.V.rows());
  EXPECT_THROW(drop_inverted_tets(grid.V, grid.V, &T), UsageError);
  T = grid.T;
  EXPECT_THROW(drop_inverted_tets(grid.V, grid.V, &T, nullptr, -0.1), UsageError);
  EXPECT_THROW(drop_inverted_tets(grid.V, grid.V, &T, nullptr, 1.5), UsageError);
}

}  // namespace
}  // namespace unfold
