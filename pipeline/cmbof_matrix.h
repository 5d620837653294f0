// The CM-BOF dissimilarity matrix of a set of meshes in memory (the Python
// API's entry point; unfold_batch does the same in cached, sharded steps):
// each mesh's features (pipeline/cmbof_features.h), the set's vocabulary and
// word histograms (pipeline/cmbof_vocabulary.h), clock matching of every pair.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "mesh/surface_mesh.h"
#include "metrics/shape_retrieval.h"

namespace unfold {

/// The symmetric matrix (zero diagonal, from the upper triangle) of CM-BOF
/// dissimilarities of `shapes`, the vocabulary learned on them.
/// @throws UsageError for fewer than 2 shapes, as ort_normalise and
///         cmbof_features, or if no view of any shape has a SIFT feature
Eigen::MatrixXd cmbof_matrix(const std::vector<SurfaceMesh>& shapes, const CmbofOptions& options);

}  // namespace unfold
