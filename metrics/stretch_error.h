// E_str (paper Eq. 9): mean relative change of all pairwise distances.
#pragma once

#include <Eigen/Core>
#include <cstdint>

namespace unfold {

struct StretchErrorOptions {
  int exact_limit = 20000;         ///< exact over all pairs when n <= this, else sampled
  int64_t sample_pairs = 2000000;  ///< pairs drawn by the sampled estimate
  uint64_t seed = 1;               ///< seed of the sampled estimate (fixed: reproducible)
};

struct StretchError {
  double value = 0;           ///< E_str (or its estimate)
  bool exact = false;         ///< true: all pairs were summed
  int64_t pairs_used = 0;     ///< pairs in the mean
  int64_t pairs_skipped = 0;  ///< pairs with d_ij == 0 (coincident rest points), left out
  double standard_error = 0;  ///< of the estimate; 0 when exact
};

/// E_str = 2/(n(n-1)) sum_{i<j} (d'_ij - d_ij) / d_ij, d = |p_i - p_j|, d' = |q_i - q_j|,
/// averaged over the pairs with d_ij > 0. Exact when n <= exact_limit (parallel
/// over rows; per-row partial sums added in row order, so the result does not
/// depend on the thread count). Otherwise the mean over `sample_pairs` pairs
/// drawn uniformly (with replacement) from a fixed-seed generator, with its
/// standard error. Equals s - 1 for a uniform scale by s, 0 for a rigid motion.
/// @param P rest positions (n x 3), n >= 2
/// @param Q deformed positions (n x 3)
/// @throws UsageError on mismatched sizes, n < 2, exact_limit < 0 or sample_pairs < 2
/// @throws InputError if every pair used has d_ij == 0
StretchError stretch_error(const Eigen::MatrixX3d& P, const Eigen::MatrixX3d& Q,
                           const StretchErrorOptions& options = {});

}  // namespace unfold
