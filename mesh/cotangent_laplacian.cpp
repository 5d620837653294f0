#include "mesh/cotangent_laplacian.h"

#include <Eigen/Geometry>
#include <vector>

#include "core/errors.h"

namespace unfold {

Eigen::SparseMatrix<double> cotangent_laplacian(const Eigen::MatrixX3d& V,
                                                const Eigen::MatrixX3i& F) {
  const int n = int(V.rows());
  if (F.size() > 0 && (F.minCoeff() < 0 || F.maxCoeff() >= n))
    throw UsageError("cotangent_laplacian: a triangle names a vertex outside the mesh");
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(size_t(F.rows()) * 12);
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    const Eigen::Vector3d p[3] = {V.row(F(f, 0)), V.row(F(f, 1)), V.row(F(f, 2))};
    const double twice_area = (p[1] - p[0]).cross(p[2] - p[0]).norm();
    if (!(twice_area > 0)) continue;
    for (int k = 0; k < 3; ++k) {
      // The angle at corner k is opposite the edge (k+1, k+2).
      const int i = F(f, (k + 1) % 3), j = F(f, (k + 2) % 3);
      const double cot = (p[(k + 1) % 3] - p[k]).dot(p[(k + 2) % 3] - p[k]) / twice_area;
      const double w = 0.5 * cot;
      entries.emplace_back(i, j, -w);
      entries.emplace_back(j, i, -w);
      entries.emplace_back(i, i, w);
      entries.emplace_back(j, j, w);
    }
  }
  Eigen::SparseMatrix<double> W(n, n);
  W.setFromTriplets(entries.begin(), entries.end());
  return W;
}

}  // namespace unfold
