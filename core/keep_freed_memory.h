// How the process's allocator hands memory back to the system: the apps and
// the benchmarks set it once at start, so that the stages do not pay page
// faults for memory the stage before them gave back.
#pragma once

namespace unfold {

/// With glibc: blocks up to 4 MB come from the heap (not fresh mappings), the
/// heap is trimmed only above 64 MB free at its top, and keeps 128 MB whenever
/// it grows or is trimmed. Without it each stage's n x 3 buffers, sparse
/// matrices and factors are faulted in again: david0's paper config takes
/// 144k page faults and 5.3 s, with it 67-80k and 4.3-4.5 s (the default
/// 7.7 -> 7.0 s), at a peak memory 15-25 % higher (docs/performance.md).
/// Process-wide; elsewhere a no-op.
void keep_freed_memory();

}  // namespace unfold
