// The project's only CGAL translation unit (the headers are heavy: keep them here).
#include "mesh/curve_skeleton.h"

#include <CGAL/Mean_curvature_flow_skeletonization.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <glog/logging.h>

#include <cmath>
#include <iterator>
#include <string>
#include <vector>

#include "core/errors.h"
#include "mesh/edge_graph.h"

namespace unfold {
namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Skeletonization = CGAL::Mean_curvature_flow_skeletonization<Mesh>;

// The surface as a CGAL mesh whose vertex i is row i of V.
Mesh to_cgal_mesh(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F) {
  Mesh mesh;
  for (int i = 0; i < V.rows(); ++i) mesh.add_vertex(Kernel::Point_3(V(i, 0), V(i, 1), V(i, 2)));
  for (int f = 0; f < F.rows(); ++f) {
    const Mesh::Face_index face = mesh.add_face(
        Mesh::Vertex_index(F(f, 0)), Mesh::Vertex_index(F(f, 1)), Mesh::Vertex_index(F(f, 2)));
    if (face == Mesh::null_face())
      throw InputError("scf: triangle " + std::to_string(f) +
                       " makes the surface non-manifold; the skeleton needs a 2-manifold surface");
  }
  return mesh;
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

}  // namespace

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
  Mesh mesh = to_cgal_mesh(V, F);
  if (const int holes = close_holes(&mesh)) LOG(INFO) << "scf: closed " << holes << " hole(s)";
  if (!CGAL::is_closed(mesh)) {
    int open_edges = 0;
    for (const Mesh::Halfedge_index h : mesh.halfedges()) open_edges += mesh.is_border(h);
    throw InputError("scf: the surface is open and " + std::to_string(open_edges) +
                     " boundary edges are left after closing its holes; the skeleton needs a "
                     "closed surface");
  }

  const Eigen::RowVector3d centroid = V.colwise().mean();
  const double diameter = 2 * (V.rowwise() - centroid).rowwise().norm().maxCoeff();
  Skeletonization::Skeleton graph;
  try {
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
    for (const Mesh::Vertex_index v : node.vertices) s.node_of_vertex(int(v.idx())) = k;
  }
  if (!s.nodes.allFinite() || s.node_of_vertex.minCoeff() < 0)
    throw NumericalError("scf: the skeleton extraction left vertices without a skeleton node");
  s.edges.resize(int(boost::num_edges(graph)), 2);
  int e = 0;
  for (const auto edge : CGAL::make_range(boost::edges(graph))) {
    const int a = int(boost::source(edge, graph)), b = int(boost::target(edge, graph));
    s.edges.row(e++) << std::min(a, b), std::max(a, b);
  }
  LOG(INFO) << "scf: skeleton of " << num_nodes << " nodes, " << e << " bones";
  return s;
}

}  // namespace unfold
