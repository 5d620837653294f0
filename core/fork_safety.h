// Whether the process may fork (TetGen runs in a child, tetra/run_tetgen.h)
// while other threads of it run. glibc's malloc holds its locks across fork();
// the AddressSanitizer's allocator (GCC 12) does not, and a child forked while
// another thread allocates can wait on its lock forever. Under ASan the stages
// that would overlap a fork therefore run one after the other.
#pragma once

namespace unfold {

#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kForkAlongsideThreads = false;
#else
inline constexpr bool kForkAlongsideThreads = true;
#endif

}  // namespace unfold
