// Shape retrieval on canonical forms (the paper's Table 3, ORT-style): each
// shape becomes a normalised point sample (centred, unit RMS radius, principal
// axes), two shapes' dissimilarity is their best rigid alignment distance
// (PCA sign flips, then ICP, then the symmetric mean nearest-point distance),
// and retrieval is scored by metrics/retrieval_measures.h.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

namespace unfold {

/// CM-BOF's parameters (pipeline/cmbof_features.h, docs/evaluation.md says
/// where each comes from).
struct CmbofOptions {
  int view_subdivisions = 2;      ///< octahedron subdivisions: 66 views
  int image_size = 256;           ///< depth image width = height, pixels
  int features_per_view = 0;      ///< SIFT features kept per view, strongest first; 0: all
  int words = 1500;               ///< visual vocabulary size
  int training_features = 20000;  ///< features sampled for k-means (evenly over the set)
  int kmeans_iterations = 10;     ///< Lloyd iterations after k-means++ seeding
};

struct RetrievalOptions {
  int sample_points = 1000;  ///< vertices kept per shape (every ceil(n / this)-th)
  int icp_iterations = 20;   ///< ICP iterations after the best sign flip
  CmbofOptions cmbof = {};
};

/// The normalised sample of a shape: every ceil(n / sample_points)-th vertex,
/// centred, scaled to unit RMS distance from the centroid, rotated onto its
/// principal axes (largest variance first; a proper rotation).
/// @throws UsageError for fewer than 4 vertices or sample_points < 4
Eigen::MatrixX3d retrieval_sample(const Eigen::MatrixX3d& V, const RetrievalOptions& options);

/// Symmetric mean nearest-point distance: the mean over a of the distance to
/// the nearest b, and over b to the nearest a, averaged.
/// @throws UsageError for an empty set
double nearest_point_distance(const Eigen::MatrixX3d& A, const Eigen::MatrixX3d& B);

/// Index in B of the nearest point to each row of A (brute force: samples are
/// small); the mean distance to it in *mean_distance, the mean squared
/// distance in *mean_squared (either may be null).
/// @pre B is not empty
std::vector<int> nearest_points(const Eigen::MatrixX3d& A, const Eigen::MatrixX3d& B,
                                double* mean_distance, double* mean_squared = nullptr);

/// B moved onto A by ICP: `iterations` rounds of nearest points in A and the
/// best rigid motion of B onto them (Kabsch), stopping early once B stays put.
/// @pre A is not empty
Eigen::MatrixX3d icp_align(const Eigen::MatrixX3d& A, Eigen::MatrixX3d B, int iterations);

/// Dissimilarity of two normalised samples: B is tried under the four proper
/// sign flips of the principal axes, the best refined by ICP (nearest points
/// and Kabsch), then nearest_point_distance.
double shape_dissimilarity(const Eigen::MatrixX3d& A, const Eigen::MatrixX3d& B,
                           const RetrievalOptions& options);

/// All pairwise dissimilarities (symmetric, zero diagonal), in parallel.
Eigen::MatrixXd dissimilarity_matrix(const std::vector<Eigen::MatrixX3d>& samples,
                                     const RetrievalOptions& options);

}  // namespace unfold
