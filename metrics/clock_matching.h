// Clock Matching (CM-BOF, Lian et al. 2013): two shapes' views, each a word
// histogram, are compared under every rotation of the view sphere that the
// pose normalisation cannot tell apart; the dissimilarity is the smallest sum
// of per-view histogram distances.
#pragma once

#include <vector>

#include "metrics/visual_vocabulary.h"

namespace unfold {

/// Normalised histogram intersection distance,
/// 1 - sum_w min(a_w, b_w) / max(sum_w a_w, sum_w b_w), in [0, 1]; 0 when both
/// are empty.
double histogram_distance(const WordHistogram& a, const WordHistogram& b);

/// min over the permutations p of sum_v histogram_distance(a[v], b[p[v]]).
/// @param rotations view permutations (metrics/view_sphere.h)
/// @throws UsageError if a and b have different view counts, no rotation is
///         given, or a permutation does not fit the views
double clock_matching_dissimilarity(const std::vector<WordHistogram>& a,
                                    const std::vector<WordHistogram>& b,
                                    const std::vector<std::vector<int>>& rotations);

}  // namespace unfold
