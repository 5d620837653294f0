#include "mesh/read_with_openmesh.h"

#include <OpenMesh/Core/IO/IOManager.hh>
#include <OpenMesh/Core/IO/importer/BaseImporter.hh>
#include <algorithm>
#include <vector>

#include "mesh/silence_openmesh.h"
#include "mesh/text_lines.h"

namespace unfold {
namespace {

// Records positions and faces exactly as the OpenMesh reader reports them: no
// halfedge structure, so faces on non-manifold edges are kept. Everything
// else a reader may offer (normals, colours, texture coordinates) is ignored.
class RawImporter : public OpenMesh::IO::BaseImporter {
 public:
  std::vector<double> coords;  // x y z per vertex
  std::vector<std::vector<int>> faces;

  OpenMesh::VertexHandle add_vertex(const OpenMesh::Vec3f& p) override {
    return add_vertex(OpenMesh::Vec3d(p));
  }
  OpenMesh::VertexHandle add_vertex(const OpenMesh::Vec3d& p) override {
    coords.insert(coords.end(), {p[0], p[1], p[2]});
    return OpenMesh::VertexHandle(int(n_vertices()) - 1);
  }
  OpenMesh::VertexHandle add_vertex() override { return add_vertex(OpenMesh::Vec3d(0, 0, 0)); }
  void set_point(OpenMesh::VertexHandle v, const OpenMesh::Vec3f& p) override {
    if (v.idx() < 0 || size_t(v.idx()) >= n_vertices()) return;
    std::copy(p.data(), p.data() + 3, coords.begin() + 3 * v.idx());
  }
  OpenMesh::FaceHandle add_face(const VHandles& vertices) override {
    std::vector<int> face;
    face.reserve(vertices.size());
    for (const auto& v : vertices) face.push_back(v.idx());
    faces.push_back(std::move(face));
    return OpenMesh::FaceHandle(int(faces.size()) - 1);
  }
  size_t n_vertices() const override { return coords.size() / 3; }
  size_t n_faces() const override { return faces.size(); }
  size_t n_edges() const override { return 0; }

  // Halfedge-level construction (only the .om reader uses it) and attributes.
  OpenMesh::HalfedgeHandle add_edge(OpenMesh::VertexHandle, OpenMesh::VertexHandle) override {
    return OpenMesh::HalfedgeHandle();
  }
  OpenMesh::FaceHandle add_face(OpenMesh::HalfedgeHandle) override {
    return OpenMesh::FaceHandle();
  }
  void add_face_texcoords(OpenMesh::FaceHandle, OpenMesh::VertexHandle,
                          const std::vector<OpenMesh::Vec2f>&) override {}
  void add_face_texcoords(OpenMesh::FaceHandle, OpenMesh::VertexHandle,
                          const std::vector<OpenMesh::Vec3f>&) override {}
  void set_face_texindex(OpenMesh::FaceHandle, int) override {}
  void set_halfedge(OpenMesh::VertexHandle, OpenMesh::HalfedgeHandle) override {}
  void set_normal(OpenMesh::VertexHandle, const OpenMesh::Vec3f&) override {}
  void set_normal(OpenMesh::VertexHandle, const OpenMesh::Vec3d&) override {}
  void set_color(OpenMesh::VertexHandle, const OpenMesh::Vec3uc&) override {}
  void set_color(OpenMesh::VertexHandle, const OpenMesh::Vec4uc&) override {}
  void set_color(OpenMesh::VertexHandle, const OpenMesh::Vec3f&) override {}
  void set_color(OpenMesh::VertexHandle, const OpenMesh::Vec4f&) override {}
  void set_texcoord(OpenMesh::VertexHandle, const OpenMesh::Vec2f&) override {}
  void set_status(OpenMesh::VertexHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void set_next(OpenMesh::HalfedgeHandle, OpenMesh::HalfedgeHandle) override {}
  void set_face(OpenMesh::HalfedgeHandle, OpenMesh::FaceHandle) override {}
  void request_face_texcoords2D() override {}
  void set_texcoord(OpenMesh::HalfedgeHandle, const OpenMesh::Vec2f&) override {}
  void set_texcoord(OpenMesh::VertexHandle, const OpenMesh::Vec3f&) override {}
  void set_texcoord(OpenMesh::HalfedgeHandle, const OpenMesh::Vec3f&) override {}
  void set_status(OpenMesh::HalfedgeHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec3uc&) override {}
  void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec4uc&) override {}
  void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec3f&) override {}
  void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec4f&) override {}
  void set_status(OpenMesh::EdgeHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void set_normal(OpenMesh::FaceHandle, const OpenMesh::Vec3f&) override {}
  void set_normal(OpenMesh::FaceHandle, const OpenMesh::Vec3d&) override {}
  void set_color(OpenMesh::FaceHandle, const OpenMesh::Vec3uc&) override {}
  void set_color(OpenMesh::FaceHandle, const OpenMesh::Vec4uc&) override {}
  void set_color(OpenMesh::FaceHandle, const OpenMesh::Vec3f&) override {}
  void set_color(OpenMesh::FaceHandle, const OpenMesh::Vec4f&) override {}
  void set_status(OpenMesh::FaceHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void add_texture_information(int, std::string) override {}
};

}  // namespace

SurfaceMesh read_with_openmesh(const std::string& path, long long declared_vertices,
                               long long declared_faces) {
  RawImporter importer;
  OpenMesh::IO::Options options;
  bool ok;
  {
    SilenceOpenMesh quiet;
    ok = OpenMesh::IO::IOManager().read(path, importer, options);
  }
  if (!ok) fail_reading(path, "OpenMesh cannot parse the file (corrupt or truncated)");
  if (declared_vertices >= 0 && (long long)importer.n_vertices() != declared_vertices)
    fail_reading(path, "truncated: " + std::to_string(importer.n_vertices()) + " of " +
                           std::to_string(declared_vertices) + " vertices");
  if (declared_faces >= 0 && (long long)importer.n_faces() != declared_faces)
    fail_reading(path, "truncated: " + std::to_string(importer.n_faces()) + " of " +
                           std::to_string(declared_faces) + " faces");
  return surface_mesh_from_rows(importer.coords, std::move(importer.faces));
}

}  // namespace unfold
