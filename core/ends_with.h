// Whether a string ends with a suffix (std::string::ends_with is C++20).
#pragma once

#include <string>

namespace unfold {

inline bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace unfold
