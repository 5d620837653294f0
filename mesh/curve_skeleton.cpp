// One of the project's two CGAL translation units (the headers are heavy: keep them here).
#include "mesh/curve_skeleton.h"

// CGAL's containers (the skeletonization's halfedge structure) take their
// memory from an OrderedArena: the skeletonization orders its edge collapses
// by handle address, and with malloc's addresses the same surface gave
// another skeleton on every run (cat0: 306 to 333 nodes).
#include "core/ordered_arena.h"
#define CGAL_ALLOCATOR(T) unfold::OrderedArenaAllocator<T>

#include <CGAL/Mean_curvature_flow_skeletonization.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/stitch_borders.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <glog/logging.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "core/errors.h"
#include "mesh/edge_graph.h"

namespace unfold {
namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Skeletonization = CGAL::Mean_curvature_flow_skeletonization<Mesh>;

namespace PMP = CGAL::Polygon_mesh_processing;

Kernel::Point_3 point(const Eigen::MatrixX3d& V, int i) {
  return Kernel::Point_3(V(i, 0), V(i, 1), V(i, 2));
}

// The surface as a CGAL mesh whose vertex i is row i of V; none if a triangle
// makes it non-manifold.
std::optional<Mesh> to_cgal_mesh(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F) {
  Mesh mesh;
  for (int i = 0; i < V.rows(); ++i) mesh.add_vertex(point(V, i));
  for (int f = 0; f < F.rows(); ++f)
    if (mesh.add_face(Mesh::Vertex_index(F(f, 0)), Mesh::Vertex_index(F(f, 1)),
                      Mesh::Vertex_index(F(f, 2))) == Mesh::null_face())
      return std::nullopt;
  return mesh;
}

int count_border_edges(const Mesh& mesh) {
  int open_edges = 0;
  for (const Mesh::Halfedge_index h : mesh.halfedges()) open_edges += mesh.is_border(h);
  return open_edges;
}

// Closes every hole with triangles between its own vertices (no vertex is
// added, so the correspondence stays the input's): the contraction needs a
// closed surface, and shapes such as TOSCA's cats come with small holes.
// Returns the number of holes closed.
int close_holes(Mesh* mesh) {
  std::vector<Mesh::Halfedge_index> holes;
  std::vector<bool> seen(mesh->number_of_halfedges(), false);
  for (const Mesh::Halfedge_index h : mesh->halfedges()) {
    if (!mesh->is_border(h) || seen[h.idx()]) continue;
    holes.push_back(h);
    for (Mesh::Halfedge_index g = h; !seen[g.idx()]; g = mesh->next(g)) seen[g.idx()] = true;
  }
  std::vector<Mesh::Face_index> added;
  for (const Mesh::Halfedge_index h : holes)
    CGAL::Polygon_mesh_processing::triangulate_hole(*mesh, h, std::back_inserter(added));
  return int(holes.size());
}

// A closed surface made from a surface the direct route cannot take (a
// non-manifold one, or one whose holes CGAL cannot triangulate between their
// own vertices, e.g. holes that touch themselves; TOSCA's centaur4 and davids
// after simplification): its triangles as a polygon soup, oriented
// consistently by CGAL (which duplicates the vertices where no consistent
// manifold exists), stitched where borders coincide, its holes closed, and
// its largest component kept. Every vertex of the result is at the position
// of a row of V: (*row)[k] names it, -1 for none.
// @throws InputError if the result is still open
Mesh repaired_closed_mesh(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
                          std::vector<int>* row) {
  std::vector<Kernel::Point_3> points;
  for (int i = 0; i < V.rows(); ++i) points.push_back(point(V, i));
  std::vector<std::vector<std::size_t>> triangles;
  std::set<std::array<int, 3>> seen;  // a triangle twice, in either orientation, once
  for (int f = 0; f < F.rows(); ++f) {
    std::array<int, 3> key = {F(f, 0), F(f, 1), F(f, 2)};
    std::sort(key.begin(), key.end());
    if (key[0] == key[1] || key[1] == key[2] || !seen.insert(key).second) continue;
    triangles.push_back({std::size_t(F(f, 0)), std::size_t(F(f, 1)), std::size_t(F(f, 2))});
  }
  PMP::orient_polygon_soup(points, triangles);
  Mesh soup;
  PMP::polygon_soup_to_polygon_mesh(points, triangles, soup);
  PMP::stitch_borders(soup);
  PMP::duplicate_non_manifold_vertices(soup);
  close_holes(&soup);

  // The largest component, as a fresh mesh (no removed elements for the contraction).
  auto component = soup.add_property_map<Mesh::Face_index, std::size_t>("f:component").first;
  const std::size_t num_components = PMP::connected_components(soup, component);
  std::vector<int> size(num_components, 0);
  for (const Mesh::Face_index f : soup.faces()) ++size[component[f]];
  const std::size_t largest =
      std::size_t(std::max_element(size.begin(), size.end()) - size.begin());
  std::map<std::array<double, 3>, int> row_at;  // the first row at each position
  for (int i = int(V.rows()) - 1; i >= 0; --i) row_at[{V(i, 0), V(i, 1), V(i, 2)}] = i;
  Mesh mesh;
  std::vector<Mesh::Vertex_index> copy(
      soup.number_of_vertices() + soup.number_of_removed_vertices(), Mesh::null_vertex());
  row->clear();
  for (const Mesh::Face_index f : soup.faces()) {
    if (component[f] != largest) continue;
    std::vector<Mesh::Vertex_index> corners;
    for (const Mesh::Vertex_index v : CGAL::vertices_around_face(soup.halfedge(f), soup)) {
      if (copy[v.idx()] == Mesh::null_vertex()) {
        const Kernel::Point_3& p = soup.point(v);
        copy[v.idx()] = mesh.add_vertex(p);
        const auto at = row_at.find({p.x(), p.y(), p.z()});
        row->push_back(at == row_at.end() ? -1 : at->second);
      }
      corners.push_back(copy[v.idx()]);
    }
    mesh.add_face(corners);
  }
  if (!CGAL::is_closed(mesh) || mesh.number_of_faces() != std::size_t(size[largest]))
    throw InputError("scf: the surface is open and " + std::to_string(count_border_edges(mesh)) +
                     " boundary edges are left after repairing it and closing its holes; the "
                     "skeleton needs a closed surface");
  return mesh;
}

}  // namespace

int assign_nearest_nodes(const Eigen::MatrixX3d& V, Eigen::VectorXi* node_of_vertex) {
  Eigen::VectorXi& node = *node_of_vertex;
  std::vector<int> carried, left;
  for (int i = 0; i < node.size(); ++i) (node(i) >= 0 ? carried : left).push_back(i);
  if (left.empty()) return 0;
  if (carried.empty())
    throw NumericalError("scf: the skeleton extraction left every vertex without a skeleton node");
  for (const int i : left) {
    double nearest = INFINITY;
    for (const int j : carried)
      if (const double d = (V.row(i) - V.row(j)).squaredNorm(); d < nearest) {
        nearest = d;
        node(i) = node(j);
      }
  }
  return int(left.size());
}

void validate_curve_skeleton_options(const CurveSkeletonOptions& o) {
  const auto positive = [](double x) { return std::isfinite(x) && x > 0; };
  if (!positive(o.quality_speed_tradeoff))
    throw UsageError("config key 'scf.quality_speed_tradeoff' must be a positive finite number");
  if (!positive(o.medially_centered_speed_tradeoff))
    throw UsageError(
        "config key 'scf.medially_centered_speed_tradeoff' must be a positive finite number");
  if (o.max_iterations < 1) throw UsageError("config key 'scf.max_iterations' must be >= 1");
  if (!(positive(o.min_edge_length) && o.min_edge_length < 1))
    throw UsageError("config key 'scf.min_edge_length' must be in (0, 1)");
}

CurveSkeleton curve_skeleton(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
                             const CurveSkeletonOptions& options) {
  validate_curve_skeleton_options(options);
  const int n = int(V.rows());
  if (n < 8)
    throw InputError("scf: the surface has " + std::to_string(n) +
                     " vertices; a skeleton needs at least 8");
  if (F.size() > 0 && (F.minCoeff() < 0 || F.maxCoeff() >= n))
    throw InputError("scf: a triangle names a vertex that does not exist");
  const int components = connected_components(build_edge_graph(n, Eigen::MatrixXi(F)));
  if (components != 1)
    throw InputError("scf: the surface has " + std::to_string(components) +
                     " connected components; the skeleton needs one");
  // The surface itself with its holes closed when it can; else the repaired
  // one, whose vertex k is row[k] of V (-1: a new position).
  std::optional<Mesh> direct = to_cgal_mesh(V, F);
  std::vector<int> row;
  if (direct) {
    if (const int holes = close_holes(&*direct)) LOG(INFO) << "scf: closed " << holes << " hole(s)";
    if (!CGAL::is_closed(*direct)) {
      LOG(INFO) << "scf: " << count_border_edges(*direct)
                << " boundary edges left after closing the holes: repairing the surface";
      direct.reset();
    }
  } else {
    LOG(INFO) << "scf: the surface is not a 2-manifold: repairing it";
  }
  Mesh mesh = direct ? std::move(*direct) : repaired_closed_mesh(V, F, &row);
  if (row.empty())
    for (int i = 0; i < n; ++i) row.push_back(i);

  const Eigen::RowVector3d centroid = V.colwise().mean();
  const double diameter = 2 * (V.rowwise() - centroid).rowwise().norm().maxCoeff();
  Skeletonization::Skeleton graph;
  OrderedArena arena(std::size_t(1) << 36);  // address space: pages are taken as written
  if (arena.capacity() == 0)
    LOG(WARNING) << "scf: no address space for the skeleton's arena (ulimit -v?): the skeleton "
                    "may differ from run to run";
  try {
    const OrderedArena::Scope scope(&arena);
    Skeletonization skeletonize(mesh);
    skeletonize.set_quality_speed_tradeoff(options.quality_speed_tradeoff);
    skeletonize.set_medially_centered_speed_tradeoff(options.medially_centered_speed_tradeoff);
    skeletonize.set_max_iterations(std::size_t(options.max_iterations));
    skeletonize.set_min_edge_length(options.min_edge_length * diameter);
    skeletonize(graph);
  } catch (const std::exception& e) {  // CGAL's precondition and solver failures
    throw NumericalError(std::string("scf: the skeleton extraction failed: ") + e.what());
  }

  CurveSkeleton s;
  const int num_nodes = int(boost::num_vertices(graph));
  if (num_nodes < 2 || boost::num_edges(graph) < 1)
    throw NumericalError("scf: the surface contracted to " + std::to_string(num_nodes) +
                         " skeleton node(s); no curve skeleton (a thin sheet or a blob?)");
  s.nodes.resize(num_nodes, 3);
  s.node_of_vertex = Eigen::VectorXi::Constant(n, -1);
  for (int k = 0; k < num_nodes; ++k) {
    const auto& node = graph[Skeletonization::Skeleton::vertex_descriptor(k)];
    s.nodes.row(k) << node.point.x(), node.point.y(), node.point.z();
    for (const Mesh::Vertex_index v : node.vertices)
      if (row[v.idx()] >= 0) s.node_of_vertex(row[v.idx()]) = k;
  }
  if (!s.nodes.allFinite())
    throw NumericalError("scf: the skeleton extraction gave non-finite nodes");
  s.num_left_out = assign_nearest_nodes(V, &s.node_of_vertex);
  s.edges.resize(int(boost::num_edges(graph)), 2);
  int e = 0;
  for (const auto edge : CGAL::make_range(boost::edges(graph))) {
    const int a = int(boost::source(edge, graph)), b = int(boost::target(edge, graph));
    s.edges.row(e++) << std::min(a, b), std::max(a, b);
  }
  LOG(INFO) << "scf: skeleton of " << num_nodes << " nodes, " << e << " bones ("
            << arena.bytes_used() / 1e6 << " MB of CGAL's memory in the arena)";
  return s;
}

}  // namespace unfold
