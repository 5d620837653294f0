#include "solvers/best_rotations.h"

#include <Eigen/LU>
#include <Eigen/SVD>

namespace unfold {

Eigen::Matrix3d best_rotation(const Eigen::Matrix3d& cov) {
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(cov, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d U = svd.matrixU();
  const Eigen::Matrix3d V = svd.matrixV();
  Eigen::Matrix3d R = V * U.transpose();
  if (R.determinant() < 0) {
    U.col(2) = -U.col(2);  // singular values are sorted: column 2 is the weakest
    R = V * U.transpose();
  }
  return R;
}

void best_rotations(const EdgeGraph& g, const Eigen::MatrixX3d& rest,
                    const Eigen::MatrixX3d& current, Rotations* R) {
  R->resize(size_t(g.num_vertices));
#pragma omp parallel for schedule(static)
  for (int i = 0; i < g.num_vertices; ++i) {
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    for (int k = g.offsets[size_t(i)]; k < g.offsets[size_t(i) + 1]; ++k) {
      const int j = g.neighbors[size_t(k)];
      cov.noalias() += (rest.row(i) - rest.row(j)).transpose() * (current.row(i) - current.row(j));
    }
    (*R)[size_t(i)] = g.degree(i) > 0 ? best_rotation(cov) : Eigen::Matrix3d::Identity();
  }
}

}  // namespace unfold
