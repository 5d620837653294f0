// A surface's signed mean curvature smoothed at several scales: a per-vertex
// descriptor that tells a nose from the back of a head and toes from heels,
// so that a map placing a body turned round (front onto back) disagrees with
// it where a map the right way round agrees (solvers/match_canonical_forms.h).
#pragma once

#include <Eigen/Core>
#include <vector>

namespace unfold {

/// Per vertex and scale s: H smoothed by the implicit heat step
/// (M + t W) h = M H with t = s^2 area, where H = <M^{-1} W V, n> is the
/// signed sum of the principal curvatures, twice the mean curvature
/// (positive where the surface is convex, n the
/// outward area-weighted vertex normal; the orientation is taken from the
/// signed volume, so inward-facing triangles give the same values), times
/// sqrt(area) so that the values do not depend on the shape's size.
/// @param V vertex positions (n x 3), F triangles
/// @param scales smoothing lengths as fractions of sqrt(area), each > 0
/// @return n x scales.size()
/// @throws UsageError for no scale or a scale <= 0; InputError if the surface
///         has no area at a vertex; NumericalError if a smoothing system
///         cannot be factored
Eigen::MatrixXd mean_curvature_scales(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
                                      const std::vector<double>& scales = {0.01, 0.02, 0.04, 0.08});

}  // namespace unfold
