// The nearest-rank percentile of a sample: the value a stated share of the
// sample is at or below, one of the sample's own values (no interpolation).
#pragma once

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <vector>

namespace unfold {

/// The k-th smallest of `values`, k = ceil(per_mille * m / 1000) in integers
/// (exact, no rounding of 0.999 * m), at least 1: the 99.9th percentile is
/// per_mille 999. Reorders `values` (nth_element); O(m).
/// @pre values is not empty, 0 <= per_mille <= 1000
inline double nearest_rank(std::vector<double>* values, std::size_t per_mille) {
  const std::size_t m = values->size();
  const std::size_t k = std::max<std::size_t>((per_mille * m + 999) / 1000, 1);
  std::nth_element(values->begin(), values->begin() + std::ptrdiff_t(k - 1), values->end());
  return (*values)[k - 1];
}

}  // namespace unfold
