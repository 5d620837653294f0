#include "metrics/tet_deformation.h"

#include <Eigen/LU>
#include <limits>
#include <string>

#include "core/errors.h"
#include "geometry/best_rotation.h"

namespace unfold {

TetDeformation tet_deformation(const Eigen::MatrixX3d& P, const Eigen::MatrixX3d& Q,
                               const Eigen::MatrixX4i& T) {
  if (P.rows() != Q.rows())
    throw UsageError("tet_deformation: " + std::to_string(P.rows()) + " rest and " +
                     std::to_string(Q.rows()) + " deformed positions");
  if (T.size() > 0 && (T.minCoeff() < 0 || T.maxCoeff() >= P.rows()))
    throw UsageError("tet_deformation: a tet indexes a vertex outside [0, " +
                     std::to_string(P.rows()) + ")");
  TetDeformation result;
  result.volume_ratio.resize(T.rows());
  result.rigidity.resize(T.rows());
  for (Eigen::Index t = 0; t < T.rows(); ++t) {
    Eigen::Matrix3d rest, deformed;  // edge vectors from corner 0, as columns
    for (int k = 0; k < 3; ++k) {
      rest.col(k) = (P.row(T(t, k + 1)) - P.row(T(t, 0))).transpose();
      deformed.col(k) = (Q.row(T(t, k + 1)) - Q.row(T(t, 0))).transpose();
    }
    if (rest.determinant() == 0) {
      result.volume_ratio[t] = result.rigidity[t] = std::numeric_limits<double>::quiet_NaN();
      continue;
    }
    const Eigen::Matrix3d F = deformed * rest.inverse();
    result.volume_ratio[t] = F.determinant();
    // sum_k |F e_k - R e_k|^2 = |F - R|_F^2, whose minimiser best_rotation gives for cov F^T.
    result.rigidity[t] = (F - best_rotation(F.transpose())).norm();
  }
  return result;
}

}  // namespace unfold
