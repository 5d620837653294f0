// Pose invariance (beyond the paper): how far apart the canonical forms of two
// poses of one shape are, vertex by vertex after the best rigid alignment, in
// units of the shape's size.
#pragma once

#include <Eigen/Core>

#include "mesh/surface_mesh.h"

namespace unfold {

/// Total area of the (fan-triangulated) faces.
double surface_area(const SurfaceMesh& mesh);

/// Total area of the triangles F over the vertex positions V.
double surface_area(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F);

/// The pose distance of issue 16: A and B (one surface in two poses: rows
/// corresponding, triangles F) each scaled to unit surface area, then the mean
/// |a_k - (R b_k + t)| after Procrustes (no further scale). Zero for two forms
/// that differ by a rigid motion and a uniform scale.
/// @throws UsageError if the sizes differ, n == 0 or a surface has zero area
double pose_distance(const Eigen::MatrixX3d& A, const Eigen::MatrixX3d& B,
                     const Eigen::MatrixX3i& F);

/// The same pose distance for two shapes meshed differently, on given
/// correspondences: A (triangles F_A) and B (triangles F_B) each scaled to its
/// own unit surface area, then the mean |a_{rows_a[k]} - (R b_{rows_b[k]} + t)|
/// over k after Procrustes on those rows. With F_A = F_B and rows_a = rows_b =
/// 0..n-1 it is the vertex-order distance above.
/// @param rows_a, rows_b zero-based vertex ids of A and B, row k the same point
/// @throws UsageError if rows_a and rows_b differ in size or are empty, an id
///         or a triangle names a vertex out of range, or a surface has zero area
double pose_distance(const Eigen::MatrixX3d& A, const Eigen::MatrixX3i& F_A,
                     const Eigen::VectorXi& rows_a, const Eigen::MatrixX3d& B,
                     const Eigen::MatrixX3i& F_B, const Eigen::VectorXi& rows_b);

/// V divided by the square root of its surface area (triangles F): the form at unit area.
/// @throws UsageError if a triangle names a vertex out of range or the area is zero
Eigen::MatrixX3d scaled_to_unit_area(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F);

/// Carries a deformation to other points: each target point takes the moved
/// position of its nearest rest point (for canonical forms of a simplified
/// mesh, on the input's vertices; the error is of the order of the simplified
/// edge length times the local stretch).
/// @throws UsageError if rest and moved differ in size or rest is empty
Eigen::MatrixX3d transfer_by_nearest_point(const Eigen::MatrixX3d& rest,
                                           const Eigen::MatrixX3d& moved,
                                           const Eigen::MatrixX3d& targets);

}  // namespace unfold
