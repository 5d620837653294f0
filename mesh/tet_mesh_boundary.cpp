#include "mesh/tet_mesh_boundary.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "core/errors.h"

namespace unfold {
namespace {

using Face = std::array<int, 3>;

Face sorted(Face f) {
  std::sort(f.begin(), f.end());
  return f;
}

// Triangles of exactly one tet, each with the tet's fourth vertex.
std::map<Face, std::pair<Face, int>> boundary_faces(const Eigen::MatrixX3d& V,
                                                    const Eigen::MatrixX4i& T) {
  if (T.rows() == 0) throw InputError("the tet mesh has no tetrahedra");
  if (T.minCoeff() < 0 || T.maxCoeff() >= V.rows())
    throw InputError("a tetrahedron's vertex index is outside the " + std::to_string(V.rows()) +
                     " vertices");
  std::map<Face, std::pair<Face, int>> once;
  std::set<Face> twice;
  for (Eigen::Index t = 0; t < T.rows(); ++t)
    for (int skip = 0; skip < 4; ++skip) {
      Face f;
      for (int c = 0, k = 0; c < 4; ++c)
        if (c != skip) f[size_t(k++)] = T(t, c);
      const Face key = sorted(f);
      if (twice.count(key)) continue;
      if (once.erase(key)) {
        twice.insert(key);
        continue;
      }
      once[key] = {f, T(t, skip)};
    }
  return once;
}

}  // namespace

SurfaceMesh tet_mesh_boundary(const Eigen::MatrixX3d& V, const Eigen::MatrixX4i& T) {
  const auto faces = boundary_faces(V, T);
  std::vector<int> index(size_t(V.rows()), -1);
  for (const auto& [key, face] : faces)
    for (const int v : key) index[size_t(v)] = 0;
  SurfaceMesh surface;
  std::vector<int> rows;
  for (int v = 0; v < int(V.rows()); ++v)
    if (index[size_t(v)] == 0) {
      index[size_t(v)] = int(rows.size());
      rows.push_back(v);
    }
  surface.V.resize(Eigen::Index(rows.size()), 3);
  for (size_t k = 0; k < rows.size(); ++k) surface.V.row(Eigen::Index(k)) = V.row(rows[k]);
  for (const auto& [key, face_and_apex] : faces) {
    const auto& [f, apex] = face_and_apex;
    const Eigen::Vector3d p = V.row(f[0]), q = V.row(f[1]), r = V.row(f[2]), a = V.row(apex);
    const bool outward = (q - p).cross(r - p).dot(p - a) > 0;
    surface.faces.push_back({index[size_t(f[0])], index[size_t(outward ? f[1] : f[2])],
                             index[size_t(outward ? f[2] : f[1])]});
  }
  return surface;
}

Eigen::VectorXi match_tet_mesh_boundary(const SurfaceMesh& surface, const Eigen::MatrixX3d& V,
                                        const Eigen::MatrixX4i& T, std::string* mismatch) {
  const auto faces = boundary_faces(V, T);
  std::map<std::tuple<double, double, double>, int> row_at;
  for (int v = 0; v < int(V.rows()); ++v)
    row_at.emplace(std::make_tuple(V(v, 0), V(v, 1), V(v, 2)), v);
  Eigen::VectorXi row(surface.V.rows());
  for (Eigen::Index i = 0; i < surface.V.rows(); ++i) {
    const auto it = row_at.find(std::make_tuple(surface.V(i, 0), surface.V(i, 1), surface.V(i, 2)));
    if (it == row_at.end())
      throw InputError("the tet mesh's boundary is not the surface: surface vertex " +
                       std::to_string(i) + " is not a vertex of the tet mesh");
    row[i] = it->second;
  }
  const Eigen::MatrixX3i F = triangulate_faces(surface);
  int unmatched = 0;
  std::set<Face> surface_faces;
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    const Face key = sorted({row[F(f, 0)], row[F(f, 1)], row[F(f, 2)]});
    unmatched += !faces.count(key);
    surface_faces.insert(key);
  }
  int extra = 0;
  for (const auto& [key, face] : faces) extra += !surface_faces.count(key);
  mismatch->clear();
  if (unmatched > 0 || extra > 0)
    *mismatch = std::to_string(unmatched) + " of the surface's " + std::to_string(F.rows()) +
                " triangles are not boundary triangles of the tet mesh, and " +
                std::to_string(extra) + " of its " + std::to_string(faces.size()) +
                " boundary triangles are not surface triangles";
  return row;
}

}  // namespace unfold
