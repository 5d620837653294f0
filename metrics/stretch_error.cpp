#include "metrics/stretch_error.h"

#include <cmath>
#include <random>
#include <vector>

#include "core/errors.h"
#include "core/progress.h"

namespace unfold {

StretchError stretch_error(const Eigen::MatrixX3d& P, const Eigen::MatrixX3d& Q,
                           const StretchErrorOptions& options) {
  const int64_t n = P.rows();
  if (Q.rows() != n || n < 2)
    throw UsageError("stretch_error: need P and Q of equal size with at least 2 rows");
  if (options.exact_limit < 0 || options.sample_pairs < 2)
    throw UsageError("stretch_error: need exact_limit >= 0 and sample_pairs >= 2");
  report_stage("E_str of " + std::to_string(n) + " vertices");
  StretchError result;
  if (n <= options.exact_limit) {
    std::vector<double> row_sum(size_t(n), 0.0);
    std::vector<int64_t> row_skipped(size_t(n), 0);
    // Per row as Eigen arrays: (d' - d) / d = sqrt(d'^2 / d^2) - 1 takes one
    // vectorized square root and division per pair.
#pragma omp parallel for schedule(dynamic, 16)
    for (int64_t i = 0; i < n - 1; ++i) {
      const Eigen::Index m = n - 1 - i;
      const auto rest = [&](const Eigen::MatrixX3d& X, int c) {
        return (X.col(c).segment(i + 1, m).array() - X(i, c)).square();
      };
      const Eigen::ArrayXd d2 = rest(P, 0) + rest(P, 1) + rest(P, 2);
      const auto ratio = ((rest(Q, 0) + rest(Q, 1) + rest(Q, 2)) / d2).sqrt();
      const int64_t zeros = (d2 == 0).count();
      row_skipped[size_t(i)] = zeros;
      row_sum[size_t(i)] =
          zeros == 0 ? ratio.sum() - double(m) : (d2 > 0).select(ratio - 1.0, 0.0).sum();
    }
    double sum = 0;
    for (int64_t i = 0; i < n; ++i) {
      sum += row_sum[size_t(i)];
      result.pairs_skipped += row_skipped[size_t(i)];
    }
    result.exact = true;
    result.pairs_used = n * (n - 1) / 2 - result.pairs_skipped;
    if (result.pairs_used == 0) throw InputError("stretch_error: all rest points coincide");
    result.value = sum / double(result.pairs_used);
    return result;
  }
  // Drawing is serial (cheap next to the distances) so the pairs, and hence
  // the estimate, are fixed by the seed alone.
  std::mt19937_64 rng(options.seed);
  std::uniform_int_distribution<int64_t> first(0, n - 1), second(0, n - 2);
  double mean = 0, m2 = 0;  // Welford's running mean and sum of squared deviations
  for (int64_t s = 0; s < options.sample_pairs; ++s) {
    const int64_t i = first(rng);
    int64_t j = second(rng);
    if (j >= i) ++j;  // uniform over j != i
    const double d = (P.row(i) - P.row(j)).norm();
    if (d == 0) {
      ++result.pairs_skipped;
      continue;
    }
    const double x = ((Q.row(i) - Q.row(j)).norm() - d) / d;
    ++result.pairs_used;
    const double delta = x - mean;
    mean += delta / double(result.pairs_used);
    m2 += delta * (x - mean);
  }
  if (result.pairs_used < 2) throw InputError("stretch_error: (almost) all rest points coincide");
  result.value = mean;
  result.standard_error = std::sqrt(m2 / double(result.pairs_used - 1) / double(result.pairs_used));
  return result;
}

}  // namespace unfold
