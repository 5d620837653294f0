#include "core/keep_freed_memory.h"

#include <cstdlib>  // defines __GLIBC__ with glibc

#ifdef __GLIBC__
#include <malloc.h>
#endif

namespace unfold {

void keep_freed_memory() {
#ifdef __GLIBC__
  // Mapped blocks are fresh pages on every allocation; 32 MB and 256 MB
  // thresholds raised david0's peak memory by a fifth, 4 MB left it as it was.
  mallopt(M_MMAP_THRESHOLD, 4 << 20);
  mallopt(M_TRIM_THRESHOLD, 64 << 20);
  mallopt(M_TOP_PAD, 128 << 20);
#endif
}

}  // namespace unfold
