#include "metrics/shape_retrieval.h"

#include <Eigen/Eigenvalues>
#include <limits>

#include "core/errors.h"
#include "metrics/rigid_alignment.h"

namespace unfold {

std::vector<int> nearest_points(const Eigen::MatrixX3d& A, const Eigen::MatrixX3d& B,
                                double* mean_distance, double* mean_squared) {
  std::vector<int> nearest(size_t(A.rows()));
  double sum = 0, sum_squared = 0;
  for (Eigen::Index i = 0; i < A.rows(); ++i) {
    Eigen::Index best;
    const double d2 = (B.rowwise() - A.row(i)).rowwise().squaredNorm().minCoeff(&best);
    nearest[size_t(i)] = int(best);
    sum += std::sqrt(d2), sum_squared += d2;
  }
  if (mean_distance) *mean_distance = sum / double(A.rows());
  if (mean_squared) *mean_squared = sum_squared / double(A.rows());
  return nearest;
}

Eigen::MatrixX3d icp_align(const Eigen::MatrixX3d& A, Eigen::MatrixX3d B, int iterations) {
  for (int it = 0; it < iterations; ++it) {
    const std::vector<int> nearest = nearest_points(B, A, nullptr);
    Eigen::MatrixX3d matched(B.rows(), 3);
    for (Eigen::Index i = 0; i < B.rows(); ++i) matched.row(i) = A.row(nearest[size_t(i)]);
    const RigidAlignment step = align_rigidly(matched, B);
    const double moved = (step.aligned - B).norm();
    B = step.aligned;
    if (moved < 1e-9 * std::sqrt(double(B.rows()))) break;
  }
  return B;
}

Eigen::MatrixX3d retrieval_sample(const Eigen::MatrixX3d& V, const RetrievalOptions& options) {
  if (V.rows() < 4 || options.sample_points < 4)
    throw UsageError("retrieval needs at least 4 vertices and sample points");
  const Eigen::Index stride = (V.rows() + options.sample_points - 1) / options.sample_points;
  Eigen::MatrixX3d S((V.rows() + stride - 1) / stride, 3);
  for (Eigen::Index i = 0; i < S.rows(); ++i) S.row(i) = V.row(i * stride);
  S.rowwise() -= S.colwise().mean();
  const double rms = std::sqrt(S.rowwise().squaredNorm().mean());
  if (rms > 0) S /= rms;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(S.transpose() * S);
  Eigen::Matrix3d axes = eig.eigenvectors().rowwise().reverse();  // largest variance first
  if (axes.determinant() < 0) axes.col(2) *= -1;
  return S * axes;
}

double nearest_point_distance(const Eigen::MatrixX3d& A, const Eigen::MatrixX3d& B) {
  if (A.rows() == 0 || B.rows() == 0) throw UsageError("nearest_point_distance: empty point set");
  double ab, ba;
  nearest_points(A, B, &ab);
  nearest_points(B, A, &ba);
  return 0.5 * (ab + ba);
}

double shape_dissimilarity(const Eigen::MatrixX3d& A, const Eigen::MatrixX3d& B,
                           const RetrievalOptions& options) {
  // Principal axes are defined up to sign: the four flips with det = +1.
  static const double flips[4][3] = {{1, 1, 1}, {-1, -1, 1}, {-1, 1, -1}, {1, -1, -1}};
  Eigen::MatrixX3d best;
  double best_distance = std::numeric_limits<double>::infinity();
  for (const auto& f : flips) {
    const Eigen::MatrixX3d flipped = B * Eigen::Vector3d(f[0], f[1], f[2]).asDiagonal();
    const double d = nearest_point_distance(A, flipped);
    if (d < best_distance) best_distance = d, best = flipped;
  }
  best = icp_align(A, best, options.icp_iterations);
  return std::min(best_distance, nearest_point_distance(A, best));
}

Eigen::MatrixXd dissimilarity_matrix(const std::vector<Eigen::MatrixX3d>& samples,
                                     const RetrievalOptions& options) {
  const int n = int(samples.size());
  Eigen::MatrixXd D = Eigen::MatrixXd::Zero(n, n);
#pragma omp parallel for schedule(dynamic)
  for (int k = 0; k < n * n; ++k) {
    const int i = k / n, j = k % n;
    if (j <= i) continue;
    D(i, j) = D(j, i) = shape_dissimilarity(samples[size_t(i)], samples[size_t(j)], options);
  }
  return D;
}

}  // namespace unfold
