// A locality order (mesh/locality_order.h): a permutation that keeps the held
// rows first and puts a grid's neighbours near each other in the order.
#include "mesh/locality_order.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <vector>

#include "core/errors.h"

namespace unfold {
namespace {

// A k^3 grid's points, shuffled, and each point's grid position.
struct ShuffledGrid {
  explicit ShuffledGrid(int k) : P(k * k * k, 3), at(size_t(k * k * k)) {
    std::vector<int> slot(size_t(k * k * k));
    std::iota(slot.begin(), slot.end(), 0);
    std::shuffle(slot.begin(), slot.end(), std::mt19937(7));
    for (int x = 0, c = 0; x < k; ++x)
      for (int y = 0; y < k; ++y)
        for (int z = 0; z < k; ++z, ++c) {
          P.row(slot[size_t(c)]) << x, y, z;
          at[size_t(c)] = slot[size_t(c)];
        }
  }
  Eigen::MatrixX3d P;
  std::vector<int> at;  // the row of grid point c (x-major)
};

// The median, over the grid's neighbours along x, of how far apart the two are
// in the order `position` (position[row] = index in the order).
double median_gap(const ShuffledGrid& g, int k, const std::vector<int>& position) {
  std::vector<int> gaps;
  for (int c = 0; c + k * k < k * k * k; ++c)
    gaps.push_back(
        std::abs(position[size_t(g.at[size_t(c)])] - position[size_t(g.at[size_t(c + k * k)])]));
  std::nth_element(gaps.begin(), gaps.begin() + gaps.size() / 2, gaps.end());
  return gaps[gaps.size() / 2];
}

TEST(LocalityOrder, IsAPermutationWithTheKeptRowsFirst) {
  const ShuffledGrid g(6);
  const std::vector<int> order = locality_order(g.P, 4);
  ASSERT_EQ(order.size(), size_t(216));
  for (int i = 0; i < 4; ++i) EXPECT_EQ(order[size_t(i)], i);
  std::vector<int> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  for (int i = 0; i < 216; ++i) EXPECT_EQ(sorted[size_t(i)], i);
}

TEST(LocalityOrder, PutsAShuffledGridsNeighboursNearEachOther) {
  const int k = 16;
  const ShuffledGrid g(k);
  std::vector<int> as_given(size_t(k * k * k)), ordered(size_t(k * k * k));
  std::iota(as_given.begin(), as_given.end(), 0);
  const std::vector<int> order = locality_order(g.P);
  for (size_t a = 0; a < order.size(); ++a) ordered[size_t(order[a])] = int(a);
  const double before = median_gap(g, k, as_given), after = median_gap(g, k, ordered);
  // Shuffled, neighbours are about a third of the rows apart; along a Z curve a
  // step in x is a few cells' worth of rows at most levels.
  EXPECT_GT(before, 500);
  EXPECT_LT(after, 0.05 * before) << before << " -> " << after;
}

TEST(LocalityOrder, KeepsCoincidentPointsInTheirOwnOrder) {
  const Eigen::MatrixX3d P = Eigen::MatrixX3d::Zero(5, 3);
  const std::vector<int> order = locality_order(P, 1);
  for (int i = 0; i < 5; ++i) EXPECT_EQ(order[size_t(i)], i);
}

TEST(LocalityOrder, RefusesAKeptCountOutsideTheRows) {
  const Eigen::MatrixX3d P = Eigen::MatrixX3d::Random(5, 3);
  EXPECT_THROW(locality_order(P, -1), UsageError);
  EXPECT_THROW(locality_order(P, 6), UsageError);
}

}  // namespace
}  // namespace unfold
