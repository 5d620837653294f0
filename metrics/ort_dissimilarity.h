// ORT retrieval (the paper's Table 3, after Pickup et al.'s canonical-form
// benchmarks): each shape is normalised (centred at its area centroid, scaled
// to unit surface area, oriented by PCA or by rectilinearity), and two shapes'
// dissimilarity is the mean squared vertex error after the optimal rigid
// transformation. Shapes of different classes share no vertex order, so the
// error pairs each vertex with the nearest vertex of the other shape
// (symmetrically); the transformation is the best of the 24 rotations of a
// cube (the orientation's remaining ambiguity), refined by ICP.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace unfold {

/// The grid of the silhouettes that choose the orientation: 256 x 256 pixels,
/// as in the public reimplementation of CM-BOF (Pickup).
constexpr int kSilhouetteResolution = 256;

/// The total silhouette area of (V, F) in the three axis views: the pixels
/// (metrics/silhouette_area.h, kSilhouetteResolution) covered along x, y and z
/// by the shape scaled into the unit ball about the origin.
/// @pre V not all at the origin
long axis_silhouette_pixels(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F);

/// The orientation of the normalised mesh: its principal axes (area-weighted
/// second moments, largest first) or its rectilinearity orientation
/// (metrics/rectilinearity.h), whichever gives the smaller total silhouette
/// area in the three axis views (axis_silhouette_pixels; a tie keeps
/// rectilinearity). Lian, Rosin and Sun combine the two "by a simple selection
/// criterion" they do not spell out in their abstract; this is the public
/// reimplementation's (Pickup, poseNormalisationPCAplusRECT.m), probably what
/// the canonical-form benchmarks ran.
/// @return R with det +1; the oriented points are the rows of V R^T
/// @pre V centred at the area centroid
Eigen::Matrix3d ort_orientation(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F);

/// The ORT normalisation (shared with CM-BOF, pipeline/cmbof_features.h): the
/// mesh's vertices centred at its area centroid, scaled to unit surface area
/// and oriented by ort_orientation.
/// @throws UsageError for fewer than 4 vertices or zero area
Eigen::MatrixX3d ort_normalise(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F);

/// Every ceil(n / count)-th row of V (count >= 1): an even subsample that keeps
/// the order.
Eigen::MatrixX3d evenly_spaced_rows(const Eigen::MatrixX3d& V, Eigen::Index count);

/// The ORT sample: every ceil(n / sample_points)-th vertex of ort_normalise.
/// @throws UsageError for fewer than 4 vertices, sample_points < 4 or zero area
Eigen::MatrixX3d ort_sample(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
                            int sample_points);

/// The 24 rotations of a cube (signed permutation matrices with det +1): the
/// ambiguity left by ort_orientation.
std::vector<Eigen::Matrix3d> cube_rotations();

/// The symmetric mean squared nearest-point distance,
/// (mean_a min_b |a - b|^2 + mean_b min_a |a - b|^2) / 2.
/// @throws UsageError for an empty set
double mean_squared_point_error(const Eigen::MatrixX3d& A, const Eigen::MatrixX3d& B);

/// ORT dissimilarity of two ORT samples: the smallest mean_squared_point_error
/// of A and B under the 24 cube rotations (scored on at most 200 points of
/// each), then after `icp_iterations` of ICP from the best.
/// @throws UsageError for an empty set
double ort_dissimilarity(const Eigen::MatrixX3d& A, const Eigen::MatrixX3d& B, int icp_iterations);

}  // namespace unfold
