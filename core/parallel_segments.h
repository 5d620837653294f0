// Sweeps over long vectors (n x 3 positions seen as one vector) split into
// fixed segments that run on all threads. Every entry, and every segment's
// partial sum, is computed as on one thread, and the partial sums are added
// in segment order, so the results do not depend on the thread count.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <vector>

#include "core/parallel.h"

namespace unfold {

/// Entries per segment.
constexpr Eigen::Index kSegment = 4096;
/// Vectors shorter than this are swept on one thread (kMinParallelRows rows of 3).
constexpr Eigen::Index kMinParallelEntries = 3 * Eigen::Index(kMinParallelRows);

/// Calls sweep(begin, size) once per segment of [0, n).
template <typename Sweep>
void for_segments(Eigen::Index n, const Sweep& sweep) {
  const Eigen::Index segments = (n + kSegment - 1) / kSegment;
#pragma omp parallel for schedule(static) if (n >= kMinParallelEntries)
  for (Eigen::Index k = 0; k < segments; ++k)
    sweep(k * kSegment, std::min(kSegment, n - k * kSegment));
}

/// The sum over the segments of [0, n) of partial(begin, size), in segment order.
template <typename Partial>
double sum_segments(Eigen::Index n, const Partial& partial) {
  const Eigen::Index segments = (n + kSegment - 1) / kSegment;
  std::vector<double> parts(static_cast<size_t>(segments));
#pragma omp parallel for schedule(static) if (n >= kMinParallelEntries)
  for (Eigen::Index k = 0; k < segments; ++k)
    parts[static_cast<size_t>(k)] = partial(k * kSegment, std::min(kSegment, n - k * kSegment));
  double sum = 0;
  for (const double p : parts) sum += p;
  return sum;
}

}  // namespace unfold
