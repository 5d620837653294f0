#include "mesh/position_order.h"

#include <algorithm>
#include <numeric>

namespace unfold {

std::vector<int> position_order(const Eigen::MatrixX3d& V) {
  std::vector<int> order(size_t(V.rows()));
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    for (int k = 0; k < 3; ++k)
      if (V(a, k) != V(b, k)) return V(a, k) < V(b, k);
    return a < b;
  });
  return order;
}

}  // namespace unfold
