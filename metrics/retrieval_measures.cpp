#include "metrics/retrieval_measures.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/errors.h"

namespace unfold {

RetrievalMeasures retrieval_measures(const Eigen::MatrixXd& D,
                                     const std::vector<std::string>& classes) {
  const Eigen::Index n = D.rows();
  if (D.cols() != n || Eigen::Index(classes.size()) != n)
    throw UsageError("retrieval_measures: need a square matrix with a class per shape");
  if (D.hasNaN()) throw UsageError("retrieval_measures: the matrix has a NaN");
  RetrievalMeasures m;
  m.precision.assign(kRecallLevels, 0.0);
  for (Eigen::Index q = 0; q < n; ++q) {
    std::vector<Eigen::Index> ranked;
    for (Eigen::Index j = 0; j < n; ++j)
      if (j != q) ranked.push_back(j);
    std::stable_sort(ranked.begin(), ranked.end(),
                     [&](Eigen::Index a, Eigen::Index b) { return D(q, a) < D(q, b); });
    std::vector<int> relevant(ranked.size());
    for (size_t k = 0; k < ranked.size(); ++k)
      relevant[k] = classes[size_t(ranked[k])] == classes[size_t(q)];
    const int R = std::accumulate(relevant.begin(), relevant.end(), 0);
    if (R == 0) continue;
    ++m.queries;
    auto found_in_first = [&](size_t count) {
      return std::accumulate(relevant.begin(), relevant.begin() + std::min(count, relevant.size()),
                             0);
    };
    m.nn += relevant[0];
    m.first_tier += double(found_in_first(size_t(R))) / R;
    m.second_tier += double(found_in_first(size_t(2 * R))) / R;
    const double found32 = found_in_first(32);
    if (found32 > 0) {
      const double p = found32 / 32, r = found32 / R;
      m.e_measure += 2 * p * r / (p + r);
    }
    // Rank k (1-based) is discounted by log2(k), the first not at all.
    auto discount = [](size_t k) { return k == 1 ? 1.0 : 1.0 / std::log2(double(k)); };
    double dcg = 0, ideal = 0;
    for (size_t k = 1; k <= relevant.size(); ++k) {
      dcg += relevant[k - 1] * discount(k);
      if (k <= size_t(R)) ideal += discount(k);
    }
    m.dcg += dcg / ideal;
    // Interpolated precision: the best precision at a rank reaching each recall level.
    int found = 0;
    std::vector<double> best(kRecallLevels, 0.0);
    for (size_t k = 1; k <= relevant.size(); ++k) {
      found += relevant[k - 1];
      const double precision = double(found) / double(k), recall = double(found) / R;
      for (int l = 0; l < kRecallLevels; ++l)
        if (recall >= double(l + 1) / kRecallLevels - 1e-12)
          best[size_t(l)] = std::max(best[size_t(l)], precision);
    }
    for (int l = 0; l < kRecallLevels; ++l) m.precision[size_t(l)] += best[size_t(l)];
  }
  if (m.queries == 0) throw UsageError("retrieval_measures: no class has two shapes");
  const double q = m.queries;
  m.nn /= q, m.first_tier /= q, m.second_tier /= q, m.e_measure /= q, m.dcg /= q;
  for (double& p : m.precision) p /= q;
  return m;
}

}  // namespace unfold
