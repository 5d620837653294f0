// When a loop over vertices is worth an OpenMP parallel region.
#pragma once

namespace unfold {

/// Loops over fewer rows than this run on one thread: opening a parallel
/// region costs more than they do, and far more when other processes share
/// the cores (a thread waiting at the region's end burns its time slice).
/// Use as `#pragma omp parallel for if (n >= kMinParallelRows)`.
constexpr int kMinParallelRows = 4096;

}  // namespace unfold
