#include "solvers/best_rotations.h"

#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <cmath>

namespace unfold {
namespace {

// Cofactor matrix C of A (A^{-T} = C / det A), and det A, without pivoting:
// callers only pass well-conditioned matrices.
inline double cofactor(const Eigen::Matrix3d& A, Eigen::Matrix3d* C) {
  C->col(0) = A.col(1).cross(A.col(2));
  C->col(1) = A.col(2).cross(A.col(0));
  C->col(2) = A.col(0).cross(A.col(1));
  return A.col(0).dot(C->col(0));
}

// Kabsch through the SVD: the reference method, and the fallback for cells
// whose covariance is (near) singular or orientation-reversing.
Eigen::Matrix3d rotation_by_svd(const Eigen::Matrix3d& cov) {
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

}  // namespace

Eigen::Matrix3d best_rotation(const Eigen::Matrix3d& cov) {
  // With cov = U S V^T the answer is V U^T, the orthogonal polar factor of
  // cov^T whenever det(cov) > 0. Higham's scaled Newton iteration
  // X <- (z X + X^{-T} / z) / 2 reaches it in ~6-8 steps of 3x3 cofactors,
  // far cheaper than a Jacobi SVD. It needs det(X) clearly positive (no
  // reflection to fix, no rank loss): checked through the scale-free
  // ratio det(cov) / |cov|_F^3, which is 3^{-3/2} for a multiple of a rotation and
  // goes to 0 with the smallest singular value.
  const double norm = cov.norm();
  if (!(norm > 0)) return rotation_by_svd(cov);
  Eigen::Matrix3d X = cov.transpose() / norm;  // unit scale: no over/underflow below
  Eigen::Matrix3d C;
  double det = cofactor(X, &C);
  if (!(det > 1e-6)) return rotation_by_svd(cov);
  for (int k = 0; k < 30; ++k) {
    // Frobenius scaling z = (|X^{-1}|_F / |X|_F)^{1/2}, X^{-1} = C^T / det.
    const double z = std::sqrt(C.norm() / (det * X.norm()));
    const Eigen::Matrix3d next = 0.5 * (z * X + C / (z * det));
    const double change = (next - X).squaredNorm();
    X = next;
    if (change < 1e-26) return X;  // quadratic convergence: X is exact to roundoff
    det = cofactor(X, &C);
  }
  return rotation_by_svd(cov);  // not reached for the conditioning admitted above
}

void best_rotations(const EdgeGraph& g, const Eigen::MatrixX3d& rest,
                    const Eigen::MatrixX3d& current, Rotations* R) {
  R->resize(size_t(g.num_vertices));
#pragma omp parallel for schedule(static)
  for (int i = 0; i < g.num_vertices; ++i) {
    const Eigen::RowVector3d p = rest.row(i), q = current.row(i);
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    for (int k = g.offsets[size_t(i)]; k < g.offsets[size_t(i) + 1]; ++k) {
      const int j = g.neighbors[size_t(k)];
      cov.noalias() += (p - rest.row(j)).transpose() * (q - current.row(j));
    }
    (*R)[size_t(i)] = g.degree(i) > 0 ? best_rotation(cov) : Eigen::Matrix3d::Identity();
  }
}

}  // namespace unfold
