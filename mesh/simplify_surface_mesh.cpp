#include "mesh/simplify_surface_mesh.h"

// OpenMesh's VectorT default constructor leaves coordinates uninitialized on
// purpose; GCC 12 flags the copies its property containers make of them.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"

#include <glog/logging.h>

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Decimater/DecimaterT.hh>
#include <OpenMesh/Tools/Decimater/ModNormalFlippingT.hh>
#include <OpenMesh/Tools/Decimater/ModQuadricT.hh>
#include <string>

#include "core/errors.h"
#include "mesh/silence_openmesh.h"

namespace unfold {
namespace {

// Double-precision points, so that simplification loses no digits of the
// vertices it keeps.
struct DoubleTraits : OpenMesh::DefaultTraits {
  typedef OpenMesh::Vec3d Point;
  typedef OpenMesh::Vec3d Normal;
};
using HalfedgeMesh = OpenMesh::TriMesh_ArrayKernelT<DoubleTraits>;

}  // namespace

SurfaceMesh simplify_surface_mesh(const SurfaceMesh& mesh, int target_vertices) {
  if (target_vertices < 4)
    throw UsageError("simplification target of " + std::to_string(target_vertices) +
                     " vertices is too small (minimum 4)");
  if (mesh.V.rows() <= target_vertices) return mesh;

  const Eigen::MatrixX3i triangles = triangulate_faces(mesh);
  HalfedgeMesh hm;
  std::vector<HalfedgeMesh::VertexHandle> handles;
  handles.reserve(size_t(mesh.V.rows()));
  for (Eigen::Index i = 0; i < mesh.V.rows(); ++i)
    handles.push_back(hm.add_vertex(HalfedgeMesh::Point(mesh.V(i, 0), mesh.V(i, 1), mesh.V(i, 2))));
  int rejected = 0;
  {
    SilenceOpenMesh quiet;  // add_face reports each "complex edge" on omerr
    for (Eigen::Index t = 0; t < triangles.rows(); ++t) {
      const int a = triangles(t, 0), b = triangles(t, 1), c = triangles(t, 2);
      for (int v : {a, b, c})
        if (v < 0 || v >= mesh.V.rows())
          throw InputError("triangle " + std::to_string(t) + " refers to vertex " +
                           std::to_string(v) + " but the mesh has " +
                           std::to_string(mesh.V.rows()) + " vertices");
      if (a == b || b == c || a == c ||
          !hm.add_face(handles[size_t(a)], handles[size_t(b)], handles[size_t(c)]).is_valid())
        ++rejected;
    }
  }
  if (rejected > 0)
    LOG(WARNING) << "simplify_surface_mesh: left out " << rejected << " of " << triangles.rows()
                 << " triangles that the halfedge mesh cannot take (non-manifold or degenerate)";

  hm.request_face_normals();
  hm.update_face_normals();
  {
    SilenceOpenMesh quiet;
    OpenMesh::Decimater::DecimaterT<HalfedgeMesh> decimater(hm);
    OpenMesh::Decimater::ModQuadricT<HalfedgeMesh>::Handle quadric;
    OpenMesh::Decimater::ModNormalFlippingT<HalfedgeMesh>::Handle no_flips;
    decimater.add(quadric);
    decimater.add(no_flips);
    decimater.initialize();
    // Vertices whose faces were all left out (or that had none) would
    // otherwise count towards the target and come out unused.
    hm.delete_isolated_vertices();
    decimater.decimate_to(size_t(target_vertices));
    // Here, not after the block: the decimater's destructor releases the
    // status flags that mark the collapsed elements as deleted.
    hm.garbage_collection();
  }

  SurfaceMesh result;
  result.V.resize(Eigen::Index(hm.n_vertices()), 3);
  for (const auto v : hm.vertices())
    for (int k = 0; k < 3; ++k) result.V(v.idx(), k) = hm.point(v)[k];
  result.faces.reserve(hm.n_faces());
  for (const auto f : hm.faces()) {
    std::vector<int> face;
    for (const auto v : hm.fv_range(f)) face.push_back(v.idx());
    result.faces.push_back(std::move(face));
  }
  return result;
}

}  // namespace unfold
