// How the process's allocator hands memory back to the system: the apps and
// the benchmarks set it once at start, so that the stages do not pay page
// faults for memory the stage before them gave back.
#pragma once

namespace unfold {

/// With glibc: blocks up to 256 MB come from the heap (not fresh mappings),
/// the heap is trimmed only above 64 MB free at its top, and keeps 128 MB
/// whenever it grows or is trimmed. Without it each stage's n x 3 buffers,
/// sparse matrices and factors are faulted in again: david0's paper config
/// takes 140k page faults without it and 77k with it, 16 % less time (the
/// default 7 %); a 1.2M-vertex scan 7.6M faults against 3.4M with blocks up
/// to 4 MB only (docs/performance.md).
/// Process-wide; elsewhere a no-op.
void keep_freed_memory();

}  // namespace unfold
