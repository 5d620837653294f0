#include "metrics/rigid_alignment.h"

#include "core/errors.h"
#include "geometry/best_rotation.h"

namespace unfold {

RigidAlignment align_rigidly(const Eigen::MatrixX3d& A, const Eigen::MatrixX3d& B) {
  if (A.rows() != B.rows() || A.rows() == 0)
    throw UsageError("align_rigidly: need two non-empty point sets of equal size");
  const Eigen::RowVector3d ca = A.colwise().mean(), cb = B.colwise().mean();
  const Eigen::MatrixX3d a = A.rowwise() - ca, b = B.rowwise() - cb;
  RigidAlignment result;
  result.R = best_rotation(b.transpose() * a);  // maps source b onto target a, det = +1
  result.t = ca.transpose() - result.R * cb.transpose();
  result.aligned = (B * result.R.transpose()).rowwise() + result.t.transpose();
  result.mean_distance = (A - result.aligned).rowwise().norm().mean();
  return result;
}

double aligned_distance(const Eigen::MatrixX3d& A, const Eigen::MatrixX3d& B) {
  return align_rigidly(A, B).mean_distance;
}

}  // namespace unfold
