#include "mesh/boundary_chain.h"

#include <algorithm>
#include <cstdint>
#include <utility>

namespace unfold {

std::vector<ChainEdge> boundary_chain(const Eigen::MatrixX3i& F) {
  // Each directed edge as its undirected key, +1 from the lower index and -1
  // from the higher.
  std::vector<std::pair<uint64_t, int>> uses;
  uses.reserve(size_t(3 * F.rows()));
  for (Eigen::Index t = 0; t < F.rows(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = F(t, k), b = F(t, (k + 1) % 3);
      if (a == b) continue;  // a degenerate corner's edges cancel within its triangle
      const auto lo = uint32_t(std::min(a, b)), hi = uint32_t(std::max(a, b));
      uses.emplace_back((uint64_t(lo) << 32) | hi, a < b ? 1 : -1);
    }
  std::sort(uses.begin(), uses.end());
  std::vector<ChainEdge> chain;
  for (size_t k = 0; k < uses.size();) {
    const uint64_t key = uses[k].first;
    int sum = 0;
    for (; k < uses.size() && uses[k].first == key; ++k) sum += uses[k].second;
    const int lo = int(key >> 32), hi = int(key & 0xffffffffu);
    if (sum > 0) chain.push_back({lo, hi, sum});
    if (sum < 0) chain.push_back({hi, lo, -sum});
  }
  return chain;
}

}  // namespace unfold
