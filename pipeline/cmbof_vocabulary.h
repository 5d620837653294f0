// CM-BOF's visual vocabulary for a dataset and the shapes' word histograms.
// The vocabulary is learned once per dataset (per method's forms) from the
// cached features of all its shapes, so every shard of a split run must use
// the same one: it is a deterministic function of the features, stored in the
// output directory by the first run that learns it and read by the others,
// and its fingerprint is part of the CMBOF similarity blocks' key, so that a
// block made with another vocabulary is never mixed in.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "metrics/visual_vocabulary.h"
#include "pipeline/cmbof_features.h"

namespace unfold {

/// The vocabulary of a dataset: learn_vocabulary (seed 1) on every
/// ceil(total / training_features)-th descriptor of the shapes' features taken
/// in order.
/// @throws UsageError if the shapes have no features at all
Eigen::MatrixXf cmbof_vocabulary(const std::vector<const CmbofFeatures*>& shapes,
                                 const CmbofOptions& options);

/// One word histogram per view.
std::vector<WordHistogram> cmbof_histograms(const CmbofFeatures& features,
                                            const Eigen::MatrixXf& vocabulary);

/// A 64-bit FNV-1a hash of the vocabulary's size and values, in hex.
std::string vocabulary_fingerprint(const Eigen::MatrixXf& vocabulary);

/// A 64-bit FNV-1a hash of a shape's features, in hex: part of the vocabulary's
/// key, so that a vocabulary learned before a shape was unfolded again is not
/// read back.
std::string features_fingerprint(const CmbofFeatures& features);

/// Writes the vocabulary (text, exact round trip) atomically with `key` (what it
/// depends on: options and shapes). @throws OutputError
void write_vocabulary(const std::string& path, const Eigen::MatrixXf& vocabulary,
                      const std::string& key);

/// The vocabulary in `path`, or nothing if missing, malformed or of another key.
std::optional<Eigen::MatrixXf> read_vocabulary(const std::string& path, const std::string& key);

}  // namespace unfold
