// The visual vocabulary of bag-of-features retrieval (CM-BOF, Lian et al.
// 2013): k-means centres of local image descriptors learned on a dataset's
// features; an image becomes the histogram of its descriptors' nearest words.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <utility>
#include <vector>

namespace unfold {

/// A word histogram, sparse: (word, count) pairs in increasing word order,
/// counts > 0.
using WordHistogram = std::vector<std::pair<int, int>>;

/// k-means (Lloyd) on the rows of `features`: min(words, rows) centres seeded by
/// k-means++ from a std::mt19937_64 with `seed`, then `iterations` rounds of
/// assignment to the nearest centre and centre update (an emptied centre
/// stays). Deterministic for given arguments on a given build.
/// @return one word per row
/// @throws UsageError for no features, words < 1 or iterations < 0
Eigen::MatrixXf learn_vocabulary(const Eigen::MatrixXf& features, int words, int iterations,
                                 std::uint64_t seed);

/// The index of the nearest word (Euclidean; ties to the lower index) of each
/// row of `features`. @pre same column count
Eigen::VectorXi nearest_words(const Eigen::MatrixXf& vocabulary, const Eigen::MatrixXf& features);

/// The histogram of nearest_words(vocabulary, features).
WordHistogram word_histogram(const Eigen::MatrixXf& vocabulary, const Eigen::MatrixXf& features);

}  // namespace unfold
