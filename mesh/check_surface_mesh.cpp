#include "mesh/check_surface_mesh.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>

#include "core/errors.h"
#include "mesh/edge_graph.h"

namespace unfold {
namespace {

std::string face_name(size_t f) { return "face " + std::to_string(f); }

std::string edge_name(int a, int b) {
  return "edge " + std::to_string(a) + "-" + std::to_string(b);
}

std::string describe(double x) { return std::isnan(x) ? "nan" : x > 0 ? "inf" : "-inf"; }

void check_vertices_and_faces(const SurfaceMesh& mesh) {
  const Eigen::Index nv = mesh.V.rows();
  if (nv == 0 || mesh.faces.empty())
    throw InputError("the surface mesh is empty (" + std::to_string(nv) + " vertices, " +
                     std::to_string(mesh.faces.size()) + " faces)");
  for (Eigen::Index i = 0; i < nv; ++i)
    for (int c = 0; c < 3; ++c)
      if (!std::isfinite(mesh.V(i, c)))
        throw InputError("vertex " + std::to_string(i) + " has a non-finite coordinate (" +
                         describe(mesh.V(i, c)) + ")");
  // One pass per kind of defect, so the reported defect does not depend on
  // which face happens to come first.
  for (size_t f = 0; f < mesh.faces.size(); ++f)
    if (mesh.faces[f].size() < 3)
      throw InputError(face_name(f) + " has " + std::to_string(mesh.faces[f].size()) +
                       " vertices; a face needs at least 3");
  for (size_t f = 0; f < mesh.faces.size(); ++f)
    for (int v : mesh.faces[f])
      if (v < 0 || v >= nv)
        throw InputError(face_name(f) + " refers to vertex " + std::to_string(v) +
                         " but the mesh has " + std::to_string(nv) + " vertices");
  for (size_t f = 0; f < mesh.faces.size(); ++f) {
    std::vector<int> sorted = mesh.faces[f];
    std::sort(sorted.begin(), sorted.end());
    const auto repeat = std::adjacent_find(sorted.begin(), sorted.end());
    if (repeat != sorted.end())
      throw InputError(face_name(f) + " repeats vertex " + std::to_string(*repeat));
  }
  const double diagonal2 =
      (mesh.V.colwise().maxCoeff() - mesh.V.colwise().minCoeff()).squaredNorm();
  for (size_t f = 0; f < mesh.faces.size(); ++f) {
    // Vector area of the polygon (its area when planar), relative to the first
    // corner for accuracy far from the origin.
    const auto& face = mesh.faces[f];
    const Eigen::Vector3d p0 = mesh.V.row(face[0]);
    Eigen::Vector3d twice_area = Eigen::Vector3d::Zero();
    for (size_t k = 2; k < face.size(); ++k)
      twice_area +=
          (mesh.V.row(face[k - 1]).transpose() - p0).cross(mesh.V.row(face[k]).transpose() - p0);
    if (0.5 * twice_area.norm() <= 1e-12 * diagonal2)
      throw InputError(face_name(f) + " has zero area (degenerate)");
  }
  std::vector<bool> used(size_t(nv), false);
  for (const auto& face : mesh.faces)
    for (int v : face) used[size_t(v)] = true;
  const auto unused = std::find(used.begin(), used.end(), false);
  if (unused != used.end())
    throw InputError("vertex " + std::to_string(unused - used.begin()) + " is used by no face");
}

void check_single_component(const SurfaceMesh& mesh) {
  std::vector<int> labels;
  const int count =
      connected_components(build_edge_graph(int(mesh.V.rows()), triangulate_faces(mesh)), &labels);
  if (count == 1) return;
  std::vector<int> sizes(size_t(count), 0);
  for (int label : labels) ++sizes[size_t(label)];
  std::sort(sizes.begin(), sizes.end(), std::greater<int>());
  std::string list;
  for (size_t c = 0; c < sizes.size() && c < 10; ++c)
    list += (c ? ", " : "") + std::to_string(sizes[c]);
  if (sizes.size() > 10) list += ", ...";
  throw InputError("the surface has " + std::to_string(count) + " connected components (sizes " +
                   list + "); unfold needs one");
}

}  // namespace

SurfaceReport check_surface_mesh(const SurfaceMesh& mesh) {
  check_vertices_and_faces(mesh);
  check_single_component(mesh);

  // Each face side as (undirected edge key, traversed low-to-high?); sorting
  // groups the sides of one edge together.
  std::vector<std::pair<uint64_t, bool>> sides;
  for (const auto& face : mesh.faces)
    for (size_t k = 0; k < face.size(); ++k) {
      const uint64_t a = uint64_t(face[k]), b = uint64_t(face[(k + 1) % face.size()]);
      sides.emplace_back(std::min(a, b) << 32 | std::max(a, b), a < b);
    }
  std::sort(sides.begin(), sides.end());

  SurfaceReport report;
  std::string boundary_example, nonmanifold_example, misoriented_example;
  for (size_t s = 0; s < sides.size();) {
    size_t end = s;
    while (end < sides.size() && sides[end].first == sides[s].first) ++end;
    const size_t count = end - s;
    const auto name = [&] {
      return edge_name(int(sides[s].first >> 32), int(sides[s].first & 0xffffffffu));
    };
    if (count == 1) {
      if (report.num_boundary_edges++ == 0) boundary_example = name();
    } else if (count > 2) {
      if (report.num_nonmanifold_edges++ == 0)
        nonmanifold_example = name() + ", in " + std::to_string(count) + " faces";
    } else if (sides[s].second == sides[s + 1].second) {
      if (report.num_misoriented_edges++ == 0) misoriented_example = name();
    }
    s = end;
  }
  if (report.num_boundary_edges)
    report.warnings.push_back("open surface: " + std::to_string(report.num_boundary_edges) +
                              " boundary edges (e.g. " + boundary_example + ")");
  if (report.num_nonmanifold_edges)
    report.warnings.push_back(std::to_string(report.num_nonmanifold_edges) +
                              " non-manifold edges shared by more than two faces (e.g. " +
                              nonmanifold_example + ")");
  if (report.num_misoriented_edges)
    report.warnings.push_back("inconsistent face orientation across " +
                              std::to_string(report.num_misoriented_edges) + " edges (e.g. " +
                              misoriented_example + ")");
  return report;
}

}  // namespace unfold
