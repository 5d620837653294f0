#include "mesh/check_surface_mesh.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <iomanip>
#include <numeric>
#include <sstream>

#include "core/errors.h"
#include "mesh/edge_graph.h"

namespace unfold {
namespace {

std::string face_name(size_t f) { return "face " + std::to_string(f); }

std::string edge_name(int a, int b) {
  return "edge " + std::to_string(a) + "-" + std::to_string(b);
}

std::string describe(double x) { return std::isnan(x) ? "nan" : x > 0 ? "inf" : "-inf"; }

// Squared lengths, areas, volumes and the solver's products of them overflow
// or underflow far outside 1e-30..1e30 (measured on a sphere: wrong E_geo at
// 1e100, TetGen aborting at 1e150, face areas inf at 1e200 and 0 at 1e-100).
void check_size(const Eigen::MatrixX3d& V) {
  const Eigen::RowVector3d extent = V.colwise().maxCoeff() - V.colwise().minCoeff();
  const double size = extent.stableNorm();  // stable: no overflow in the squares
  std::ostringstream shown;
  if (std::isfinite(size))
    shown << std::setprecision(3) << size;
  else
    shown << "more than 1.8e308";
  if (!(size <= 1e30))
    throw InputError("coordinates too large to process: the bounding box diagonal is " +
                     shown.str() + ", unfold handles 1e-30 to 1e30 (scale the mesh down)");
  if (size > 0 && size < 1e-30)
    throw InputError("coordinates too small to process: the bounding box diagonal is " +
                     shown.str() + ", unfold handles 1e-30 to 1e30 (scale the mesh up)");
}

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
  check_size(mesh.V);
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

// Returns the number of components; throws if there are several and one is required.
int check_components(const SurfaceMesh& mesh, bool require_one) {
  std::vector<int> labels;
  const int count =
      connected_components(build_edge_graph(int(mesh.V.rows()), triangulate_faces(mesh)), &labels);
  if (count == 1 || !require_one) return count;
  std::vector<int> sizes(size_t(count), 0);
  for (int label : labels) ++sizes[size_t(label)];
  std::sort(sizes.begin(), sizes.end(), std::greater<int>());
  std::string list;
  for (size_t c = 0; c < sizes.size() && c < 10; ++c)
    list += (c ? ", " : "") + std::to_string(sizes[c]);
  if (sizes.size() > 10) list += ", ...";
  throw InputError("the surface has " + std::to_string(count) + " connected components (sizes " +
                   list + "); unfold needs one (or components: separately)");
}

// Vertices whose faces form more than one fan (faces around the vertex
// linked through edges at the vertex), e.g. two cones touching at their tips.
// Returns the count and sets *example to the lowest such vertex.
int count_nonmanifold_vertices(const SurfaceMesh& mesh, int* example) {
  // One union-find node per face corner.
  std::vector<int> first_corner(mesh.faces.size() + 1, 0), corner_vertex;
  for (size_t f = 0; f < mesh.faces.size(); ++f) {
    first_corner[f + 1] = first_corner[f] + int(mesh.faces[f].size());
    corner_vertex.insert(corner_vertex.end(), mesh.faces[f].begin(), mesh.faces[f].end());
  }
  std::vector<int> parent(corner_vertex.size());
  std::iota(parent.begin(), parent.end(), 0);
  const std::function<int(int)> find = [&](int c) {
    return parent[size_t(c)] == c ? c : parent[size_t(c)] = find(parent[size_t(c)]);
  };
  // (edge key, corner at the lower vertex, corner at the higher vertex) per face side.
  std::vector<std::array<uint64_t, 3>> sides;
  for (size_t f = 0; f < mesh.faces.size(); ++f) {
    const int n = int(mesh.faces[f].size());
    for (int k = 0; k < n; ++k) {
      uint64_t a = uint64_t(first_corner[f] + k), b = uint64_t(first_corner[f] + (k + 1) % n);
      if (corner_vertex[a] > corner_vertex[b]) std::swap(a, b);
      sides.push_back({uint64_t(corner_vertex[a]) << 32 | uint64_t(corner_vertex[b]), a, b});
    }
  }
  std::sort(sides.begin(), sides.end());
  for (size_t s = 1; s < sides.size(); ++s)
    if (sides[s][0] == sides[s - 1][0])
      for (int end = 1; end <= 2; ++end)
        parent[size_t(find(int(sides[s][end])))] = find(int(sides[s - 1][end]));
  std::vector<int> fan(size_t(mesh.V.rows()), -1);
  std::vector<bool> nonmanifold(size_t(mesh.V.rows()), false);
  for (size_t c = 0; c < corner_vertex.size(); ++c) {
    int& root = fan[size_t(corner_vertex[c])];
    if (root < 0) root = find(int(c));
    if (root != find(int(c))) nonmanifold[size_t(corner_vertex[c])] = true;
  }
  const auto first = std::find(nonmanifold.begin(), nonmanifold.end(), true);
  *example = int(first - nonmanifold.begin());
  return int(std::count(nonmanifold.begin(), nonmanifold.end(), true));
}

}  // namespace

SurfaceReport check_surface_mesh(const SurfaceMesh& mesh, bool require_one_component) {
  check_vertices_and_faces(mesh);
  SurfaceReport report;
  report.num_components = check_components(mesh, require_one_component);

  // Each face side as (undirected edge key, traversed low-to-high?); sorting
  // groups the sides of one edge together.
  std::vector<std::pair<uint64_t, bool>> sides;
  for (const auto& face : mesh.faces)
    for (size_t k = 0; k < face.size(); ++k) {
      const uint64_t a = uint64_t(face[k]), b = uint64_t(face[(k + 1) % face.size()]);
      sides.emplace_back(std::min(a, b) << 32 | std::max(a, b), a < b);
    }
  std::sort(sides.begin(), sides.end());

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
  int vertex_example = 0;
  report.num_nonmanifold_vertices = count_nonmanifold_vertices(mesh, &vertex_example);
  if (report.num_nonmanifold_vertices)
    report.warnings.push_back(std::to_string(report.num_nonmanifold_vertices) +
                              " non-manifold vertices where separate fans of faces meet (e.g. "
                              "vertex " +
                              std::to_string(vertex_example) + ")");
  if (report.num_misoriented_edges)
    report.warnings.push_back("inconsistent face orientation across " +
                              std::to_string(report.num_misoriented_edges) + " edges (e.g. " +
                              misoriented_example + ")");
  return report;
}

}  // namespace unfold
