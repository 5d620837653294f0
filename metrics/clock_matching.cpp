#include "metrics/clock_matching.h"

#include <algorithm>
#include <limits>

#include "core/errors.h"

namespace unfold {

double histogram_distance(const WordHistogram& a, const WordHistogram& b) {
  long long total_a = 0, total_b = 0, common = 0;
  for (const auto& [word, count] : a) total_a += count;
  for (const auto& [word, count] : b) total_b += count;
  if (total_a == 0 && total_b == 0) return 0;
  for (size_t i = 0, j = 0; i < a.size() && j < b.size();) {
    if (a[i].first < b[j].first) {
      ++i;
    } else if (b[j].first < a[i].first) {
      ++j;
    } else {
      common += std::min(a[i].second, b[j].second);
      ++i, ++j;
    }
  }
  return 1 - double(common) / double(std::max(total_a, total_b));
}

double clock_matching_dissimilarity(const std::vector<WordHistogram>& a,
                                    const std::vector<WordHistogram>& b,
                                    const std::vector<std::vector<int>>& rotations) {
  if (a.size() != b.size() || rotations.empty())
    throw UsageError("clock matching: the shapes need equally many views and a rotation");
  for (const std::vector<int>& p : rotations)
    if (p.size() != a.size() ||
        std::any_of(p.begin(), p.end(), [&](int v) { return v < 0 || size_t(v) >= b.size(); }))
      throw UsageError("clock matching: a rotation does not fit the views");
  double best = std::numeric_limits<double>::infinity();
  for (const std::vector<int>& p : rotations) {
    double sum = 0;  // a rotation stops once it cannot beat the best
    for (size_t v = 0; v < a.size() && sum < best; ++v)
      sum += histogram_distance(a[v], b[size_t(p[v])]);
    best = std::min(best, sum);
  }
  return best;
}

}  // namespace unfold
