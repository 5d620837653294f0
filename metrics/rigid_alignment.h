// Best rigid alignment of corresponding point sets, to compare canonical forms
// of two poses up to a rigid motion.
#pragma once

#include <Eigen/Core>

namespace unfold {

struct RigidAlignment {
  Eigen::Matrix3d R;         ///< rotation, det = +1
  Eigen::Vector3d t;         ///< translation: aligned row k = R b_k + t
  Eigen::MatrixX3d aligned;  ///< B moved onto A
  double mean_distance = 0;  ///< (1/n) sum_k |a_k - aligned_k|
};

/// Rotation and translation (no scale, no reflection) minimising
/// sum_k |a_k - (R b_k + t)|^2 (Kabsch), rows corresponding.
/// @param A target points (n x 3), n >= 1
/// @param B points to move (n x 3)
/// @throws UsageError if the sizes differ or n == 0
RigidAlignment align_rigidly(const Eigen::MatrixX3d& A, const Eigen::MatrixX3d& B);

/// Mean distance between corresponding rows after align_rigidly(A, B).
/// @throws UsageError if the sizes differ or n == 0
double aligned_distance(const Eigen::MatrixX3d& A, const Eigen::MatrixX3d& B);

}  // namespace unfold
