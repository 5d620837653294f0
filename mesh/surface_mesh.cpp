#include "mesh/surface_mesh.h"

namespace unfold {

SurfaceMesh surface_mesh_from_rows(const std::vector<double>& coords,
                                   std::vector<std::vector<int>> faces) {
  SurfaceMesh mesh;
  mesh.V = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>(
      coords.data(), Eigen::Index(coords.size() / 3), 3);
  mesh.faces = std::move(faces);
  return mesh;
}

Eigen::MatrixX3i triangulate_faces(const SurfaceMesh& mesh) {
  Eigen::Index count = 0;
  for (const auto& f : mesh.faces) count += f.size() >= 3 ? Eigen::Index(f.size() - 2) : 0;
  Eigen::MatrixX3i F(count, 3);
  Eigen::Index row = 0;
  for (const auto& f : mesh.faces)
    for (size_t k = 2; k < f.size(); ++k) F.row(row++) << f[0], f[k - 1], f[k];
  return F;
}

double mean_edge_length(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F) {
  double sum = 0;
  for (Eigen::Index t = 0; t < F.rows(); ++t)
    for (int k = 0; k < 3; ++k) sum += (V.row(F(t, k)) - V.row(F(t, (k + 1) % 3))).norm();
  return F.rows() > 0 ? sum / double(3 * F.rows()) : 0;
}

}  // namespace unfold
