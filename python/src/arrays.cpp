#include "arrays.h"

namespace unfold::python {

SurfaceMesh make_surface(const Vertices& V, const Elements& F) {
  SurfaceMesh mesh;
  mesh.V = V;
  mesh.faces.reserve(F.rows());
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    mesh.faces.emplace_back(F.row(f).data(), F.row(f).data() + F.cols());
  return mesh;
}

std::pair<Vertices, Elements> to_arrays(const SurfaceMesh& mesh) {
  return {mesh.V, triangulate_faces(mesh)};
}

}  // namespace unfold::python
