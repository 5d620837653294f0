// Wall-clock seconds since a steady_clock time point: the stage timings.
#pragma once

#include <chrono>

namespace unfold {

inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace unfold
