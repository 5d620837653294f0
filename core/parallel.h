// When a loop over vertices is worth an OpenMP parallel region.
#pragma once

namespace unfold {

/// Loops over fewer rows than this run on one thread: opening a parallel
/// region costs more than they do, and far more when other processes share
/// the cores (a thread waiting at the region's end burns its time slice).
/// Use as `#pragma omp parallel for if (n >= kMinParallelRows)`.
/// 8192: on an idle machine wolf0's cascade (5.5k rows) takes the same time on
/// one thread as on two (docs/history/performance.md); on a shared one, two threads
/// made it 7x slower (0.78 s against 5.8 s, issue 15). Results do not depend
/// on the thread count.
constexpr int kMinParallelRows = 8192;

}  // namespace unfold
