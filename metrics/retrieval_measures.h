// The standard retrieval measures of the shape benchmarks (Princeton Shape
// Benchmark, Shilane et al. 2004; the SHREC tracks, e.g. Pickup et al. 2016,
// 2018) over a dissimilarity matrix and a class per shape. Every shape is a
// query; the query itself is left out of its ranked list; the others are
// ranked by increasing dissimilarity (ties: lower index first). With C the
// query's class size, the R = C - 1 other members are the relevant shapes:
//   NN  = 1 if the first retrieved is relevant
//   FT  = (relevant among the first R) / R        (first tier)
//   ST  = (relevant among the first 2R) / R       (second tier)
//   E   = 2 P R' / (P + R') over the first 32 retrieved, P = relevant/32,
//         R' = relevant/R (0 when none is relevant)
//   DCG = sum_k G_k / log2(k) (k >= 2; G_1 for k = 1), G_k = 1 if the k-th
//         retrieved is relevant, over the whole list, divided by the same sum
//         for the ideal list (R relevant first)
//   P(r) at recall r = 0.05, 0.10, ..., 1: the interpolated precision, the
//         largest precision at any rank whose recall is >= r
// Each measure is the mean over the queries whose class has another member.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

namespace unfold {

/// The recall levels of the precision-recall curve: 0.05, 0.10, ..., 1.
constexpr int kRecallLevels = 20;

struct RetrievalMeasures {
  double nn = 0, first_tier = 0, second_tier = 0, e_measure = 0, dcg = 0;
  std::vector<double> precision;  ///< at recall (k + 1) / kRecallLevels, k < kRecallLevels
  int queries = 0;                ///< shapes whose class has another member
};

/// The measures of the file comment.
/// @param dissimilarity n x n, smaller = more similar (the diagonal is ignored)
/// @param classes the class of each shape
/// @throws UsageError if the sizes differ, a value is NaN, or no class has two members
RetrievalMeasures retrieval_measures(const Eigen::MatrixXd& dissimilarity,
                                     const std::vector<std::string>& classes);

}  // namespace unfold
