#include "solvers/scf.h"

#include <glog/logging.h>

#include <array>
#include <cmath>
#include <map>
#include <utility>

#include "core/errors.h"
#include "mesh/surface_mesh.h"
#include "mesh/tet_mesh_boundary.h"
#include "solvers/skeleton_deformation.h"

namespace unfold {
namespace {

// The skeleton of the boundary of the tets T over P, its correspondence on the
// surface's vertices (P's first rows): through the boundary vertex at the same
// position, or else (a surface vertex inside the tets) the nearest vertex's.
CurveSkeleton tet_boundary_skeleton(const Eigen::MatrixX3d& P, const Eigen::MatrixX4i& T,
                                    int num_surface_vertices, const CurveSkeletonOptions& options) {
  const SurfaceMesh boundary = tet_mesh_boundary(P, T);
  CurveSkeleton s = curve_skeleton(boundary.V, triangulate_faces(boundary), options);
  std::map<std::array<double, 3>, int> at;
  for (int k = 0; k < boundary.V.rows(); ++k)
    at[{boundary.V(k, 0), boundary.V(k, 1), boundary.V(k, 2)}] = s.node_of_vertex(k);
  Eigen::VectorXi node = Eigen::VectorXi::Constant(num_surface_vertices, -1);
  for (int i = 0; i < num_surface_vertices; ++i)
    if (const auto it = at.find({P(i, 0), P(i, 1), P(i, 2)}); it != at.end()) node(i) = it->second;
  s.num_left_out = assign_nearest_nodes(P.topRows(num_surface_vertices), &node);
  s.node_of_vertex = std::move(node);
  return s;
}

}  // namespace

void validate_scf_options(const ScfOptions& o) {
  validate_curve_skeleton_options(o.skeleton);
  if (o.mds_iterations < 1) throw UsageError("config key 'scf.mds_iterations' must be >= 1");
  if (!(std::isfinite(o.blend_radius) && o.blend_radius > 0))
    throw UsageError("config key 'scf.blend_radius' must be a positive finite number");
  if (!(std::isfinite(o.arap_anchor) && o.arap_anchor > 0))
    throw UsageError("config key 'scf.arap_anchor' must be a positive finite number");
  if (o.arap_iterations < 0) throw UsageError("config key 'scf.arap_iterations' must be >= 0");
}

ScfResult scf(const EdgeGraph& graph, const Eigen::MatrixX3d& P, int num_surface_vertices,
              const Eigen::MatrixX3i& F, const Eigen::MatrixX4i& T, const ScfOptions& options) {
  validate_scf_options(options);
  if (P.rows() != graph.num_vertices || num_surface_vertices < 1 || num_surface_vertices > P.rows())
    throw UsageError("scf: positions, edge graph and surface vertex count do not match");
  const Eigen::MatrixX3d surface = P.topRows(num_surface_vertices);
  ScfResult r;
  r.skeleton = curve_skeleton(surface, F, options.skeleton);
  if (r.skeleton.num_left_out > 0 && T.rows() > 0) {
    try {
      CurveSkeleton b = tet_boundary_skeleton(P, T, num_surface_vertices, options.skeleton);
      LOG(INFO) << "scf: the tet boundary's skeleton leaves " << b.num_left_out
                << " surface vertices out, the surface's " << r.skeleton.num_left_out;
      if (b.num_left_out < r.skeleton.num_left_out) r.skeleton = std::move(b);
    } catch (const Error& e) {  // the surface's skeleton stands
      LOG(INFO) << "scf: no skeleton of the tet boundary: " << e.what();
    }
  }
  r.unbent = unbend_skeleton(r.skeleton.nodes, r.skeleton.edges, options.mds_iterations);
  SkeletonDeformationOptions deform;
  deform.blend_radius = options.blend_radius * 2 *
                        (surface.rowwise() - surface.colwise().mean()).rowwise().norm().maxCoeff();
  deform.arap_anchor = options.arap_anchor;
  deform.arap_iterations = options.arap_iterations;
  SkeletonDeformation d = deform_by_skeleton(graph, P, r.skeleton, r.unbent, deform);
  r.positions = std::move(d.positions);
  r.skinned = std::move(d.skinned);
  r.canonical_nodes = std::move(d.canonical_nodes);
  LOG(INFO) << "scf: " << r.skeleton.nodes.rows() << " skeleton nodes, skeleton MDS stress "
            << r.unbent.stress << " after " << r.unbent.iterations << " transforms";
  return r;
}

}  // namespace unfold
