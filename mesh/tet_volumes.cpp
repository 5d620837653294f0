#include "mesh/tet_volumes.h"

#include <Eigen/Geometry>

namespace unfold {

Eigen::VectorXd tet_volumes(const Eigen::MatrixX3d& V, const Eigen::MatrixX4i& T) {
  Eigen::VectorXd volumes(T.rows());
  for (Eigen::Index t = 0; t < T.rows(); ++t) {
    const Eigen::Vector3d a = V.row(T(t, 0));
    volumes[t] = (V.row(T(t, 1)).transpose() - a)
                     .cross(V.row(T(t, 2)).transpose() - a)
                     .dot(V.row(T(t, 3)).transpose() - a) /
                 6.0;
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
