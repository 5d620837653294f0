#include "mesh/mean_curvature_scales.h"

#include <Eigen/SparseCholesky>
#include <cmath>

#include "core/errors.h"
#include "mesh/cotangent_laplacian.h"
#include "mesh/lumped_masses.h"

namespace unfold {

Eigen::MatrixXd mean_curvature_scales(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
                                      const std::vector<double>& scales) {
  if (scales.empty()) throw UsageError("mean_curvature_scales: no scale given");
  for (const double s : scales)
    if (!(s > 0) || !std::isfinite(s))
      throw UsageError("mean_curvature_scales: scales must be positive");
  const Eigen::VectorXd masses = lumped_masses(V, F);
  const Eigen::SparseMatrix<double> W = cotangent_laplacian(V, F);
  Eigen::MatrixX3d normals = Eigen::MatrixX3d::Zero(V.rows(), 3);
  double area = 0, volume = 0;
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    const Eigen::Vector3d a = V.row(F(f, 0)), b = V.row(F(f, 1)), c = V.row(F(f, 2));
    const Eigen::Vector3d n = (b - a).cross(c - a);  // twice the area
    area += 0.5 * n.norm();
    volume += a.dot(b.cross(c)) / 6;
    for (int k = 0; k < 3; ++k) normals.row(F(f, k)) += n.transpose();
  }
  // W V points out of a convex surface; the signed volume says whether the
  // triangles' normals do too.
  const double orientation = volume < 0 ? -1.0 : 1.0;
  const Eigen::MatrixX3d curvature_normal = masses.cwiseInverse().asDiagonal() * (W * V);
  Eigen::VectorXd H(V.rows());
  for (Eigen::Index i = 0; i < V.rows(); ++i) {
    const double length = normals.row(i).norm();
    H(i) = length > 0 ? orientation * curvature_normal.row(i).dot(normals.row(i)) / length : 0;
  }
  H *= std::sqrt(area);
  const Eigen::SparseMatrix<double> M(masses.asDiagonal());
  Eigen::MatrixXd result(V.rows(), Eigen::Index(scales.size()));
  for (size_t k = 0; k < scales.size(); ++k) {
    const Eigen::SparseMatrix<double> A = M + (scales[k] * scales[k] * area) * W;
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(A);
    if (solver.info() != Eigen::Success)
      throw NumericalError("mean_curvature_scales: the smoothing system could not be factored");
    result.col(Eigen::Index(k)) = solver.solve(masses.cwiseProduct(H));
  }
  return result;
}

}  // namespace unfold
