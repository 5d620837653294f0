// Signed volumes of tetrahedra.
#pragma once

#include <Eigen/Core>

namespace unfold {

/// Signed volume of one tetrahedron, its corners the rows of x (positive for a
/// right-handed corner order).
double tet_volume(const Eigen::Matrix<double, 4, 3>& x);

/// Signed volume of each tetrahedron (tet_volume of its corners).
Eigen::VectorXd tet_volumes(const Eigen::MatrixX3d& V, const Eigen::MatrixX4i& T);

/// Number of tetrahedra whose signed volume in Q has the opposite sign of (or
/// is zero while non-zero in) the rest positions P: inverted elements.
int count_inverted_tets(const Eigen::MatrixX3d& P, const Eigen::MatrixX3d& Q,
                        const Eigen::MatrixX4i& T);

}  // namespace unfold
