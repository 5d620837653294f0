#include "mesh/tet_volumes.h"

#include <Eigen/Geometry>

namespace unfold {

double tet_volume(const Eigen::Matrix<double, 4, 3>& x) {
  const Eigen::RowVector3d a = x.row(0);
  return (x.row(1) - a).cross(x.row(2) - a).dot(x.row(3) - a) / 6.0;
}

Eigen::VectorXd tet_volumes(const Eigen::MatrixX3d& V, const Eigen::MatrixX4i& T) {
  Eigen::VectorXd volumes(T.rows());
  Eigen::Matrix<double, 4, 3> x;
  for (Eigen::Index t = 0; t < T.rows(); ++t) {
    for (int k = 0; k < 4; ++k) x.row(k) = V.row(T(t, k));
    volumes[t] = tet_volume(x);
  }
  return volumes;
}

int count_inverted_tets(const Eigen::MatrixX3d& P, const Eigen::MatrixX3d& Q,
                        const Eigen::MatrixX4i& T) {
  const Eigen::VectorXd rest = tet_volumes(P, T), now = tet_volumes(Q, T);
  int inverted = 0;
  for (Eigen::Index t = 0; t < T.rows(); ++t) inverted += rest[t] * now[t] <= 0 && rest[t] != 0;
  return inverted;
}

}  // namespace unfold
