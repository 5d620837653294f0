// Pose invariance (beyond the paper): how far apart the canonical forms of two
// poses of one shape are, vertex by vertex after the best rigid alignment, in
// units of the shape's size.
#pragma once

#include <Eigen/Core>

#include "mesh/surface_mesh.h"

namespace unfold {

/// Total area of the (fan-triangulated) faces.
double surface_area(const SurfaceMesh& mesh);

/// Mean |a_k - (R b_k + t)| after Procrustes (rows corresponding, no scale),
/// divided by sqrt(area). @throws UsageError if the sizes differ, n == 0 or area <= 0
double pose_distance(const Eigen::MatrixX3d& A, const Eigen::MatrixX3d& B, double area);

/// Carries a deformation to other points: each target point takes the moved
/// position of its nearest rest point (for canonical forms of a simplified
/// mesh, on the input's vertices; the error is of the order of the simplified
/// edge length times the local stretch).
/// @throws UsageError if rest and moved differ in size or rest is empty
Eigen::MatrixX3d transfer_by_nearest_point(const Eigen::MatrixX3d& rest,
                                           const Eigen::MatrixX3d& moved,
                                           const Eigen::MatrixX3d& targets);

}  // namespace unfold
