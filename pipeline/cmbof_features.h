// CM-BOF's per-shape features (Lian et al., "CM-BOF: visual similarity-based
// 3D shape retrieval using Clock Matching and Bag-of-Features", MVA 2013): the
// shape normalised in pose (ORT's normalisation: area centroid, PCA or
// rectilinearity), scaled into the unit ball, seen as depth images from the
// view sphere's directions (metrics/view_sphere.h), each image's SIFT
// descriptors. Independent of the dataset, so computed once per shape and
// cached; the dataset's vocabulary (pipeline/cmbof_vocabulary.h) turns them
// into word histograms.
#pragma once

#include <Eigen/Core>
#include <istream>
#include <ostream>
#include <vector>

#include "metrics/shape_retrieval.h"
#include "render/sift_features.h"

namespace unfold {

struct CmbofFeatures {
  SiftDescriptors descriptors;  ///< every view's descriptors, view after view
  std::vector<int> view_start;  ///< view v's rows are [view_start[v], view_start[v + 1])

  int views() const { return int(view_start.size()) - 1; }
};

/// The features of a mesh with triangles F, from its ORT-normalised vertices.
/// @param normalised ort_normalise(V, F) (metrics/ort_dissimilarity.h), which
///        the descriptor shares with ORT
/// @throws UsageError as view_sphere_directions, depth_image
CmbofFeatures cmbof_features(const Eigen::MatrixX3d& normalised, const Eigen::MatrixX3i& F,
                             const CmbofOptions& options);

/// Writes the features: a text line "<views> <rows>", the view offsets, then
/// the descriptors' raw bytes. @pre a binary stream
void write_cmbof_features(std::ostream& s, const CmbofFeatures& features);

/// Reads what write_cmbof_features wrote; false (and *features unspecified) if
/// the stream holds no such thing.
bool read_cmbof_features(std::istream& s, CmbofFeatures* features);

}  // namespace unfold
