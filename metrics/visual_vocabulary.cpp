#include "metrics/visual_vocabulary.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <random>

#include "core/errors.h"

namespace unfold {
namespace {

// A uniform number in [0, 1) from the generator's bits (std::uniform_real_distribution
// differs between standard libraries; this does not).
double uniform(std::mt19937_64& random) { return double(random() >> 11) * 0x1.0p-53; }

// Squared distances of every feature (row) to every word (column).
Eigen::MatrixXf squared_distances(const Eigen::MatrixXf& vocabulary,
                                  const Eigen::MatrixXf& features) {
  Eigen::MatrixXf d = -2 * features * vocabulary.transpose();
  d.colwise() += features.rowwise().squaredNorm();
  d.rowwise() += vocabulary.rowwise().squaredNorm().transpose();
  return d;
}

}  // namespace

Eigen::MatrixXf learn_vocabulary(const Eigen::MatrixXf& features, int words, int iterations,
                                 std::uint64_t seed) {
  if (features.rows() == 0) throw UsageError("visual vocabulary: no features to learn from");
  if (words < 1 || iterations < 0)
    throw UsageError("visual vocabulary: words must be >= 1 and iterations >= 0");
  const Eigen::Index n = features.rows(), k = std::min<Eigen::Index>(words, n);
  std::mt19937_64 random(seed);
  // k-means++: each next centre drawn with probability proportional to the
  // squared distance to the nearest centre so far.
  Eigen::MatrixXf centres(k, features.cols());
  Eigen::VectorXd nearest = Eigen::VectorXd::Constant(n, INFINITY);
  Eigen::Index pick = Eigen::Index(random() % std::uint64_t(n));
  for (Eigen::Index c = 0;;) {
    centres.row(c) = features.row(pick);
    double total = 0;
    for (Eigen::Index i = 0; i < n; ++i)  // row by row: no n x d temporary
      total += nearest[i] =
          std::min(nearest[i], double((features.row(i) - centres.row(c)).squaredNorm()));
    if (++c == k) break;
    const double target = uniform(random) * total;
    pick = 0;
    for (double sum = 0; pick + 1 < n; ++pick)
      if ((sum += nearest[pick]) > target) break;
  }
  for (int it = 0; it < iterations; ++it) {
    const Eigen::VectorXi assigned = nearest_words(centres, features);
    Eigen::MatrixXd sums = Eigen::MatrixXd::Zero(k, features.cols());
    Eigen::VectorXi counts = Eigen::VectorXi::Zero(k);
    for (Eigen::Index i = 0; i < n; ++i)
      sums.row(assigned[i]) += features.row(i).cast<double>(), ++counts[assigned[i]];
    for (Eigen::Index c = 0; c < k; ++c)
      if (counts[c] > 0) centres.row(c) = (sums.row(c) / counts[c]).cast<float>();
  }
  return centres;
}

Eigen::VectorXi nearest_words(const Eigen::MatrixXf& vocabulary, const Eigen::MatrixXf& features) {
  Eigen::VectorXi words(features.rows());
  const Eigen::Index chunk = 1024;  // bounds the distance matrix's memory
  for (Eigen::Index start = 0; start < features.rows(); start += chunk) {
    const Eigen::Index rows = std::min(chunk, features.rows() - start);
    const Eigen::MatrixXf d = squared_distances(vocabulary, features.middleRows(start, rows));
    for (Eigen::Index i = 0; i < rows; ++i) d.row(i).minCoeff(&words[start + i]);
  }
  return words;
}

WordHistogram word_histogram(const Eigen::MatrixXf& vocabulary, const Eigen::MatrixXf& features) {
  std::map<int, int> counts;
  const Eigen::VectorXi words = nearest_words(vocabulary, features);
  for (Eigen::Index i = 0; i < words.size(); ++i) ++counts[words[i]];
  return WordHistogram(counts.begin(), counts.end());
}

}  // namespace unfold
