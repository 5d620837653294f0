#include "metrics/ort_dissimilarity.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <limits>
#include <vector>

#include "core/errors.h"
#include "metrics/rectilinearity.h"
#include "metrics/shape_retrieval.h"
#include "metrics/silhouette_area.h"

namespace unfold {

long axis_silhouette_pixels(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F) {
  // Into the unit ball, which the views' square [-1, 1]^2 frames.
  const Eigen::MatrixX3d unit = V / V.rowwise().norm().maxCoeff();
  long pixels = 0;
  for (int axis = 0; axis < 3; ++axis)
    pixels += silhouette_pixels(unit, F, axis, kSilhouetteResolution);
  return pixels;
}

Eigen::MatrixX3d evenly_spaced_rows(const Eigen::MatrixX3d& V, Eigen::Index count) {
  const Eigen::Index stride = std::max<Eigen::Index>(1, (V.rows() + count - 1) / count);
  Eigen::MatrixX3d S((V.rows() + stride - 1) / stride, 3);
  for (Eigen::Index i = 0; i < S.rows(); ++i) S.row(i) = V.row(i * stride);
  return S;
}

std::vector<Eigen::Matrix3d> cube_rotations() {
  std::vector<Eigen::Matrix3d> rotations;
  const int permutations[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (const auto& p : permutations)
    for (int signs = 0; signs < 8; ++signs) {
      Eigen::Matrix3d R = Eigen::Matrix3d::Zero();
      for (int k = 0; k < 3; ++k) R(k, p[k]) = (signs >> k & 1) ? -1 : 1;
      if (R.determinant() > 0) rotations.push_back(R);
    }
  return rotations;
}

Eigen::Matrix3d ort_orientation(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F) {
  // Area-weighted second moments: each face's area shared by its corners.
  Eigen::Matrix3d moments = Eigen::Matrix3d::Zero();
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    const Eigen::Vector3d a = V.row(F(f, 0)), b = V.row(F(f, 1)), c = V.row(F(f, 2));
    const double area = 0.5 * (b - a).cross(c - a).norm();
    moments += area / 3 * (a * a.transpose() + b * b.transpose() + c * c.transpose());
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(moments);
  Eigen::Matrix3d pca = eig.eigenvectors().rowwise().reverse().transpose();  // rows: axes
  if (pca.determinant() < 0) pca.row(2) *= -1;
  const Eigen::Matrix3d rect = rectilinearity_orientation(V, F);
  // Ties to rectilinearity, as in the public reimplementation.
  return axis_silhouette_pixels(V * pca.transpose(), F) <
                 axis_silhouette_pixels(V * rect.transpose(), F)
             ? pca
             : rect;
}

Eigen::MatrixX3d ort_normalise(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F) {
  if (V.rows() < 4) throw UsageError("ORT needs at least 4 vertices");
  double area = 0;
  Eigen::RowVector3d centroid = Eigen::RowVector3d::Zero();
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    const Eigen::RowVector3d a = V.row(F(f, 0)), b = V.row(F(f, 1)), c = V.row(F(f, 2));
    const double face = 0.5 * (b - a).cross(c - a).norm();
    area += face, centroid += face * (a + b + c) / 3;
  }
  if (area <= 0) throw UsageError("ORT: the mesh has zero area");
  const Eigen::MatrixX3d normalised = (V.rowwise() - centroid / area) / std::sqrt(area);
  return normalised * ort_orientation(normalised, F).transpose();
}

Eigen::MatrixX3d ort_sample(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
                            int sample_points) {
  if (V.rows() < 4 || sample_points < 4)
    throw UsageError("ORT needs at least 4 vertices and sample points");
  return evenly_spaced_rows(ort_normalise(V, F), sample_points);
}

double mean_squared_point_error(const Eigen::MatrixX3d& A, const Eigen::MatrixX3d& B) {
  if (A.rows() == 0 || B.rows() == 0) throw UsageError("mean_squared_point_error: empty set");
  double ab, ba;
  nearest_points(A, B, nullptr, &ab);
  nearest_points(B, A, nullptr, &ba);
  return 0.5 * (ab + ba);
}

double ort_dissimilarity(const Eigen::MatrixX3d& A, const Eigen::MatrixX3d& B, int icp_iterations) {
  if (A.rows() == 0 || B.rows() == 0) throw UsageError("ort_dissimilarity: empty set");
  static const std::vector<Eigen::Matrix3d> rotations = cube_rotations();
  const Eigen::MatrixX3d a = evenly_spaced_rows(A, 200), b = evenly_spaced_rows(B, 200);
  Eigen::Matrix3d best_rotation;
  double best = std::numeric_limits<double>::infinity();
  for (const Eigen::Matrix3d& R : rotations) {
    const double e = mean_squared_point_error(a, b * R.transpose());
    if (e < best) best = e, best_rotation = R;
  }
  const Eigen::MatrixX3d start = B * best_rotation.transpose();
  return std::min(mean_squared_point_error(A, start),
                  mean_squared_point_error(A, icp_align(A, start, icp_iterations)));
}

}  // namespace unfold
