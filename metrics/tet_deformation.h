// How each tetrahedron deformed: its volume ratio and how far its linear map
// is from a rotation (per-cell fields for viewers such as ParaView).
#pragma once

#include <Eigen/Core>

namespace unfold {

struct TetDeformation {
  Eigen::VectorXd volume_ratio;  ///< det F: signed deformed / rest volume (< 0: inverted)
  Eigen::VectorXd rigidity;      ///< |F - R|_F with R the rotation nearest F (0: rigid)
};

/// The deformation gradient F of each tet (the linear map taking its rest edge
/// vectors P to the deformed ones Q) summarised per tet.
/// @param P rest positions, Q deformed positions (same size), T tets indexing them
/// A rest tet of zero volume (the unfolded shape's tets put back into the
/// input may flatten one) has no F: both its fields are NaN.
/// @throws UsageError if sizes disagree or T indexes outside P
TetDeformation tet_deformation(const Eigen::MatrixX3d& P, const Eigen::MatrixX3d& Q,
                               const Eigen::MatrixX4i& T);

}  // namespace unfold
