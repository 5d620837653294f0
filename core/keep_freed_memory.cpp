#include "core/keep_freed_memory.h"

#include <cstdlib>  // defines __GLIBC__ with glibc

#ifdef __GLIBC__
#include <malloc.h>
#endif

namespace unfold {

void keep_freed_memory() {
#ifdef __GLIBC__
  // Mapped blocks are fresh pages on every allocation, zeroed by the kernel:
  // a large scan's n x 3 buffers (4.5 MB at 186k vertices, 29 MB at 1.2M) and
  // sparse matrices would be faulted in again at every step. From the heap
  // they are reused (docs/performance.md, keeping freed memory).
  mallopt(M_MMAP_THRESHOLD, 256 << 20);
  mallopt(M_TRIM_THRESHOLD, 64 << 20);
  mallopt(M_TOP_PAD, 128 << 20);
#endif
}

}  // namespace unfold
