#include "metrics/pose_invariance.h"

#include <Eigen/Geometry>

#include "core/errors.h"
#include "metrics/rigid_alignment.h"

namespace unfold {

double surface_area(const SurfaceMesh& mesh) {
  const Eigen::MatrixX3i F = triangulate_faces(mesh);
  double area = 0;
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    const Eigen::Vector3d a = mesh.V.row(F(f, 0)), b = mesh.V.row(F(f, 1)), c = mesh.V.row(F(f, 2));
    area += 0.5 * (b - a).cross(c - a).norm();
  }
  return area;
}

double pose_distance(const Eigen::MatrixX3d& A, const Eigen::MatrixX3d& B, double area) {
  if (!(area > 0)) throw UsageError("pose_distance: the surface area must be positive");
  return aligned_distance(A, B) / std::sqrt(area);
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
