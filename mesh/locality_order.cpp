#include "mesh/locality_order.h"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <utility>

#include "core/errors.h"

namespace unfold {
namespace {

// The low 21 bits of x spread out to every third bit.
uint64_t spread_bits(uint64_t x) {
  x &= 0x1fffff;
  x = (x | x << 32) & 0x1f00000000ffffULL;
  x = (x | x << 16) & 0x1f0000ff0000ffULL;
  x = (x | x << 8) & 0x100f00f00f00f00fULL;
  x = (x | x << 4) & 0x10c30c30c30c30c3ULL;
  x = (x | x << 2) & 0x1249249249249249ULL;
  return x;
}

}  // namespace

std::vector<int> locality_order(const Eigen::MatrixX3d& P, int num_kept) {
  const int n = int(P.rows());
  if (num_kept < 0 || num_kept > n)
    throw UsageError("locality_order: num_kept must be in [0, " + std::to_string(n) + "], got " +
                     std::to_string(num_kept));
  std::vector<int> order(static_cast<size_t>(n));
  std::iota(order.begin(), order.end(), 0);
  if (n - num_kept < 2) return order;
  const Eigen::RowVector3d low = P.colwise().minCoeff();
  const double extent = (P.colwise().maxCoeff() - low).maxCoeff();
  const double scale = extent > 0 ? double((1 << 21) - 1) / extent : 0.0;
  std::vector<std::pair<uint64_t, int>> keyed(size_t(n - num_kept));
  for (int i = num_kept; i < n; ++i) {
    uint64_t code = 0;
    for (int k = 0; k < 3; ++k) code |= spread_bits(uint64_t((P(i, k) - low(k)) * scale)) << k;
    keyed[size_t(i - num_kept)] = {code, i};
  }
  std::sort(keyed.begin(), keyed.end());
  for (size_t a = 0; a < keyed.size(); ++a) order[size_t(num_kept) + a] = keyed[a].second;
  return order;
}

}  // namespace unfold
