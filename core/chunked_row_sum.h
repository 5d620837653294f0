// A sum over the rows of a mesh's vertices (or edges) taken in parallel, the
// same to the last bit on any number of threads.
#pragma once

#include <algorithm>
#include <type_traits>

#include "core/parallel.h"

namespace unfold {

/// Sum over rows i of row_sum(i) (a fixed-size Eigen array), in parallel. The rows
/// are cut into 64 chunks fixed by n alone and the partial sums added in chunk
/// order, so the result does not depend on the number of threads. row_sum may
/// also update row i of other blocks (each row is visited once): that is how
/// the solvers fuse an update with the reduction that follows it.
template <typename RowSum, typename Sum = std::invoke_result_t<RowSum, int>>
Sum chunked_row_sum(int n, const RowSum& row_sum) {
  constexpr int kChunks = 64;
  Sum partial[kChunks];
  const int size = (n + kChunks - 1) / kChunks;
#pragma omp parallel for schedule(static) if (n >= kMinParallelRows)
  for (int c = 0; c < kChunks; ++c) {
    Sum s = Sum::Zero();
    for (int i = c * size; i < std::min(n, (c + 1) * size); ++i) s += row_sum(i);
    partial[c] = s;
  }
  Sum total = Sum::Zero();
  for (const auto& s : partial) total += s;
  return total;
}

}  // namespace unfold
