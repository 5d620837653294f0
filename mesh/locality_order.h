// A vertex order that keeps neighbours near each other in memory: the sweeps
// over a cell's neighbours then read from cache rather than main memory once
// the vertices' data outgrow it (a refined scan's vertices come in the order
// its refinement made them, the neighbours of one cell far apart).
#pragma once

#include <Eigen/Core>
#include <vector>

namespace unfold {

/// The rows of P in Morton (Z-curve) order of their positions in P's bounding
/// cube, 21 bits an axis, ties by index; the first `num_kept` rows stay first,
/// in their own order.
/// @param P        positions (n x 3), finite
/// @param num_kept rows [0, num_kept) kept in place, 0 <= num_kept <= n
/// @return order, order[new] = old: a permutation of 0..n-1
/// @throws UsageError if num_kept is outside [0, n]
std::vector<int> locality_order(const Eigen::MatrixX3d& P, int num_kept = 0);

}  // namespace unfold
