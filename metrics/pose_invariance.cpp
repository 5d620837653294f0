#include "metrics/pose_invariance.h"

#include <Eigen/Geometry>

#include "core/errors.h"
#include "metrics/rigid_alignment.h"

namespace unfold {

double surface_area(const SurfaceMesh& mesh) {
  return surface_area(mesh.V, triangulate_faces(mesh));
}

double surface_area(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F) {
  double area = 0;
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    const Eigen::Vector3d a = V.row(F(f, 0)), b = V.row(F(f, 1)), c = V.row(F(f, 2));
    area += 0.5 * (b - a).cross(c - a).norm();
  }
  return area;
}

Eigen::MatrixX3d scaled_to_unit_area(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F) {
  if (F.size() > 0 && (F.minCoeff() < 0 || F.maxCoeff() >= V.rows()))
    throw UsageError("pose_distance: a triangle names a vertex out of range");
  const double area = surface_area(V, F);
  if (!(area > 0)) throw UsageError("pose_distance: a surface has zero area");
  return V / std::sqrt(area);
}

double pose_distance(const Eigen::MatrixX3d& A, const Eigen::MatrixX3d& B,
                     const Eigen::MatrixX3i& F) {
  if (A.rows() != B.rows()) throw UsageError("pose_distance: the two poses differ in size");
  return aligned_distance(scaled_to_unit_area(A, F), scaled_to_unit_area(B, F));
}

double pose_distance(const Eigen::MatrixX3d& A, const Eigen::MatrixX3i& F_A,
                     const Eigen::VectorXi& rows_a, const Eigen::MatrixX3d& B,
                     const Eigen::MatrixX3i& F_B, const Eigen::VectorXi& rows_b) {
  if (rows_a.size() != rows_b.size() || rows_a.size() == 0)
    throw UsageError("pose_distance: the two correspondence lists differ in size or are empty");
  if (rows_a.minCoeff() < 0 || rows_a.maxCoeff() >= A.rows() || rows_b.minCoeff() < 0 ||
      rows_b.maxCoeff() >= B.rows())
    throw UsageError("pose_distance: a correspondence names a vertex out of range");
  return aligned_distance(scaled_to_unit_area(A, F_A)(rows_a, Eigen::all),
                          scaled_to_unit_area(B, F_B)(rows_b, Eigen::all));
}

Eigen::MatrixX3d transfer_by_nearest_point(const Eigen::MatrixX3d& rest,
                                           const Eigen::MatrixX3d& moved,
                                           const Eigen::MatrixX3d& targets) {
  if (rest.rows() != moved.rows() || rest.rows() == 0)
    throw UsageError("transfer_by_nearest_point: rest and moved positions differ in size");
  Eigen::MatrixX3d out(targets.rows(), 3);
#pragma omp parallel for schedule(static)
  for (Eigen::Index i = 0; i < targets.rows(); ++i) {
    Eigen::Index nearest;
    (rest.rowwise() - targets.row(i)).rowwise().squaredNorm().minCoeff(&nearest);
    out.row(i) = moved.row(nearest);
  }
  return out;
}

}  // namespace unfold
