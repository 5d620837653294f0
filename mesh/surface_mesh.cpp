#include "mesh/surface_mesh.h"

namespace unfold {

Eigen::MatrixX3i triangulate_faces(const SurfaceMesh& mesh) {
  Eigen::Index count = 0;
  for (const auto& f : mesh.faces) count += f.size() >= 3 ? Eigen::Index(f.size() - 2) : 0;
  Eigen::MatrixX3i F(count, 3);
  Eigen::Index row = 0;
  for (const auto& f : mesh.faces)
    for (size_t k = 2; k < f.size(); ++k) F.row(row++) << f[0], f[k - 1], f[k];
  return F;
}

}  // namespace unfold
