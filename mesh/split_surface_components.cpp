#include "mesh/split_surface_components.h"

#include "mesh/edge_graph.h"

namespace unfold {

std::vector<SurfaceComponent> split_surface_components(const SurfaceMesh& mesh) {
  std::vector<int> label;
  // Labels are handed out scanning vertices upwards: component c's lowest
  // vertex is below component c+1's.
  const int count =
      connected_components(build_edge_graph(int(mesh.V.rows()), triangulate_faces(mesh)), &label);
  std::vector<SurfaceComponent> parts(static_cast<size_t>(count));
  std::vector<int> local(size_t(mesh.V.rows()));
  for (int v = 0; v < int(mesh.V.rows()); ++v) {
    auto& part = parts[size_t(label[size_t(v)])];
    local[size_t(v)] = int(part.vertices.size());
    part.vertices.push_back(v);
  }
  for (auto& part : parts) {
    part.mesh.V.resize(Eigen::Index(part.vertices.size()), 3);
    for (size_t i = 0; i < part.vertices.size(); ++i)
      part.mesh.V.row(Eigen::Index(i)) = mesh.V.row(part.vertices[i]);
  }
  for (const auto& face : mesh.faces) {
    std::vector<int> mapped;
    mapped.reserve(face.size());
    for (int v : face) mapped.push_back(local[size_t(v)]);
    parts[size_t(label[size_t(face[0])])].mesh.faces.push_back(std::move(mapped));
  }
  return parts;
}

}  // namespace unfold
